// TetGen on the nested shells as one PLC. Materials are found by a flood fill
// over tet faces that do not lie on a shell, then one exact inside test per
// region (CGAL), rather than by TetGen's -A region seeds: seeds strictly
// between two shells are hard to place robustly, and an embedded closed
// surface would split a region so that one seed no longer reaches all of it.
#include "igaprep/mesh/tetrahedralize.h"

#include <tetgen.h>

#include <CGAL/Polygon_mesh_processing/intersection.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "cgal_surface.h"
#include "tetgen_run.h"
#include "igaprep/core/error.h"
#include "igaprep/mesh/enclosed_volume.h"

namespace igaprep::mesh {
namespace {

using detail::Kernel;
using detail::Point3;
using detail::SurfaceMesh;

struct FaceKey {
  std::array<int, 3> v;
  bool operator==(const FaceKey& o) const { return v == o.v; }
};
struct FaceKeyHash {
  std::size_t operator()(const FaceKey& k) const {
    std::uint64_t h = 1469598103934665603ULL;
    for (int x : k.v) h = (h ^ static_cast<std::uint64_t>(x)) * 1099511628211ULL;
    return static_cast<std::size_t>(h);
  }
};
FaceKey sorted_key(int a, int b, int c) {
  FaceKey k{{a, b, c}};
  std::sort(k.v.begin(), k.v.end());
  return k;
}

using FaceMap = std::unordered_map<FaceKey, int, FaceKeyHash>;

// The surfaces of the PLC, T1..Tn then the embedded ones, and where each
// one's points start in the concatenated point list.
struct SurfaceSet {
  std::vector<const TriMesh*> all;
  int n = 0;  // closed shells T1..Tn, the first n of `all`
  std::vector<int> vertex_offset;
  int num_points = 0, num_faces = 0;

