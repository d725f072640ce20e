#include "igaprep/mesh/check_surface.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <sstream>
#include <tuple>
#include <utility>

#include <Eigen/Geometry>

#include "igaprep/core/error.h"
#include "igaprep/core/union_find.h"
#include "igaprep/mesh/orient_outward.h"
#include "igaprep/mesh/read_surface.h"
#include "igaprep/mesh/remove_unused_vertices.h"
#include "igaprep/mesh/self_intersections.h"
#include "igaprep/mesh/to_surface_mesh.h"
#include "surface_pieces.h"

namespace igaprep::mesh {

namespace {

std::string coords(const Eigen::Vector3d& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%g, %g, %g)", p.x(), p.y(), p.z());
  return buf;
}

Eigen::Vector3d point(const TriMesh& m, int v) { return m.V.row(v).transpose(); }

Eigen::Vector3d face_centre(const TriMesh& m, int f) {
  return (point(m, m.F(f, 0)) + point(m, m.F(f, 1)) + point(m, m.F(f, 2))) / 3.0;
}

// Every message starts with the surface's name.
void add_error(SurfaceReport& r, const std::string& what) { r.errors.push_back(r.file + ": " + what); }
void add_warning(SurfaceReport& r, const std::string& what) { r.warnings.push_back(r.file + ": " + what); }

// The warnings about what check_and_repair_surface repairs, as the check
// words them and as the repair does (it rewrites them once done).
std::string inward_warning(const SurfaceReport& r, int piece, bool repaired) {
  return r.file + ": surface " + (r.components > 1 ? "piece " + std::to_string(piece + 1) + " " : "") +
         "is oriented inward (normals point into the solid)" + (repaired ? "; re-oriented outward" : "");
}
std::string unused_warning(const SurfaceReport& r, bool removed) {
  return r.file + ": " + std::to_string(r.unused_vertices) +
         (removed ? " vertices used by no face were removed" : " vertices are used by no face");
}

// ---- step 1: arrays the other steps can read

// Adds an error and returns false when the arrays cannot be checked further:
// no faces, not 3 columns, an index out of range, a non-finite coordinate.
bool arrays_readable(const TriMesh& m, SurfaceReport& r) {
  const int nv = static_cast<int>(m.V.rows()), nf = static_cast<int>(m.F.rows());
  if (nf == 0) {
    add_error(r, "no faces (empty surface)");
    return false;
  }
  if (m.V.cols() != 3 || m.F.cols() != 3) {
    add_error(r, "not a triangle mesh in 3D (V has " + std::to_string(m.V.cols()) + " columns, F has " +
                     std::to_string(m.F.cols()) + ")");
    return false;
  }
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k)
      if (m.F(f, k) < 0 || m.F(f, k) >= nv) {
        add_error(r, "face " + std::to_string(f) + " refers to vertex " + std::to_string(m.F(f, k)) +
                         ", but there are only " + std::to_string(nv) + " vertices");
        return false;
      }
  int bad = 0, first = -1;
  for (int i = 0; i < nv; ++i)
    if (!m.V.row(i).allFinite()) {
      if (first < 0) first = i;
      ++bad;
    }
  if (bad) {
    add_error(r, std::to_string(bad) + " vertices with NaN or infinite coordinates, e.g. vertex " + std::to_string(first));
    return false;
  }
  return true;
}

// ---- step 2: size

void measure_size(const TriMesh& m, SurfaceReport& r) {
  std::vector<char> used(static_cast<std::size_t>(m.V.rows()), 0);
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) used[static_cast<std::size_t>(m.F(f, k))] = 1;
  r.faces = static_cast<int>(m.F.rows());
  r.vertices = static_cast<int>(std::count(used.begin(), used.end(), 1));
  r.unused_vertices = static_cast<int>(m.V.rows()) - r.vertices;
  std::tie(r.bbox_min, r.bbox_max) = detail::referenced_bounding_box(m);
}

// ---- step 3: degenerate faces

struct DegenerateFaces {
  int repeated = 0, flat = 0, first = -1;
  int count() const { return repeated + flat; }
};

// A repeated vertex, or three collinear corners (exact predicate).
DegenerateFaces find_degenerate_faces(const TriMesh& m) {
  auto cgal_point = [&](int v) { return CgalPoint(m.V(v, 0), m.V(v, 1), m.V(v, 2)); };
  DegenerateFaces d;
  for (int f = 0; f < m.F.rows(); ++f) {
    const int a = m.F(f, 0), b = m.F(f, 1), c = m.F(f, 2);
    bool bad = false;
    if (a == b || b == c || a == c) {
      ++d.repeated;
      bad = true;
    } else if (CGAL::collinear(cgal_point(a), cgal_point(b), cgal_point(c))) {
      ++d.flat;
      bad = true;
    }
    if (bad && d.first < 0) d.first = f;
  }
  return d;
}

