#include "igaprep/param/midsurface_pipeline.h"

#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "igaprep/core/error.h"
#include "igaprep/param/sheet_topology.h"
#include "igaprep/param/thin_sides.h"
#include "igaprep/param/tunnel_loops.h"

namespace igaprep::param {
namespace {

// The plane family tried when no principal plane works: 40 normals x 7
// offsets (about 15 s of cuts on the pelvis), and the midsurface on at most
// the 8 shortest valid cuts.
constexpr int kFamilyNormals = 40, kFamilyOffsets = 7;
constexpr std::size_t kFamilyTried = 8;
// The midsurface on at most this many of the tunnel loops' cuts (the
// shortest first; one per choice of the loops' sides).
constexpr std::size_t kTunnelCutsTried = 4;

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

// The midsurface on an automatic cut; false (and why, in `tried`) when a
// stage refuses it, so that the next candidate can be tried.
bool try_automatic_cut(const std::vector<mesh::TriMesh>& surfaces, const MidsurfaceOptions& o, CutLoops cut,
                       MidsurfaceResult& r, std::vector<std::string>& tried) {
  r.cut = std::move(cut);
  try {
    complete_midsurface(surfaces, o, r);
    return true;
  } catch (const Error& e) {
    if (e.kind() == ErrorKind::Internal) throw;
    tried.push_back(r.cut.source + ": " + e.what());
    return false;
  }
}

// The quality of a valid cut (section 4.1): the root mean square of the
// path lengths from T1 to M0, so that long paths and a wide spread both
// count (the shell's streamlines fan out along long paths), over the share
// of paths that reached M0.
double cut_score(const PathLengthStats& p) {
  if (p.reached == 0) return std::numeric_limits<double>::infinity();
  return std::sqrt(p.mean * p.mean + p.variance) * p.traced / p.reached;
}

// A map that squeezes more than this share of M0trim's area to under a
// tenth of its median scale loses the volume above it (a lobe pressed into
// a sliver). Measured on the chosen maps (2026-12-07): 0.01 to 0.61 % where
// the blocks covered the shape (the built-in models, the kitten, the
// propeller, the pelvis, the hand's five arms), 2.4 % and 3.7 % on the thin
// sides of a screwdriver and a chess knight (rods, their shafts lost) and
// 20 % on the hand's thin sides without arms.
constexpr double kSqueezedShare = 0.01;

// A later candidate replaces the best one only when its score is lower by
// this factor: near-ties (the principal planes of a sphere) keep the
// earlier, simpler cut.
constexpr double kClearlyBetter = 0.9;

// The valid automatic cuts, scored; the best one is kept.
class CandidateCuts {
 public:
  // good_enough: a valid cut whose paths to M0 are no longer than this on
  // average is taken without trying the others.
  CandidateCuts(const std::vector<mesh::TriMesh>& surfaces, const MidsurfaceOptions& o, double good_enough)
      : surfaces_(surfaces), o_(o), good_enough_(good_enough) {}