  std::string name(int k) const {
    return k < n ? "surface T" + std::to_string(k + 1) : "embedded surface " + std::to_string(k - n);
  }
};

SurfaceSet collect_surfaces(const std::vector<TriMesh>& surfaces, const std::vector<TriMesh>& embedded) {
  SurfaceSet set;
  set.n = static_cast<int>(surfaces.size());
  for (const auto& s : surfaces) set.all.push_back(&s);
  for (const auto& s : embedded) set.all.push_back(&s);
  for (std::size_t k = 0; k < set.all.size(); ++k) {
    const TriMesh& m = *set.all[k];
    const std::string name = set.name(static_cast<int>(k));
    if (m.F.rows() == 0) throw bad_input("tetrahedralize: " + name + " has no triangles");
    if (m.F.minCoeff() < 0 || m.F.maxCoeff() >= m.V.rows()) {
      throw bad_input("tetrahedralize: " + name + " has an out-of-range vertex index");
    }
    if (!m.V.allFinite()) throw bad_input("tetrahedralize: " + name + " has a non-finite vertex");
    set.vertex_offset.push_back(set.num_points);
    set.num_points += static_cast<int>(m.V.rows());
    set.num_faces += static_cast<int>(m.F.rows());
  }
  return set;
}

// Every input triangle with concatenated vertex indices; marker = surface index.
void concatenate_faces(const SurfaceSet& set, TetMesh& out) {
  out.F.resize(set.num_faces, 3);
  out.F_marker.resize(set.num_faces);
  int f = 0;
  for (std::size_t k = 0; k < set.all.size(); ++k) {
    for (Eigen::Index t = 0; t < set.all[k]->F.rows(); ++t, ++f) {
      out.F.row(f) = set.all[k]->F.row(t).array() + set.vertex_offset[k];
      out.F_marker(f) = static_cast<int>(k);
    }
  }
}

// Surfaces that cross each other make no valid PLC: say which ones, decided
// exactly (CGAL), before TetGen gives its terser verdict.
void check_pairs_apart(const SurfaceSet& set, const std::vector<SurfaceMesh>& meshes) {
  for (std::size_t i = 0; i < set.all.size(); ++i)
    for (std::size_t j = i + 1; j < set.all.size(); ++j)
      if (CGAL::Polygon_mesh_processing::do_intersect(meshes[i], meshes[j],
                                                      CGAL::parameters::do_overlap_test_of_bounded_sides(false),
                                                      CGAL::parameters::do_overlap_test_of_bounded_sides(false))) {
        throw bad_input("tetrahedralize: " + set.name(static_cast<int>(i)) + " and " +
                        set.name(static_cast<int>(j)) + " intersect or touch; surfaces must be strictly nested");
      }
}

// Nor does an embedded surface that crosses itself (the input surfaces were
// checked when they were read; an embedded one, such as the base surface M,
// is made by the pipeline). TetGen would only say "a segment and a subface
// intersect", or crash.
void check_embedded_not_self_intersecting(const SurfaceSet& set, const std::vector<SurfaceMesh>& meshes) {
  for (std::size_t k = static_cast<std::size_t>(set.n); k < set.all.size(); ++k) {
    std::vector<std::pair<SurfaceMesh::Face_index, SurfaceMesh::Face_index>> pairs;
    CGAL::Polygon_mesh_processing::self_intersections(meshes[k], std::back_inserter(pairs));
    if (pairs.empty()) continue;
    const TriMesh& m = *set.all[k];
    const Eigen::Index f = static_cast<Eigen::Index>(pairs.front().first.idx());
    const Eigen::RowVector3d c = (m.V.row(m.F(f, 0)) + m.V.row(m.F(f, 1)) + m.V.row(m.F(f, 2))) / 3.0;
    char where[96];
    std::snprintf(where, sizeof where, "(%.6g, %.6g, %.6g)", c(0), c(1), c(2));
    throw bad_input("tetrahedralize: " + set.name(static_cast<int>(k)) + " intersects itself: " +
                    std::to_string(pairs.size()) + " pairs of triangles, the first near " + where);
  }
}

// CGAL copies of the surfaces, checked: shells closed, no two surfaces
// touching, no embedded surface crossing itself. The shells' copies later
// decide the materials.
std::vector<SurfaceMesh> checked_surface_meshes(const SurfaceSet& set) {
  std::vector<SurfaceMesh> meshes;
  meshes.reserve(set.all.size());
  for (std::size_t k = 0; k < set.all.size(); ++k) {
    meshes.push_back(to_surface_mesh(*set.all[k], "tetrahedralize: " + set.name(static_cast<int>(k))));
  }
  for (int k = 0; k < set.n; ++k) {
    if (!CGAL::is_closed(meshes[k])) throw bad_input("tetrahedralize: " + set.name(k) + " is not closed");
  }
  check_pairs_apart(set, meshes);
  check_embedded_not_self_intersecting(set, meshes);
  return meshes;
}

// TetGen's PLC: the points, and one facet per input triangle with marker
// surface index + 1 (TetGen reserves 0 for "no facet").
void fill_tetgen_input(const SurfaceSet& set, const TetMesh& out, tetgenio& in) {
  in.firstnumber = 0;
  in.numberofpoints = set.num_points;
  in.pointlist = new REAL[3 * set.num_points];
  for (std::size_t k = 0; k < set.all.size(); ++k) {
    const TriMesh& m = *set.all[k];
    for (Eigen::Index i = 0; i < m.V.rows(); ++i) {
      for (int c = 0; c < 3; ++c) in.pointlist[3 * (set.vertex_offset[k] + i) + c] = m.V(i, c);
    }
  }
  in.numberoffacets = set.num_faces;
  in.facetlist = new tetgenio::facet[set.num_faces];
  in.facetmarkerlist = new int[set.num_faces];
  for (int f = 0; f < set.num_faces; ++f) {
    tetgenio::facet& facet = in.facetlist[f];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&facet.polygonlist[0]);
    facet.polygonlist[0].numberofvertices = 3;
    facet.polygonlist[0].vertexlist = new int[3];
    for (int c = 0; c < 3; ++c) facet.polygonlist[0].vertexlist[c] = out.F(f, c);
    in.facetmarkerlist[f] = out.F_marker(f) + 1;
  }
}

// p: PLC; Y: no Steiner points on the input facets; z: 0-based; n: neighbours.
// No Q: TetGen then also prints why it fails; its output is captured and
// shown only when options.quiet is false.
std::string tetgen_switches(const TetgenOptions& options) {
  std::string switches = "pYzn";
  if (options.radius_edge_ratio > 0) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "q%.17g", options.radius_edge_ratio);
    switches += buf;
  }
  if (options.max_volume > 0) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "a%.17g", options.max_volume);
    switches += buf;
  }
  return switches;
}