void report_degenerate_faces(const TriMesh& m, const DegenerateFaces& d, SurfaceReport& r) {
  if (d.count() == 0) return;
  const int f = d.first;
  add_error(r, std::to_string(d.count()) + " degenerate faces (" + std::to_string(d.flat) + " with zero area, " +
                   std::to_string(d.repeated) + " with a repeated vertex), e.g. face " + std::to_string(f) +
                   " (vertices " + std::to_string(m.F(f, 0)) + ", " + std::to_string(m.F(f, 1)) + ", " +
                   std::to_string(m.F(f, 2)) + ") at " + coords(face_centre(m, f)));
}

// ---- step 4: edges

// One side of an undirected edge: the face it belongs to and whether the face
// runs along it from the smaller vertex to the larger.
struct HalfEdge {
  int lo, hi, face, corner;  // corner: index 0..2 in the face of the edge's first vertex
  bool forward;
};

// The half-edges sorted by undirected edge (then face); each edge is a run
// [first, end) of them. Counts of the edges by how many faces share them,
// with the first example of each defect.
struct EdgeCensus {
  std::vector<HalfEdge> half;
  std::vector<std::pair<std::size_t, std::size_t>> runs;
  int boundary = 0, nonmanifold = 0, conflicts = 0;
  std::size_t ex_boundary = 0, ex_nonmanifold = 0, ex_conflict = 0;  // first half-edge of the example
  int ex_nonmanifold_count = 0;
  int edges() const { return static_cast<int>(runs.size()); }
};

std::vector<HalfEdge> sorted_half_edges(const TriMesh& m) {
  std::vector<HalfEdge> half;
  half.reserve(3 * static_cast<std::size_t>(m.F.rows()));
  for (int f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = m.F(f, k), b = m.F(f, (k + 1) % 3);
      if (a == b) continue;
      half.push_back({std::min(a, b), std::max(a, b), f, k, a < b});
    }
  std::sort(half.begin(), half.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return std::tie(x.lo, x.hi, x.face) < std::tie(y.lo, y.hi, y.face);
  });
  return half;
}

EdgeCensus census_edges(const TriMesh& m) {
  EdgeCensus e;
  e.half = sorted_half_edges(m);
  const std::vector<HalfEdge>& half = e.half;
  for (std::size_t i = 0; i < half.size();) {
    std::size_t j = i;
    while (j < half.size() && half[j].lo == half[i].lo && half[j].hi == half[i].hi) ++j;
    e.runs.emplace_back(i, j);
    const int count = static_cast<int>(j - i);
    if (count == 1) {
      if (!e.boundary++) e.ex_boundary = i;
    } else if (count > 2) {
      if (!e.nonmanifold++) {
        e.ex_nonmanifold = i;
        e.ex_nonmanifold_count = count;
      }
    } else if (half[i].forward == half[i + 1].forward) {
      if (!e.conflicts++) e.ex_conflict = i;
    }
    i = j;
  }
  return e;
}

void report_edge_defects(const TriMesh& m, const EdgeCensus& e, SurfaceReport& r) {
  auto edge_text = [&](std::size_t i) {
    const HalfEdge& h = e.half[i];
    return "edge between vertices " + std::to_string(h.lo) + " and " + std::to_string(h.hi) + " at " +
           coords((point(m, h.lo) + point(m, h.hi)) / 2.0);
  };
  if (e.boundary)
    add_error(r, std::to_string(e.boundary) + " boundary edges (not closed), e.g. " + edge_text(e.ex_boundary));
  if (e.nonmanifold)
    add_error(r, std::to_string(e.nonmanifold) + " non-manifold edges (shared by more than two faces), e.g. " +
                     edge_text(e.ex_nonmanifold) + ", shared by " + std::to_string(e.ex_nonmanifold_count) + " faces");
  if (e.conflicts)
    add_error(r, "inconsistent orientation: " + std::to_string(e.conflicts) +
                     " edges where the two faces disagree on orientation, e.g. " + edge_text(e.ex_conflict) +
                     " (faces " + std::to_string(e.half[e.ex_conflict].face) + " and " +
                     std::to_string(e.half[e.ex_conflict + 1].face) + ")");
}

// ---- step 5: vertices where separate fans of faces meet

