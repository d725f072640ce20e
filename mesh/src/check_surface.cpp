#include "igaprep/mesh/check_surface.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <sstream>
#include <utility>

#include <Eigen/Geometry>

#include "igaprep/core/error.h"
#include "igaprep/core/union_find.h"
#include "igaprep/mesh/enclosed_volume.h"
#include "igaprep/mesh/read_surface.h"
#include "igaprep/mesh/self_intersections.h"
#include "igaprep/mesh/to_surface_mesh.h"

namespace igaprep::mesh {

namespace {

using Point = CgalPoint;

std::string coords(const Eigen::Vector3d& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%g, %g, %g)", p.x(), p.y(), p.z());
  return buf;
}

// One side of an undirected edge: the face it belongs to and whether the face
// runs along it from the smaller vertex to the larger.
struct HalfEdge {
  int lo, hi, face, corner;  // corner: index 0..2 in the face of the edge's first vertex
  bool forward;
};

}  // namespace

SurfaceReport check_surface(TriMesh& mesh, const std::string& name) {
  SurfaceReport r;
  r.file = name;
  auto error = [&](const std::string& what) { r.errors.push_back(name + ": " + what); };
  auto warning = [&](const std::string& what) { r.warnings.push_back(name + ": " + what); };
  Eigen::MatrixXd& V = mesh.V;
  Eigen::MatrixXi& F = mesh.F;
  const int nv = static_cast<int>(V.rows());
  const int nf = static_cast<int>(F.rows());

  if (nf == 0) {
    error("no faces (empty surface)");
    return r;
  }
  if (V.cols() != 3 || F.cols() != 3) {
    error("not a triangle mesh in 3D (V has " + std::to_string(V.cols()) + " columns, F has " +
          std::to_string(F.cols()) + ")");
    return r;
  }
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k)
      if (F(f, k) < 0 || F(f, k) >= nv) {
        error("face " + std::to_string(f) + " refers to vertex " + std::to_string(F(f, k)) + ", but there are only " +
              std::to_string(nv) + " vertices");
        return r;
      }
  {
    int bad = 0, first = -1;
    for (int i = 0; i < nv; ++i)
      if (!V.row(i).allFinite()) {
        if (first < 0) first = i;
        ++bad;
      }
    if (bad) {
      error(std::to_string(bad) + " vertices with NaN or infinite coordinates, e.g. vertex " + std::to_string(first));
      return r;
    }
  }
  auto P = [&](int i) -> Eigen::Vector3d { return V.row(i).transpose(); };

  // Referenced vertices, bounding box.
  std::vector<char> used(nv, 0);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) used[F(f, k)] = 1;
  r.faces = nf;
  r.vertices = static_cast<int>(std::count(used.begin(), used.end(), 1));
  r.bbox_min = Eigen::Vector3d::Constant(INFINITY);
  r.bbox_max = Eigen::Vector3d::Constant(-INFINITY);
  for (int i = 0; i < nv; ++i)
    if (used[i]) {
      r.bbox_min = r.bbox_min.cwiseMin(P(i));
      r.bbox_max = r.bbox_max.cwiseMax(P(i));
    }

  // Degenerate faces: a repeated vertex, or three collinear corners (exact test).
  int repeated = 0, flat = 0, first_degenerate = -1;
  for (int f = 0; f < nf; ++f) {
    const int a = F(f, 0), b = F(f, 1), c = F(f, 2);
    bool bad = false;
    if (a == b || b == c || a == c) {
      ++repeated;
      bad = true;
    } else if (CGAL::collinear(Point(V(a, 0), V(a, 1), V(a, 2)), Point(V(b, 0), V(b, 1), V(b, 2)),
                               Point(V(c, 0), V(c, 1), V(c, 2)))) {
      ++flat;
      bad = true;
    }
    if (bad && first_degenerate < 0) first_degenerate = f;
  }
  if (repeated + flat > 0) {
    const int f = first_degenerate;
    error(std::to_string(repeated + flat) + " degenerate faces (" + std::to_string(flat) + " with zero area, " +
          std::to_string(repeated) + " with a repeated vertex), e.g. face " + std::to_string(f) + " (vertices " +
          std::to_string(F(f, 0)) + ", " + std::to_string(F(f, 1)) + ", " + std::to_string(F(f, 2)) + ") at " +
          coords((P(F(f, 0)) + P(F(f, 1)) + P(F(f, 2))) / 3.0));
  }

  // Edges: sorted half-edges grouped by their undirected edge.
  std::vector<HalfEdge> half;
  half.reserve(3 * nf);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = F(f, k), b = F(f, (k + 1) % 3);
      if (a == b) continue;
      half.push_back({std::min(a, b), std::max(a, b), f, k, a < b});
    }
  std::sort(half.begin(), half.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return std::tie(x.lo, x.hi, x.face) < std::tie(y.lo, y.hi, y.face);
  });
  int num_edges = 0, boundary = 0, nonmanifold = 0, conflicts = 0;
  int ex_boundary = -1, ex_nonmanifold = -1, ex_conflict = -1, ex_nonmanifold_count = 0;
  UnionFind corner_sets(3 * nf);  // corners of a vertex joined across shared edges: one set per fan
  for (int f = 0; f < nf; ++f)      // a repeated vertex is one corner twice
    for (int k = 0; k < 3; ++k)
      if (F(f, k) == F(f, (k + 1) % 3)) corner_sets.unite(3 * f + k, 3 * f + (k + 1) % 3);
  for (size_t i = 0; i < half.size();) {
    size_t j = i;
    while (j < half.size() && half[j].lo == half[i].lo && half[j].hi == half[i].hi) ++j;
    const int count = static_cast<int>(j - i);
    ++num_edges;
    if (count == 1) {
      if (!boundary++) ex_boundary = static_cast<int>(i);
    } else if (count > 2) {
      if (!nonmanifold++) {
        ex_nonmanifold = static_cast<int>(i);
        ex_nonmanifold_count = count;
      }
    } else if (half[i].forward == half[i + 1].forward) {
      if (!conflicts++) ex_conflict = static_cast<int>(i);
    }
    if (count == 2) {
      // The edge joins the two faces' corners at each of its two vertices.
      for (int end = 0; end < 2; ++end) {
        const int v = end ? half[i].hi : half[i].lo;
        int c[2];
        for (int s = 0; s < 2; ++s) {
          const HalfEdge& h = half[i + s];
          c[s] = 3 * h.face + (F(h.face, h.corner) == v ? h.corner : (h.corner + 1) % 3);
        }
        corner_sets.unite(c[0], c[1]);
      }
    }
    i = j;
  }
  auto edge_text = [&](int i) {
    const HalfEdge& h = half[i];
    return "edge between vertices " + std::to_string(h.lo) + " and " + std::to_string(h.hi) + " at " +
           coords((P(h.lo) + P(h.hi)) / 2.0);
  };
  if (boundary) error(std::to_string(boundary) + " boundary edges (not closed), e.g. " + edge_text(ex_boundary));
  if (nonmanifold)
    error(std::to_string(nonmanifold) + " non-manifold edges (shared by more than two faces), e.g. " +
          edge_text(ex_nonmanifold) + ", shared by " + std::to_string(ex_nonmanifold_count) + " faces");
  if (conflicts)
    error("inconsistent orientation: " + std::to_string(conflicts) +
          " edges where the two faces disagree on orientation, e.g. " + edge_text(ex_conflict) + " (faces " +
          std::to_string(half[ex_conflict].face) + " and " + std::to_string(half[ex_conflict + 1].face) + ")");

  // Non-manifold vertices: more than one fan of faces around a vertex. Only
  // meaningful where the edges are manifold (otherwise already reported).
  int pinched = 0, ex_pinched = -1;
  if (nonmanifold == 0) {
    std::vector<int> fan_of(nv, -1);
    std::vector<char> counted(nv, 0);
    for (int f = 0; f < nf; ++f)
      for (int k = 0; k < 3; ++k) {
        const int v = F(f, k), set = corner_sets.find(3 * f + k);
        if (fan_of[v] < 0) fan_of[v] = set;
        else if (fan_of[v] != set && !counted[v]) {
          counted[v] = 1;
          if (!pinched++) ex_pinched = v;
        }
      }
    if (pinched)
      error(std::to_string(pinched) + " non-manifold vertices (several separate fans of faces meet there), e.g. vertex " +
            std::to_string(ex_pinched) + " at " + coords(P(ex_pinched)));
  }

  // Components, connected through shared vertices.
  UnionFind vertex_sets(nv);
  for (int f = 0; f < nf; ++f) {
    vertex_sets.unite(F(f, 0), F(f, 1));
    vertex_sets.unite(F(f, 0), F(f, 2));
  }
  std::vector<int> component_of_root(nv, -1), face_component(nf);
  std::vector<int> component_faces;
  for (int f = 0; f < nf; ++f) {
    const int root = vertex_sets.find(F(f, 0));
    if (component_of_root[root] < 0) {
      component_of_root[root] = static_cast<int>(component_faces.size());
      component_faces.push_back(0);
    }
    face_component[f] = component_of_root[root];
    ++component_faces[face_component[f]];
  }
  r.components = static_cast<int>(component_faces.size());
  if (r.components > 1) {
    std::string sizes;
    for (int c = 0; c < std::min(r.components, 5); ++c) sizes += (c ? ", " : "") + std::to_string(component_faces[c]);
    if (r.components > 5) sizes += ", ...";
    int second = 0;
    while (face_component[second] != 1) ++second;
    error("more than one component: " + std::to_string(r.components) + " separate pieces (faces per piece: " + sizes +
          "), e.g. the second starts at face " + std::to_string(second) + " at " + coords(P(F(second, 0))));
  }

  r.closed = boundary == 0;
  r.manifold = nonmanifold == 0 && pinched == 0;
  r.oriented = r.manifold && conflicts == 0;

  if (r.closed && r.manifold && r.oriented) {
    const int chi = r.vertices - num_edges + nf;
    r.genus = r.components - chi / 2;
    // Signed volume per component (about the box centre, for round-off); a
    // component enclosing negative volume faces inward: flip it.
    std::vector<double> volume = enclosed_volumes(mesh, face_component, r.components, (r.bbox_min + r.bbox_max) / 2.0);
    for (int c = 0; c < r.components; ++c)
      if (volume[c] < 0) {
        for (int f = 0; f < nf; ++f)
          if (face_component[f] == c) std::swap(F(f, 1), F(f, 2));
        volume[c] = -volume[c];
        warning(std::string("surface ") + (r.components > 1 ? "piece " + std::to_string(c + 1) + " " : "") +
                "is oriented inward (normals point into the solid); re-oriented outward");
      }
    r.volume = std::accumulate(volume.begin(), volume.end(), 0.0);
  }

  // Self-intersections with CGAL (exact predicates). Needs a mesh CGAL can
  // hold: manifold, consistently oriented, without degenerate faces.
  if (r.manifold && r.oriented && repeated + flat == 0) {
    const auto pairs = find_self_intersections(mesh);
    if (pairs) {
      r.self_intersections = static_cast<int>(pairs->size());
      if (!pairs->empty()) {
        const auto [f, g] = pairs->front();
        error(std::to_string(pairs->size()) + " pairs of self-intersecting faces, e.g. faces " + std::to_string(f) +
              " and " + std::to_string(g) + " near " + coords((P(F(f, 0)) + P(F(f, 1)) + P(F(f, 2))) / 3.0));
      }
    } else {
      warning("self-intersection test skipped: CGAL could not build the surface");
    }
  } else {
    warning("self-intersection test skipped because of the defects above");
  }

  // Vertices no face uses: drop them when the surface is otherwise fine.
  const int unused = nv - r.vertices;
  if (unused > 0 && r.ok()) {
    std::vector<int> new_index(nv, -1);
    Eigen::MatrixXd W(r.vertices, 3);
    int n = 0;
    for (int i = 0; i < nv; ++i)
      if (used[i]) {
        W.row(n) = V.row(i);
        new_index[i] = n++;
      }
    for (int f = 0; f < nf; ++f)
      for (int k = 0; k < 3; ++k) F(f, k) = new_index[F(f, k)];
    V = std::move(W);
    warning(std::to_string(unused) + " vertices used by no face were removed");
  } else if (unused > 0) {
    warning(std::to_string(unused) + " vertices are used by no face");
  }
  return r;
}

TriMesh load_checked_surface(const std::string& path, SurfaceReport* report) {
  TriMesh mesh = read_surface(path);
  SurfaceReport r = check_surface(mesh, path);
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