// TetGen's points; -Y keeps every input point at its index: refused when
// TetGen merged, dropped or moved any (it does for duplicated points).
void copy_points(const detail::TetgenOutput& result, const tetgenio& in, TetMesh& out) {
  const int num_points = in.numberofpoints;
  const int result_points = static_cast<int>(result.points.size() / 3);
  if (result_points < num_points) {
    throw bad_input("tetrahedralize: TetGen dropped " + std::to_string(num_points - result_points) +
                    " input points (duplicated vertices within or between surfaces?)");
  }
  out.V.resize(result_points, 3);
  for (int i = 0; i < result_points; ++i) {
    for (int c = 0; c < 3; ++c) out.V(i, c) = result.points[3 * i + c];
  }
  for (int i = 0; i < num_points; ++i) {
    if (out.V(i, 0) != in.pointlist[3 * i] || out.V(i, 1) != in.pointlist[3 * i + 1] ||
        out.V(i, 2) != in.pointlist[3 * i + 2]) {
      throw bad_input("tetrahedralize: TetGen moved or merged input point " + std::to_string(i) +
                      " (duplicated vertices within or between surfaces?)");
    }
  }
}

// TetGen's tets, each made positively oriented.
void copy_tets(const detail::TetgenOutput& result, int num_surfaces, TetMesh& out) {
  const int nt = static_cast<int>(result.tets.size() / 4);
  if (nt == 0) {
    throw bad_input("tetrahedralize: TetGen produced no tetrahedra for the " + std::to_string(num_surfaces) +
                    " input surfaces");
  }
  out.T.resize(nt, 4);
  for (int t = 0; t < nt; ++t) {
    for (int c = 0; c < 4; ++c) out.T(t, c) = result.tets[4 * t + c];
    const Eigen::Vector3d a = out.V.row(out.T(t, 0)), b = out.V.row(out.T(t, 1)), c = out.V.row(out.T(t, 2)),
                          d = out.V.row(out.T(t, 3));
    if ((b - a).dot((c - a).cross(d - a)) < 0) std::swap(out.T(t, 2), out.T(t, 3));
  }
}

// Input triangle (sorted vertices) -> its marker.
FaceMap input_faces(const TetMesh& out) {
  FaceMap shell_face;
  shell_face.reserve(out.F.rows() * 2);
  for (Eigen::Index f = 0; f < out.F.rows(); ++f)
    shell_face.emplace(sorted_key(out.F(f, 0), out.F(f, 1), out.F(f, 2)), out.F_marker(f));
  return shell_face;
}

