#include "stage_midsurface.h"

#include <cstdio>
#include <filesystem>

#include "igaprep/mesh/write_vtu.h"
#include "stage_timer.h"

namespace igaprep::cli {
namespace {

void write_outputs(const std::string& dir, const param::MidsurfaceResult& r) {
  namespace fs = std::filesystem;
  fs::create_directories(dir);
  auto path = [&](const char* name) { return (fs::path(dir) / name).string(); };
  {  // T1 with its regions
    mesh::VtuMesh v = mesh::vtu_triangles(r.cut.surface);
    v.add_cell_data("region", r.cut.face_side);
    v.add_point_data("side", r.cut.vertex_side);
    mesh::write_vtu(path("midsurface_t1_regions.vtu"), v);
  }
  {  // the loops, closed
    std::vector<std::vector<int>> lines;
    for (const auto& l : r.cut.loops) {
      lines.push_back(l);
      lines.back().push_back(l.front());
    }
    mesh::VtuMesh v = mesh::vtu_polylines(r.cut.surface.V, lines);
    Eigen::VectorXi id(static_cast<Eigen::Index>(lines.size()));
    for (Eigen::Index i = 0; i < id.size(); ++i) id(i) = static_cast<int>(i);
    v.add_cell_data("loop", id);
    mesh::write_vtu(path("midsurface_loops.vtu"), v);
  }
  mesh::write_vtu(path("midsurface_m0.vtu"), mesh::vtu_triangles(r.m0.mesh));
  {
    mesh::VtuMesh v = mesh::vtu_triangles(r.m0trim.mesh);
    v.add_point_data("u", Eigen::VectorXd(r.polycube.uv.col(0)));
    v.add_point_data("v", Eigen::VectorXd(r.polycube.uv.col(1)));
    v.add_point_data("b", r.base.b);
    v.add_cell_data("jacobian", r.polycube.jacobian);
    mesh::write_vtu(path("midsurface_m0trim.vtu"), v);
    // the same sheet flattened to its (u, v) domain
    mesh::TriMesh flat{Eigen::MatrixXd::Zero(r.polycube.uv.rows(), 3), r.m0trim.mesh.F};
    flat.V.leftCols(2) = r.polycube.uv;
    mesh::write_vtu(path("midsurface_m0trim_uv.vtu"), mesh::vtu_triangles(flat));
  }
  {  // rectangles in the (u, v) plane
    Eigen::MatrixXd P(static_cast<Eigen::Index>(4 * r.polycube.rectangles.size()), 3);
    std::vector<std::vector<int>> lines;
    for (std::size_t i = 0; i < r.polycube.rectangles.size(); ++i) {
      const Eigen::Vector4d& R = r.polycube.rectangles[i];
      const int b = static_cast<int>(4 * i);
      P.row(b) << R(0), R(1), 0.0;
      P.row(b + 1) << R(2), R(1), 0.0;
      P.row(b + 2) << R(2), R(3), 0.0;
      P.row(b + 3) << R(0), R(3), 0.0;
      lines.push_back({b, b + 1, b + 2, b + 3, b});
    }
    mesh::write_vtu(path("midsurface_rectangles.vtu"), mesh::vtu_polylines(P, lines));
  }
  {
    mesh::VtuMesh v = mesh::vtu_triangles(r.base.mesh);
    v.add_point_data("u", Eigen::VectorXd(r.base.uv.col(0)));
    v.add_point_data("v", Eigen::VectorXd(r.base.uv.col(1)));
    mesh::write_vtu(path("midsurface_base.vtu"), v);
    std::vector<std::vector<int>> pts;
    for (const auto& c : r.base.corners)
      for (int k = 0; k < 4; ++k) pts.push_back({c[k]});
    mesh::VtuMesh cv = mesh::vtu_polylines(r.base.mesh.V, {});
    for (const auto& p : pts) cv.add_cell(mesh::kVtuVertex, p);
    mesh::write_vtu(path("midsurface_base_corners.vtu"), cv);
  }
}

}  // namespace

param::MidsurfaceResult run_midsurface_stage(const CaseFile& c, const CaseSurfaces& surfaces, const std::string& dir) {
  StageTimer timer;
  const param::MidsurfaceResult r = param::build_midsurface(surfaces.meshes, c.midsurface, surfaces.names.at(0));
  const int g = r.cut.genus;
  std::printf("midsurface %7.2f s  genus %d, cut: %s\n", timer.seconds(), g, r.cut.source.c_str());
  for (const auto& t : r.tried) std::printf("             rejected candidate: %s\n", t.c_str());
  for (std::size_t l = 0; l < r.cut.loops.size(); ++l)
    std::printf("             loop %zu: %zu vertices\n", l, r.cut.loops[l].size());
  std::printf("             M0: %ld triangles; M0trim: %ld triangles\n", static_cast<long>(r.m0.mesh.F.rows()),
              static_cast<long>(r.m0trim.mesh.F.rows()));
  std::printf("             path lengths to M0: %d of %d traced, mean %.6g, variance %.6g (min %.6g, max %.6g)\n",
              r.paths.reached, r.paths.traced, r.paths.mean, r.paths.variance, r.paths.min, r.paths.max);
  const auto& pc = r.polycube;
  std::printf("             domain %.6g x %.6g with %zu holes, (u, v) weights: %s\n", pc.domain.width,
              pc.domain.height, pc.domain.holes.size(), pc.weights.c_str());
  for (std::size_t l = 0; l < pc.loops.size(); ++l) {
    std::printf("             corners of loop %zu (%s):", l, pc.loops[l].outer ? "outer" : "hole");
    for (int k = 0; k < 4; ++k) {
      const int v = pc.loops[l].vertices[static_cast<std::size_t>(pc.loops[l].corners[k])];
      std::printf(" (%.4g, %.4g, %.4g)", r.m0trim.mesh.V(v, 0), r.m0trim.mesh.V(v, 1), r.m0trim.mesh.V(v, 2));
    }
    std::printf("\n");
  }
  std::printf("             rectangles: %zu\n", pc.rectangles.size());
  for (const auto& R : pc.rectangles)
    std::printf("               [%.6g, %.6g] x [%.6g, %.6g]\n", R(0), R(2), R(1), R(3));
  std::printf("             (u, v) Jacobian: min %.6g, max %.6g\n", pc.min_jacobian, pc.max_jacobian);
  std::printf("             base surface M (m0 = %.3g): %ld triangles, %zu boundary loops\n", c.midsurface.m0,
              static_cast<long>(r.base.mesh.F.rows()), r.base.boundary_loops.size());
  write_outputs(dir, r);
  std::printf("             wrote %s/midsurface_*.vtu\n", dir.c_str());
  std::fflush(stdout);
  return r;
}

}  // namespace igaprep::cli
