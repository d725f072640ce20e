// Reads an igaprep model, runs spline's Jacobian optimization on it (the
// part of spline that uses Ceres inside) and writes it for ParaView.
#include <iostream>

#include "igaprep/export/hdf5_model.h"
#include "igaprep/export/vtu_bezier.h"
#include "igaprep/spline/optimize_jacobian.h"

int main(int argc, char** argv) {
  if (argc != 3) return 2;
  igaprep::spline::MultiPatch model = igaprep::exporter::read_hdf5_model(argv[1]);
  igaprep::spline::JacobianOptimizationOptions options;
  options.target = 0.0;  // a certified model: nothing to move
  options.sweeps = 1;
  const auto slide = [](int, const Eigen::Vector3d&, const Eigen::Vector3d& to) { return to; };
  const auto result = igaprep::spline::optimize_jacobians(model, slide, {}, options);
  igaprep::exporter::write_vtu_bezier(model, std::string(argv[2]));
  std::cout << "export consumer ok " << model.patches.size() << " " << result.moved_points << "\n";
  return 0;
}