// Every input triangle must be a tet face (that is what -Y promises).
void check_input_faces_kept(const TetMesh& out, const FaceMap& shell_face) {
  FaceMap seen;
  seen.reserve(shell_face.size() * 2);
  static const int kFace[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  for (Eigen::Index t = 0; t < out.T.rows(); ++t) {
    for (const auto& fc : kFace) {
      FaceKey key = sorted_key(out.T(t, fc[0]), out.T(t, fc[1]), out.T(t, fc[2]));
      if (shell_face.count(key)) seen.emplace(key, 1);
    }
  }
  if (seen.size() != shell_face.size()) {
    throw bad_input("tetrahedralize: " + std::to_string(shell_face.size() - seen.size()) +
                    " input triangles are not tet faces (are two surfaces overlapping or touching?)");
  }
}

// Connected regions of tets across faces that do not lie on a shell T1..Tn
// (markers below n); one representative tet per region, the lowest.
struct Regions {
  std::vector<int> region;          // per tet
  std::vector<int> representative;  // per region
};

Regions flood_fill_regions(const detail::TetgenOutput& result, const FaceMap& shell_face, int n) {
  const int nt = static_cast<int>(result.tets.size() / 4);
  Regions r;
  r.region.assign(nt, -1);
  static const int kOpposite[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  std::vector<int> stack;
  for (int seed = 0; seed < nt; ++seed) {
    if (r.region[seed] >= 0) continue;
    const int id = static_cast<int>(r.representative.size());
    r.representative.push_back(seed);
    r.region[seed] = id;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const int t = stack.back();
      stack.pop_back();
      for (int j = 0; j < 4; ++j) {
        // TetGen's neighbour j is opposite corner j of its own (unswapped) tet;
        // the face is the same set of vertices either way.
        const int nb = result.neighbors[4 * t + j];
        if (nb < 0 || r.region[nb] >= 0) continue;
        const int* tv = &result.tets[4 * t];
        auto it = shell_face.find(sorted_key(tv[kOpposite[j][0]], tv[kOpposite[j][1]], tv[kOpposite[j][2]]));
        if (it != shell_face.end() && it->second < n) continue;
        r.region[nb] = id;
        stack.push_back(nb);
      }
    }
  }
  return r;
}

// Material of a region = (number of shells containing an interior point) - 1,
// decided with CGAL's exact predicates at its representative's centroid.
std::vector<int> region_materials(const std::vector<SurfaceMesh>& meshes, int n, const TetMesh& out,
                                  const std::vector<int>& representative) {
  using InsideTest = CGAL::Side_of_triangle_mesh<SurfaceMesh, Kernel>;
  std::vector<std::unique_ptr<InsideTest>> inside_test;
  for (int k = 0; k < n; ++k) inside_test.push_back(std::make_unique<InsideTest>(meshes[k]));
  std::vector<int> material(representative.size());
  for (std::size_t r = 0; r < representative.size(); ++r) {
    const int t = representative[r];
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int j = 0; j < 4; ++j) c += out.V.row(out.T(t, j)).transpose();
    c /= 4.0;
    int inside = 0;
    for (int k = 0; k < n; ++k) {
      const auto s = (*inside_test[k])(Point3(c(0), c(1), c(2)));
      if (s == CGAL::ON_BOUNDED_SIDE) ++inside;
      if (s == CGAL::ON_BOUNDARY) throw internal_error("tetrahedralize: a tet centroid lies on an input surface");
    }
    if (inside == 0) {
      throw bad_input("tetrahedralize: TetGen kept tetrahedra outside T1; is T1 closed?");
    }
    material[r] = inside - 1;
  }
  return material;
}

// Every tet is at most max_volume: T1's volume over it is a lower bound of
// the count, known before TetGen allocates anything.
void refuse_too_many_tets(const TriMesh& outer, const TetgenOptions& options) {
  if (!(options.max_volume > 0.0)) return;
  const double at_least = std::abs(enclosed_volume(outer)) / options.max_volume;
  if (at_least > options.max_tets) {
    std::ostringstream s;
    s << "tetrahedralize: a maximum tet volume of " << options.max_volume << " makes at least " << at_least
      << " tets (the volume " << std::abs(enclosed_volume(outer)) << " over it), more than the limit of "
      << options.max_tets << " (max_tets); choose a larger maximum volume, or raise the limit if the machine has the "
      << "memory (about 1 GB per 5 million tets)";
    throw bad_input(s.str());
  }
}

}  // namespace

TetMesh tetrahedralize(const std::vector<TriMesh>& surfaces, const std::vector<TriMesh>& embedded,
                       const TetgenOptions& options) {
  if (surfaces.empty()) throw bad_input("tetrahedralize: no surfaces given");
  refuse_too_many_tets(surfaces.front(), options);
  const SurfaceSet set = collect_surfaces(surfaces, embedded);
  TetMesh out;
  concatenate_faces(set, out);
  const std::vector<SurfaceMesh> meshes = checked_surface_meshes(set);

  tetgenio in;
  fill_tetgen_input(set, out, in);
  const detail::TetgenOutput result = detail::run_tetgen(
      in, tetgen_switches(options), !options.quiet, "tetrahedralize (" + std::to_string(set.all.size()) + " surfaces)");
  copy_points(result, in, out);
  copy_tets(result, static_cast<int>(set.all.size()), out);

  const FaceMap shell_face = input_faces(out);
  check_input_faces_kept(out, shell_face);
  const Regions regions = flood_fill_regions(result, shell_face, set.n);
  const std::vector<int> material = region_materials(meshes, set.n, out, regions.representative);
  out.material.resize(out.T.rows());
  for (Eigen::Index t = 0; t < out.T.rows(); ++t) out.material(t) = material[regions.region[t]];
  return out;
}

}  // namespace igaprep::mesh
