#include "igaprep/param/midsurface_pipeline.h"

#include <optional>
#include <sstream>

#include "igaprep/core/error.h"
#include "igaprep/param/sheet_topology.h"
#include "igaprep/param/thin_sides.h"

namespace igaprep::param {
namespace {

// The plane family tried when no principal plane works: 40 normals x 7
// offsets (about 15 s of cuts on the pelvis), and the midsurface on at most
// the 8 shortest valid cuts.
constexpr int kFamilyNormals = 40, kFamilyOffsets = 7;
constexpr std::size_t kFamilyTried = 8;

// Tet mesh, field and M0 for one cut.
void build_m0(const std::vector<mesh::TriMesh>& surfaces, const MidsurfaceOptions& o, MidsurfaceResult& r) {
  std::vector<mesh::TriMesh> shells = surfaces;
  shells[0] = r.cut.surface;
  r.tets = mesh::tetrahedralize(shells, {}, o.tetgen);
  split_loop_chords(r.tets, r.cut);
  r.f = midsurface_field(r.tets, r.cut);
  r.m0 = extract_midsurface(r.tets, r.cut, r.f);
  r.m0trim = trim_midsurface(r.tets, r.m0, static_cast<int>(surfaces.size()) - 1, r.cut.genus + 1);
}

// Everything after the cut: the tet mesh, f, M0, M0trim and its 2D polycube.
void complete_midsurface(const std::vector<mesh::TriMesh>& surfaces, const MidsurfaceOptions& o, MidsurfaceResult& r) {
  build_m0(surfaces, o, r);
  if (o.path_lengths) r.paths = midsurface_path_lengths(r.tets, r.f, r.cut);

  // Ears would put three vertices on one straight side of the domain.
  const Eigen::Index before = r.m0trim.mesh.V.rows();
  if (split_boundary_ears(r.m0trim.mesh) > 0) {
    r.m0trim.m0_vertex.conservativeResize(r.m0trim.mesh.V.rows());
    r.m0trim.m0_vertex.tail(r.m0trim.mesh.V.rows() - before).setConstant(-1);
    r.m0trim.m0_face = Eigen::VectorXi::Constant(r.m0trim.mesh.F.rows(), -1);
    r.m0trim.boundary_loops = analyze_sheet(r.m0trim.mesh.F, r.m0trim.mesh.V.rows()).boundary_loops;
  }
  r.polycube = polycube_2d(r.m0trim.mesh, r.m0trim.boundary_loops, o.corners);
  if (r.m0trim.mesh.V.rows() > r.m0trim.m0_vertex.size()) {  // refined at hole corners
    const Eigen::Index old = r.m0trim.m0_vertex.size();
    r.m0trim.m0_vertex.conservativeResize(r.m0trim.mesh.V.rows());
    r.m0trim.m0_vertex.tail(r.m0trim.mesh.V.rows() - old).setConstant(-1);
    r.m0trim.m0_face = Eigen::VectorXi::Constant(r.m0trim.mesh.F.rows(), -1);
  }
}

// The midsurface on an automatic cut; false (and why, in r.tried) when a
// stage refuses it, so that the next candidate can be tried.
bool try_automatic_cut(const std::vector<mesh::TriMesh>& surfaces, const MidsurfaceOptions& o, CutLoops cut,
                       MidsurfaceResult& r) {
  r.cut = std::move(cut);
  try {
    complete_midsurface(surfaces, o, r);
    return true;
  } catch (const Error& e) {
    if (e.kind() == ErrorKind::Internal) throw;
    r.tried.push_back(r.cut.source + ": " + e.what());
    return false;
  }
}

// The cut between the two sides of a thin solid (thin_sides.h); false (and
// why, in r.tried) when it is refused.
bool try_thin_sides_cut(const std::vector<mesh::TriMesh>& surfaces, const ThinSides& sides,
                        const MidsurfaceOptions& o, const std::string& name, MidsurfaceResult& r) {
  std::ostringstream src;
  src.precision(3);
  src << "thin sides (" << sides.plate_pairs << " plate pairs, median thickness " << sides.median_thickness << ")";
  CutLoops cut;
  try {
    cut = cut_by_field(surfaces[0], sides.vertex_value, name, src.str());
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::BadInput) throw;
    r.tried.push_back(std::string("thin sides: ") + e.what());
    return false;
  }
  cut.source = "automatic: " + cut.source;
  return try_automatic_cut(surfaces, o, std::move(cut), r);
}

// T1's extent along a direction.
double extent_along(const mesh::TriMesh& T1, const Eigen::Vector3d& d) {
  const Eigen::VectorXd x = T1.V * d;
  return x.maxCoeff() - x.minCoeff();
}

// A solid counts as thin when its plate pairs are, at the median, less than
// half as far apart as the solid is thick along its smallest principal axis:
// a propeller (1.5 of 9.7), a pelvis; not an ellipsoid or a ring.
constexpr double kThinRatio = 0.5;

// For a thin solid the two sides first, then principal planes (a plane
// across a thin blade makes M0 a narrow ribbon along it); for others the
// principal planes first. Then the plane family's shortest valid cuts.
void automatic_midsurface(const std::vector<mesh::TriMesh>& surfaces, const MidsurfaceOptions& o,
                          const std::string& name, MidsurfaceResult& r) {
  const mesh::TriMesh& T1 = surfaces[0];
  std::optional<ThinSides> sides;
  try {
    sides = thin_sides(T1);
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::BadInput) throw;
    r.tried.push_back(std::string("thin sides: ") + e.what());
  }
  const bool thin = sides && sides->median_thickness < kThinRatio * extent_along(T1, sides->up);
  if (thin && try_thin_sides_cut(surfaces, *sides, o, name, r)) return;
  for (const CutPlane& p : automatic_cut_planes(T1)) {
    CutLoops cut;
    try {
      cut = cut_by_plane(T1, p, name);
    } catch (const Error& e) {
      if (e.kind() != ErrorKind::BadInput) throw;
      r.tried.push_back(e.what());
      continue;
    }
    cut.source = "automatic: " + cut.source;
    if (try_automatic_cut(surfaces, o, std::move(cut), r)) return;
  }
  if (sides && !thin && try_thin_sides_cut(surfaces, *sides, o, name, r)) return;
  const PlaneFamily family = cut_plane_family(T1, kFamilyNormals, kFamilyOffsets, name);
  r.tried.push_back("plane family: " + std::to_string(family.valid.size()) + " of " + std::to_string(family.tried) +
                    " planes give valid loops; the others:");
  for (const auto& line : family.refusals) r.tried.push_back("  " + line);
  for (std::size_t i = 0; i < family.valid.size() && i < kFamilyTried; ++i)
    if (try_automatic_cut(surfaces, o, family.valid[i], r)) return;
  std::string all;
  for (const auto& t : r.tried) all += "\n  " + t;
  throw bad_input(name + ": no automatic cut gives a valid midsurface:" + all +
                  "\ngive a plane or loops drawn as waypoints in the case file's \"midsurface\" section");
}

}  // namespace

MidsurfaceResult build_midsurface(const std::vector<mesh::TriMesh>& surfaces, const MidsurfaceOptions& o,
                                  const std::string& name) {
  if (surfaces.empty()) throw bad_input("midsurface: no surfaces");
  MidsurfaceResult r;
  const mesh::TriMesh& T1 = surfaces[0];
  if (o.cut == MidsurfaceOptions::CutKind::Automatic) {
    automatic_midsurface(surfaces, o, name, r);
  } else {
    switch (o.cut) {
      case MidsurfaceOptions::CutKind::Plane: r.cut = cut_by_plane(T1, o.plane, name); break;
      case MidsurfaceOptions::CutKind::Waypoints: r.cut = cut_by_waypoints(T1, o.waypoints, name); break;
      default: r.cut = cut_by_loops(T1, o.loops, name);
    }
    complete_midsurface(surfaces, o, r);
  }
  return r;
}

}  // namespace igaprep::param
