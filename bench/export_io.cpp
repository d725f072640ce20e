// Write and read times of the HDF5 model file and the VTU Bezier file for a
// model of 100 patches with 20^3 control points each (degree 2, 18^3 Bezier
// elements per patch). HDF5 is read back with igaprep's reader; the VTU is
// read with VTK's vtkXMLUnstructuredGridReader through /usr/bin/python3
// (igaprep has no VTU reader). Plain main; prints one line per figure.
// Usage: bench_export_io [patches=100] [n=20] [degree=2]
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "igaprep/export/hdf5_model.h"
#include "igaprep/export/vtu_bezier.h"
#include "igaprep/spline/knot_vector.h"

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

igaprep::spline::MultiPatch make_model(int patches, int n, int degree) {
  igaprep::spline::MultiPatch mp;
  mp.labels = {"T1"};
  mp.materials = {{"steel", 210e9, 0.3}};
  const std::vector<double> U = igaprep::spline::uniform_knot_vector(degree, n);
  const std::vector<double> g = igaprep::spline::greville_abscissae(U, degree);
  for (int q = 0; q < patches; ++q) {
    igaprep::spline::Patch p;
    p.degrees = {degree, degree, degree};
    p.knots = {U, U, U};
    p.control_points.resize(n * n * n, 3);
    const double ox = q % 10, oy = q / 10;
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const double x = ox + g[i], y = oy + g[j], z = g[k];
          p.control_points.row(p.index(i, j, k)) << x + 0.05 * std::sin(y), y + 0.05 * std::sin(z), z + 0.05 * std::sin(x);
        }
    if (q % 2 == 1) p.weights = Eigen::VectorXd::Constant(n * n * n, 1.0).array() + 0.1 * (p.control_points.col(2).array());
    mp.patches.push_back(std::move(p));
  }
  return mp;
}
}  // namespace

int main(int argc, char** argv) {
  const int patches = argc > 1 ? std::atoi(argv[1]) : 100;
  const int n = argc > 2 ? std::atoi(argv[2]) : 20;
  const int degree = argc > 3 ? std::atoi(argv[3]) : 2;
  const auto dir = std::filesystem::temp_directory_path() / ("igaprep_bench_export_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const igaprep::spline::MultiPatch mp = make_model(patches, n, degree);
  std::printf("model: %d patches, %d^3 control points, degree %d (every second patch rational)\n", patches, n, degree);

  const std::string h5 = (dir / "model.h5").string(), vtu = (dir / "model.vtu").string();
  auto t0 = std::chrono::steady_clock::now();
  igaprep::exporter::write_hdf5_model(mp, h5);
  std::printf("hdf5 write: %.3f s, %.1f MB\n", seconds_since(t0), std::filesystem::file_size(h5) / 1e6);
  t0 = std::chrono::steady_clock::now();
  const igaprep::spline::MultiPatch back = igaprep::exporter::read_hdf5_model(h5);
  std::printf("hdf5 read: %.3f s (%zu patches)\n", seconds_since(t0), back.patches.size());

  t0 = std::chrono::steady_clock::now();
  igaprep::exporter::write_vtu_bezier(mp, vtu);
  std::printf("vtu write (appended raw binary): %.3f s, %.1f MB\n", seconds_since(t0),
              std::filesystem::file_size(vtu) / 1e6);
  const std::string cmd =
      "/usr/bin/python3 -c \"import sys,time,vtk; r=vtk.vtkXMLUnstructuredGridReader(); r.SetFileName(sys.argv[1]); "
      "t=time.perf_counter(); r.Update(); print('vtu read (VTK reader): %.3f s, %d cells' % "
      "(time.perf_counter()-t, r.GetOutput().GetNumberOfCells()))\" '" + vtu + "'";
  std::fflush(stdout);
  if (std::system(cmd.c_str()) != 0) std::printf("vtu read: VTK python reader not available\n");
  std::filesystem::remove_all(dir);
  return 0;
}