// Corner 3 f + k of face f: joined with the corners of the same vertex in
// the faces across its two edges, so that each set is one fan of faces.
UnionFind corner_fans(const TriMesh& m, const EdgeCensus& e) {
  UnionFind fans(3 * static_cast<int>(m.F.rows()));
  for (int f = 0; f < m.F.rows(); ++f)  // a repeated vertex is one corner twice
    for (int k = 0; k < 3; ++k)
      if (m.F(f, k) == m.F(f, (k + 1) % 3)) fans.unite(3 * f + k, 3 * f + (k + 1) % 3);
  for (const auto& [i, j] : e.runs) {
    if (j - i != 2) continue;
    // The edge joins the two faces' corners at each of its two vertices.
    for (int end = 0; end < 2; ++end) {
      const int v = end ? e.half[i].hi : e.half[i].lo;
      int c[2];
      for (int s = 0; s < 2; ++s) {
        const HalfEdge& h = e.half[i + static_cast<std::size_t>(s)];
        c[s] = 3 * h.face + (m.F(h.face, h.corner) == v ? h.corner : (h.corner + 1) % 3);
      }
      fans.unite(c[0], c[1]);
    }
  }
  return fans;
}

// Only meaningful where every edge is manifold (otherwise already reported).
// Returns how many vertices have more than one fan.
int report_pinched_vertices(const TriMesh& m, const EdgeCensus& e, SurfaceReport& r) {
  UnionFind fans = corner_fans(m, e);
  const std::size_t nv = static_cast<std::size_t>(m.V.rows());
  std::vector<int> fan_of(nv, -1);
  std::vector<char> counted(nv, 0);
  int pinched = 0, example = -1;
  for (int f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const std::size_t v = static_cast<std::size_t>(m.F(f, k));
      const int fan = fans.find(3 * f + k);
      if (fan_of[v] < 0) {
        fan_of[v] = fan;
      } else if (fan_of[v] != fan && !counted[v]) {
        counted[v] = 1;
        if (!pinched++) example = static_cast<int>(v);
      }
    }
  if (pinched)
    add_error(r, std::to_string(pinched) +
                     " non-manifold vertices (several separate fans of faces meet there), e.g. vertex " +
                     std::to_string(example) + " at " + coords(point(m, example)));
  return pinched;
}

// ---- step 6: pieces

void report_pieces(const TriMesh& m, const detail::SurfacePieces& pieces, SurfaceReport& r) {
  r.components = pieces.count();
  if (r.components <= 1) return;
  std::string sizes;
  for (int c = 0; c < std::min(r.components, 5); ++c)
    sizes += (c ? ", " : "") + std::to_string(pieces.face_count[static_cast<std::size_t>(c)]);
  if (r.components > 5) sizes += ", ...";
  int second = 0;
  while (pieces.of_face[static_cast<std::size_t>(second)] != 1) ++second;
  add_error(r, "more than one component: " + std::to_string(r.components) + " separate pieces (faces per piece: " +
                   sizes + "), e.g. the second starts at face " + std::to_string(second) + " at " +
                   coords(point(m, m.F(second, 0))));
}

// ---- step 7: genus and volume of a closed, manifold, oriented surface

void measure_genus_and_volume(const TriMesh& m, int edges, const detail::SurfacePieces& pieces, SurfaceReport& r) {
  const int chi = r.vertices - edges + r.faces;
  r.genus = r.components - chi / 2;
  // A piece enclosing negative volume faces inward: the volume counts it
  // turned outward (as orient_outward will).
  std::vector<double> volume = detail::piece_volumes(m, pieces);
  for (int c = 0; c < r.components; ++c)
    if (volume[static_cast<std::size_t>(c)] < 0) {
      r.inward_pieces.push_back(c);
      r.warnings.push_back(inward_warning(r, c, false));
      volume[static_cast<std::size_t>(c)] = -volume[static_cast<std::size_t>(c)];
    }
  r.volume = std::accumulate(volume.begin(), volume.end(), 0.0);
  // Coordinates near the largest double overflow the volume; near the
  // smallest, it underflows to nothing: no later step can use such a solid.
  const Eigen::Vector3d size = r.bbox_max - r.bbox_min;
  if (!std::isfinite(r.volume))
    add_error(r, "its enclosed volume overflows (coordinates up to " + std::to_string(size.cwiseAbs().maxCoeff()) +
                     " apart): scale the model");
  else if (!(r.volume > 1e-12 * size[0] * size[1] * size[2]) || !(r.volume > 0.0))
    add_error(r, "it encloses no volume (" + std::to_string(r.volume) +
                     "): a flat surface, or coordinates too small to compute with; scale the model");
}