  // Builds the midsurface on the cut; records why it was refused or its score.
  // A cut whose (u, v) map needed cuts from the holes' corners (a pinwheel
  // of small rectangles round each hole) or squeezes part of M0trim is kept
  // apart, taken only when no candidate tried gives a map without either.
  void consider(CutLoops cut) {
    MidsurfaceResult c;
    if (!try_automatic_cut(surfaces_, o_, std::move(cut), c, tried_)) return;
    const double score = cut_score(c.paths);
    const bool hole_cuts = !c.polycube.hole_cuts.empty();
    const double squeezed = squeezed_share(c.m0trim.mesh, c.polycube.jacobian);
    std::ostringstream line;
    line.precision(4);
    line << c.cut.source << ": valid" << (hole_cuts ? " with cuts from the holes' corners" : "");
    if (squeezed > kSqueezedShare)
      line << (hole_cuts ? " and" : "") << " with " << 100.0 * squeezed
           << " % of M0trim squeezed (its (u, v) map under a tenth of its median scale there)";
    line << ", path lengths to M0 mean " << c.paths.mean << ", spread " << std::sqrt(c.paths.variance) << " ("
         << c.paths.reached << " of " << c.paths.traced << " reached): score " << score;
    valid_.push_back(line.str());
    Best& b = hole_cuts ? with_hole_cuts_ : (squeezed > kSqueezedShare ? squeezed_ : best_);
    if (!b.result || score < kClearlyBetter * b.score) b.result = std::move(c), b.score = score;
  }
  // Found: a valid cut whose map needs no cuts from the holes' corners (the
  // later, costlier kinds of candidate are not tried). One that squeezes
  // part of M0trim counts, but loses to any that does not.
  bool found() const { return best_.result.has_value() || squeezed_.result.has_value(); }
  bool found_any() const { return found() || with_hole_cuts_.result.has_value(); }
  // Without the quality paths there is no score: the first valid cut is taken.
  bool done() const {
    return best_.result.has_value() && (!o_.path_lengths || best_.result->paths.mean <= good_enough_);
  }
  std::vector<std::string>& tried() { return tried_; }

  MidsurfaceResult take() {
    const bool clean = best_.result.has_value();
    MidsurfaceResult r = std::move(clean ? *best_.result : (squeezed_.result ? *squeezed_.result : *with_hole_cuts_.result));
    r.second_best = !clean;
    r.tried = std::move(tried_);
    r.valid = std::move(valid_);
    return r;
  }

 private:
  const std::vector<mesh::TriMesh>& surfaces_;
  const MidsurfaceOptions& o_;
  const double good_enough_;
  struct Best {
    std::optional<MidsurfaceResult> result;
    double score = 0.0;
  };
  Best best_, squeezed_, with_hole_cuts_;
  std::vector<std::string> tried_, valid_;
};

// The cut between the two sides of a thin solid (thin_sides.h).
void consider_thin_sides(const mesh::TriMesh& T1, const ThinSides& sides, const std::string& name,
                         CandidateCuts& candidates) {
  std::ostringstream src;
  src.precision(3);
  src << "thin sides (" << sides.plate_pairs << " plate pairs, median thickness " << sides.median_thickness << ")";
  try {
    CutLoops cut = cut_by_field(T1, sides.vertex_value, name, src.str());
    cut.source = "automatic: " + cut.source;
    candidates.consider(std::move(cut));
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::BadInput) throw;
    candidates.tried().push_back(std::string("thin sides: ") + e.what());
  }
}

// The cuts round the holes' waists, with the rim between the two sides
// (tunnel_loops.h): for solids whose holes no plane cuts all at once.
void consider_tunnel_loops(const mesh::TriMesh& T1, const std::string& name, CandidateCuts& candidates) {
  std::vector<std::vector<int>> loops;
  try {
    loops = tunnel_loops(T1);
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::BadInput) throw;
    candidates.tried().push_back(e.what());
    return;
  }
  std::vector<CutLoops> cuts = tunnel_loop_cuts(T1, loops, name, candidates.tried());
  // Every one is scored: the shortest loops need not give the shortest paths.
  for (std::size_t i = 0; i < cuts.size() && i < kTunnelCutsTried; ++i) {
    cuts[i].source = "automatic: " + cuts[i].source;
    candidates.consider(std::move(cuts[i]));
  }
}

// A principal plane; one that runs through a face of T1 (within the
// snapping tolerance) or along it is moved along its normal by a thousandth
// of T1's diagonal, once each way, before it is given up.
void consider_plane(const mesh::TriMesh& T1, const CutPlane& p, const std::string& name, CandidateCuts& candidates) {
  const double nudge = 1e-3 * (T1.V.colwise().maxCoeff() - T1.V.colwise().minCoeff()).norm();
  std::string first_refusal;
  for (const double shift : {0.0, nudge, -nudge}) {
    try {
      CutLoops cut = cut_by_plane(T1, {p.point + shift * p.normal, p.normal}, name);
      cut.source = "automatic: " + cut.source;
      candidates.consider(std::move(cut));
      return;
    } catch (const Error& e) {
      if (e.kind() != ErrorKind::BadInput) throw;
      if (first_refusal.empty()) first_refusal = e.what();
    }
  }
  candidates.tried().push_back(first_refusal);
}

