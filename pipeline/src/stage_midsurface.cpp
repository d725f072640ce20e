#include "igaprep/pipeline/midsurface.h"

#include "igaprep/core/error.h"
#include "igaprep/param/surface_projector.h"

#include "igaprep/mesh/tet_volume.h"
#include "stage_timer.h"
#include "igaprep/core/text.h"

namespace igaprep::pipeline {
namespace {

mesh::VtuMesh t1_regions(const param::MidsurfaceResult& r) {
  mesh::VtuMesh v = mesh::vtu_triangles(r.cut.surface);
  v.add_cell_data("region", r.cut.face_side);
  v.add_point_data("side", r.cut.vertex_side);
  return v;
}

mesh::VtuMesh loops(const param::MidsurfaceResult& r) {
  std::vector<std::vector<int>> lines;
  for (const auto& l : r.cut.loops) {
    lines.push_back(l);
    lines.back().push_back(l.front());
  }
  mesh::VtuMesh v = mesh::vtu_polylines(r.cut.surface.V, lines);
  Eigen::VectorXi id(static_cast<Eigen::Index>(lines.size()));
  for (Eigen::Index i = 0; i < id.size(); ++i) id(i) = static_cast<int>(i);
  v.add_cell_data("loop", id);
  return v;
}

mesh::VtuMesh m0trim(const param::MidsurfaceResult& r) {
  mesh::VtuMesh v = mesh::vtu_triangles(r.m0trim.mesh);
  v.add_point_data("u", Eigen::VectorXd(r.polycube.uv.col(0)));
  v.add_point_data("v", Eigen::VectorXd(r.polycube.uv.col(1)));
  v.add_cell_data("jacobian", r.polycube.jacobian);
  return v;
}

// The same sheet flattened to its (u, v) domain.
mesh::VtuMesh m0trim_uv(const param::MidsurfaceResult& r) {
  mesh::TriMesh flat{Eigen::MatrixXd::Zero(r.polycube.uv.rows(), 3), r.m0trim.mesh.F};
  flat.V.leftCols(2) = r.polycube.uv;
  return mesh::vtu_triangles(flat);
}

// The rectangles in the (u, v) plane.
mesh::VtuMesh rectangles(const param::MidsurfaceResult& r) {
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
  return mesh::vtu_polylines(P, lines);
}

void offer_midsurface_intermediates(const param::MidsurfaceResult& r, Observer& o) {
  offer_intermediate(o, "tetmesh", [&] { return mesh::vtu_tets(r.tets); });
  offer_intermediate(o, "midsurface_t1_regions", [&] { return t1_regions(r); });
  offer_intermediate(o, "midsurface_loops", [&] { return loops(r); });
  offer_intermediate(o, "midsurface_m0", [&] { return mesh::vtu_triangles(r.m0.mesh); });
  offer_intermediate(o, "midsurface_m0trim", [&] { return m0trim(r); });
  offer_intermediate(o, "midsurface_m0trim_uv", [&] { return m0trim_uv(r); });
  offer_intermediate(o, "midsurface_rectangles", [&] { return rectangles(r); });
}

std::vector<std::string> tet_lines(const Case& c, const mesh::TetMesh& tets) {
  const mesh::TetVolumes v = mesh::tet_volumes(tets, static_cast<int>(c.materials.size()));
  std::vector<std::string> out;
  out.push_back(text("tet mesh of the cut surfaces: %ld tets, %ld vertices, volume %.6g (radius-edge %.2f)",
                     static_cast<long>(tets.T.rows()), static_cast<long>(tets.V.rows()), v.total,
                     c.tetmesh.radius_edge_ratio));
  for (std::size_t m = 0; m < v.per_material.size(); ++m)
    out.push_back(text("  material %zu (%s): %ld tets, volume %.6g", m, c.materials[m].name.c_str(),
                       v.tets_per_material[m], v.per_material[m]));
  return out;
}

std::vector<std::string> midsurface_lines(const param::MidsurfaceResult& r) {
  std::vector<std::string> out;
  for (const auto& t : r.tried) out.push_back("rejected candidate: " + t);
  for (const auto& v : r.valid) out.push_back("candidate: " + v);
  if (r.valid.size() > 1)
    out.push_back("kept the candidate with the lowest score" +
                  std::string(r.second_best ? "" : " whose map needs no cuts from the holes' corners and squeezes no part of M0trim") +
                  " (" + r.cut.source + ")");
  for (std::size_t l = 0; l < r.cut.loops.size(); ++l)
    out.push_back(text("loop %zu: %zu vertices", l, r.cut.loops[l].size()));
  out.push_back(text("midsurface (M0): %ld triangles; trimmed (M0trim): %ld triangles", static_cast<long>(r.m0.mesh.F.rows()),
                     static_cast<long>(r.m0trim.mesh.F.rows())));
  out.push_back(text("path lengths from the surface to the midsurface: %d of %d traced, mean %.6g, variance %.6g (min %.6g, max %.6g)",
                     r.paths.reached, r.paths.traced, r.paths.mean, r.paths.variance, r.paths.min, r.paths.max));
  const auto& pc = r.polycube;
  out.push_back(text("domain %.6g x %.6g with %zu holes, (u, v) weights: %s", pc.domain.width, pc.domain.height,
                     pc.domain.holes.size(), pc.weights.c_str()));
  if (pc.arms_dropped)
    out.push_back(text("lobes of the outer loop: %d; their arms were dropped (%s)", pc.lobes, pc.arms_dropped_reason.c_str()));
  else if (pc.lobes > 0)
    out.push_back(text("lobes of the outer loop: %d, each an arm of the domain:", pc.lobes));
  for (const auto& arm : pc.domain.arms) {
    const Eigen::Vector4d b = param::arm_box(pc.domain, arm);
    out.push_back(text("  arm on the %s side: [%.6g, %.6g] x [%.6g, %.6g]", param::to_string(arm.side), b(0), b(2), b(1), b(3)));
  }
  for (std::size_t l = 0; l < pc.loops.size(); ++l) {
    std::string line = text("corners of loop %zu (%s):", l, pc.loops[l].outer ? "outer" : "hole");
    for (int k = 0; k < 4; ++k) {
      const int v = pc.loops[l].vertices[static_cast<std::size_t>(pc.loops[l].corners[k])];
      line += text(" (%.4g, %.4g, %.4g)", r.m0trim.mesh.V(v, 0), r.m0trim.mesh.V(v, 1), r.m0trim.mesh.V(v, 2));
    }
    out.push_back(line);
  }
  out.push_back(text("rectangles: %zu", pc.rectangles.size()));
  for (const auto& R : pc.rectangles) out.push_back(text("  [%.6g, %.6g] x [%.6g, %.6g]", R(0), R(2), R(1), R(3)));
  out.push_back(text("(u, v) Jacobian: min %.6g, max %.6g", pc.min_jacobian, pc.max_jacobian));
  return out;
}

mesh::VtuMesh base_vtu(const param::BaseSurface& b) {
  mesh::VtuMesh v = mesh::vtu_triangles(b.m.mesh);
  v.add_point_data("u", Eigen::VectorXd(b.m.uv.col(0)));
  v.add_point_data("v", Eigen::VectorXd(b.m.uv.col(1)));
  return v;
}

std::string uv_note(const param::BaseSurfaceOptions& o, const param::BaseSurface& b) {
  if (!o.sliding_uv) return "the midsurface's (u, v)";
  if (b.sliding_used)
    return text("the sliding (u, v) (share of the sliding side positions >= %.2f)", b.sliding.min_sliding_share);
  return "the midsurface's (u, v) (the sliding one: " + b.sliding.reason + ")";
}

}  // namespace

param::MidsurfaceResult midsurface_stage(const Case& c, const Surfaces& surfaces, Observer& observer) {
  StageTimer timer;
  if (c.midsurface.cut == param::MidsurfaceOptions::CutKind::Loops && surfaces.remeshed_to.at(0) > 0.0)
    throw bad_input("'midsurface.cut.loops' numbers the vertices of " + surfaces.names.at(0) +
                    " as given, but it was remeshed (long thin triangles): give the loops as 'waypoints' "
                    "or set the surface's 'remesh' to false");
  param::MidsurfaceResult r = param::build_midsurface(surfaces.meshes, c.midsurface, surfaces.names.at(0));
  StageSummary s{"midsurface", timer.seconds(), text("genus %d, cut: %s", r.cut.genus, r.cut.source.c_str()), {}};
  s.details = tet_lines(c, r.tets);
  for (auto& line : midsurface_lines(r)) s.details.push_back(std::move(line));
  observer.stage_finished(s);
  offer_midsurface_intermediates(r, observer);
  return r;
}

param::BaseSurface base_stage(const Case& c, const Surfaces& surfaces, const param::MidsurfaceResult& mid,
                              Observer& observer) {
  StageTimer timer;
  const mesh::TriMesh& innermost = surfaces.meshes.back();
  const param::SurfaceProjector rim(innermost.V, innermost.F);
  param::BaseSurface b = param::base_surface(mid.m0trim.mesh, mid.polycube, c.base, &rim);
  StageSummary s{"base", timer.seconds(),
                 text("base surface (M): %ld triangles, the trimmed midsurface inset by %.4g in its (u, v) domain, cut along %s",
                      static_cast<long>(b.m.mesh.F.rows()), b.m.inset, uv_note(c.base, b).c_str()),
                 {}};
  if (b.inset < c.base.inset)
    s.details.push_back(text("inset %.3g, not %.3g ('decomposition.inset'): the solid is thin at M0trim's rim (%d of the %d "
                             "vertices within the inset, half-thickness %.3g there); M's edge kept within %.3g half-thicknesses "
                             "of the rim ('decomposition.rim_reach')",
                             b.inset, c.base.inset, b.rim.thin, b.rim.considered, b.rim.half_thickness, c.base.rim_reach));
  if (b.m.smoothing < c.base.smoothing)
    s.details.push_back(text("M smoothed %d rounds, not %d (decomposition.smoothing): more made it intersect itself",
                             b.m.smoothing, c.base.smoothing));
  observer.stage_finished(s);
  offer_intermediate(observer, "base_surface", [&] { return base_vtu(b); });
  return b;
}

}  // namespace igaprep::pipeline