// ---- step 8: self-intersections

// CGAL decides with exact predicates; it needs a surface it can hold:
// manifold, consistently oriented, without degenerate faces.
void test_self_intersections(const TriMesh& m, bool degenerate_faces, SurfaceReport& r) {
  if (!(r.manifold && r.oriented) || degenerate_faces) {
    add_warning(r, "self-intersection test skipped because of the defects above");
    return;
  }
  const auto pairs = find_self_intersections(m);
  if (!pairs) {
    add_warning(r, "self-intersection test skipped: CGAL could not build the surface");
    return;
  }
  r.self_intersections = static_cast<int>(pairs->size());
  if (pairs->empty()) return;
  const auto [f, g] = pairs->front();
  add_error(r, std::to_string(pairs->size()) + " pairs of self-intersecting faces, e.g. faces " + std::to_string(f) +
                   " and " + std::to_string(g) + " near " + coords(face_centre(m, f)));
}

// Replaces the warning `from` (when present) by `to`.
void reword_warning(SurfaceReport& r, const std::string& from, const std::string& to) {
  const auto it = std::find(r.warnings.begin(), r.warnings.end(), from);
  if (it != r.warnings.end()) *it = to;
}

}  // namespace

SurfaceReport check_surface(const TriMesh& mesh, const std::string& name) {
  SurfaceReport r;
  r.file = name;
  if (!arrays_readable(mesh, r)) return r;
  measure_size(mesh, r);
  const DegenerateFaces degenerate = find_degenerate_faces(mesh);
  report_degenerate_faces(mesh, degenerate, r);
  const EdgeCensus edges = census_edges(mesh);
  report_edge_defects(mesh, edges, r);
  const int pinched = edges.nonmanifold == 0 ? report_pinched_vertices(mesh, edges, r) : 0;
  const detail::SurfacePieces pieces = detail::surface_pieces(mesh);
  report_pieces(mesh, pieces, r);
  r.closed = edges.boundary == 0;
  r.manifold = edges.nonmanifold == 0 && pinched == 0;
  r.oriented = r.manifold && edges.conflicts == 0;
  if (r.closed && r.manifold && r.oriented) measure_genus_and_volume(mesh, edges.edges(), pieces, r);
  test_self_intersections(mesh, degenerate.count() > 0, r);
  if (r.unused_vertices > 0) r.warnings.push_back(unused_warning(r, false));
  return r;
}

SurfaceReport check_and_repair_surface(TriMesh& mesh, const std::string& name) {
  SurfaceReport r = check_surface(std::as_const(mesh), name);
  if (!r.inward_pieces.empty()) {
    orient_outward(mesh);  // turns exactly r.inward_pieces: the same pieces and volumes
    for (int c : r.inward_pieces) reword_warning(r, inward_warning(r, c, false), inward_warning(r, c, true));
  }
  if (r.unused_vertices > 0 && r.ok()) {
    remove_unused_vertices(mesh);
    reword_warning(r, unused_warning(r, false), unused_warning(r, true));
  }
  return r;
}

TriMesh load_checked_surface(const std::string& path, SurfaceReport* report) {
  TriMesh mesh = read_surface(path);
  SurfaceReport r = check_and_repair_surface(mesh, path);
  if (report) *report = r;
  if (!r.ok()) {
    std::string all;
    for (const auto& e : r.errors) all += (all.empty() ? "" : "\n") + e;
    throw bad_input(all);
  }
  return mesh;
}

std::string format_report(const SurfaceReport& r) {
  std::ostringstream s;
  auto yes = [](bool b) { return b ? "yes" : "no"; };
  s << "surface: " << r.file << "\n"
    << "vertices: " << r.vertices << "\n"
    << "faces: " << r.faces << "\n"
    << "components: " << r.components << "\n"
    << "genus: " << (r.genus >= 0 ? std::to_string(r.genus) : std::string("undefined")) << "\n"
    << "closed: " << yes(r.closed) << "\n"
    << "manifold: " << yes(r.manifold) << "\n"
    << "oriented: " << yes(r.oriented) << "\n"
    << "self-intersections: "
    << (r.self_intersections >= 0 ? std::to_string(r.self_intersections) : std::string("not tested")) << "\n"
    << "volume: " << r.volume << "\n"
    << "bounding box: " << coords(r.bbox_min) << " to " << coords(r.bbox_max) << "\n";
  for (const auto& w : r.warnings) s << "warning: " << w << "\n";
  for (const auto& e : r.errors) s << "error: " << e << "\n";
  return s.str();
}

}  // namespace igaprep::mesh