// T1's extent along a direction.
double extent_along(const mesh::TriMesh& T1, const Eigen::Vector3d& d) {
  const Eigen::VectorXd x = T1.V * d;
  return x.maxCoeff() - x.minCoeff();
}

// A cut whose paths to M0 average at most this fraction of T1's extent
// along its smallest principal axis is as good as cutting a flat plate at
// its middle (half its thickness): the others are not tried. The built-in
// models' first planes: 0.28 (sphere2), 0.37 (ring2), 0.32 (torus3); the
// hand's palm plane 0.28, its plane across the width 0.63.
constexpr double kGoodEnough = 0.5;

// A solid counts as thin when its plate pairs are, at the median, less than
// half as far apart as the solid is thick along its smallest principal axis:
// a propeller (1.5 of 9.7), a pelvis; not an ellipsoid or a ring.
constexpr double kThinRatio = 0.5;

// The candidates, scored by cut_score: for a thin solid its two sides and
// the principal planes; for others the principal planes, and the two sides
// only when no plane gives a valid midsurface. When none does, the tunnel
// loops' cuts, then the plane family's shortest valid cuts (at most
// kFamilyTried). A cut whose map needs cuts from the holes' corners does not
// end the search: it is taken only when no later candidate does without. A
// cut whose map squeezes part of M0trim is not taken at once (the thin
// sides of a rod): the principal planes are tried, and any of them that
// does not squeeze wins.
MidsurfaceResult automatic_midsurface(const std::vector<mesh::TriMesh>& surfaces, const MidsurfaceOptions& o,
                                      const std::string& name) {
  const mesh::TriMesh& T1 = surfaces[0];
  const std::vector<CutPlane> planes = automatic_cut_planes(T1);
  // A flat plate cut at its middle: paths half its thickness long on average.
  CandidateCuts candidates(surfaces, o, kGoodEnough * extent_along(T1, planes.front().normal));
  std::optional<ThinSides> sides;
  try {
    sides = thin_sides(T1);
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::BadInput) throw;
    candidates.tried().push_back(std::string("thin sides: ") + e.what());
  }
  const bool thin = sides && sides->median_thickness < kThinRatio * extent_along(T1, sides->up);
  if (thin) consider_thin_sides(T1, *sides, name, candidates);
  // The three principal planes; the two offset ones (the last, see
  // automatic_cut_planes) only when none of them gives a valid midsurface.
  for (std::size_t i = 0; i < planes.size() && !candidates.done(); ++i) {
    if (i >= 3 && candidates.found()) break;
    consider_plane(T1, planes[i], name, candidates);
  }
  if (sides && !thin && !candidates.found()) consider_thin_sides(T1, *sides, name, candidates);
  if (!candidates.found() && closed_surface_genus(T1.F) >= 1) consider_tunnel_loops(T1, name, candidates);
  if (!candidates.found()) {
    const PlaneFamily family = cut_plane_family(T1, kFamilyNormals, kFamilyOffsets, name);
    auto& tried = candidates.tried();
    tried.push_back("plane family: " + std::to_string(family.valid.size()) + " of " + std::to_string(family.tried) +
                    " planes give valid loops; the others:");
    for (const auto& line : family.refusals) tried.push_back("  " + line);
    for (std::size_t i = 0; i < family.valid.size() && i < kFamilyTried && !candidates.done(); ++i)
      candidates.consider(family.valid[i]);
  }
  if (candidates.found_any()) return candidates.take();
  std::string all;
  for (const auto& t : candidates.tried()) all += "\n  " + t;
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
    r = automatic_midsurface(surfaces, o, name);
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
