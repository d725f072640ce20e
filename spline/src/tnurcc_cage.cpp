#include "igaprep/spline/tnurcc_cage.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <queue>
#include <unordered_map>

#include "igaprep/core/edge_key.h"
#include "igaprep/core/angle.h"
#include "igaprep/core/error.h"
#include "igaprep/spline/curve_surface.h"
#include "igaprep/spline/label_sides.h"
#include "igaprep/spline/multipatch_topology.h"


namespace igaprep::spline {
namespace {

// Knot interval of each net edge (P_i, P_{i+1}) along one direction, the
// knots scaled to [0, 1]; zero intervals take the nearest positive one.
std::vector<double> net_intervals(const std::vector<double>& U, int p) {
  if (p % 2 == 0)
    throw bad_input("T-NURCC cage: degree " + std::to_string(p) +
                    " is even; knot intervals are defined here for odd degrees only");
  const int n = static_cast<int>(U.size()) - p - 1;
  const double a = U[p], b = U[U.size() - p - 1];
  const int c = (p + 1) / 2;
  std::vector<double> d(n - 1);
  for (int i = 0; i + 1 < n; ++i) d[i] = (U[i + c + 1] - U[i + c]) / (b - a);
  const double tiny = 1e-14;
  for (int i = 1; i < n - 1; ++i)
    if (d[i] <= tiny) d[i] = d[i - 1];
  for (int i = n - 3; i >= 0; --i)
    if (d[i] <= tiny) d[i] = d[i + 1];
  return d;
}

Eigen::Vector3d face_normal(const Cage& cage, int f) {
  const auto& c = cage.faces[f];
  const Eigen::Vector3d d1 = cage.points.row(c[2]) - cage.points.row(c[0]);
  const Eigen::Vector3d d2 = cage.points.row(c[3]) - cage.points.row(c[1]);
  return d1.cross(d2);
}

// Reverses a face's corners (c0 c1 c2 c3 -> c0 c3 c2 c1) with its edges.
void flip_face(Cage& cage, int f) {
  auto& c = cage.faces[f];
  std::swap(c[1], c[3]);
  auto& e = cage.face_edges[f];
  e = {e[3], e[2], e[1], e[0]};
  if (!cage.origin.empty()) std::swap(cage.origin[f].net[1], cage.origin[f].net[3]);
}

// True when face f runs edge k from corner k to corner k + 1 as `from` -> `to`.
bool runs(const Cage& cage, int f, int from, int to) {
  const auto& c = cage.faces[f];
  for (int k = 0; k < 4; ++k)
    if (c[k] == from && c[(k + 1) % 4] == to) return true;
  return false;
}

// Neighbouring faces run their shared edge in opposite senses. Returns the
// component index of each face.
std::vector<int> orient_consistently(Cage& cage) {
  const int nf = static_cast<int>(cage.faces.size());
  std::vector<int> component(nf, -1);
  int components = 0;
  for (int seed = 0; seed < nf; ++seed) {
    if (component[seed] >= 0) continue;
    component[seed] = components;
    std::queue<int> todo;
    todo.push(seed);
    while (!todo.empty()) {
      const int f = todo.front();
      todo.pop();
      for (int k = 0; k < 4; ++k) {
        const int e = cage.face_edges[f][k];
        const int a = cage.faces[f][k], b = cage.faces[f][(k + 1) % 4];
        for (int g : cage.edges[e].faces) {
          if (g < 0 || g == f) continue;
          const bool same_sense = runs(cage, g, a, b);
          if (component[g] < 0) {
            component[g] = components;
            if (same_sense) flip_face(cage, g);
            todo.push(g);
          } else if (same_sense) {
            throw bad_input("T-NURCC cage: the surface is not orientable (faces " + std::to_string(f) + " and " +
                            std::to_string(g) + ")");
          }
        }
      }
    }
    ++components;
  }
  return component;
}

// A local index of patch p from the indices along the side's tangent
// directions and the layer along its normal direction.
int patch_index(const Patch& p, Side side, int i, int j, int layer) {
  std::array<int, 3> idx{};
  const auto td = side.tangent_directions();
  idx[td[0]] = i;
  idx[td[1]] = j;
  idx[side.direction()] = layer;
  return p.index(idx[0], idx[1], idx[2]);
}

// Per face, how far its normal agrees with the direction from the patch's
// next layer of control points out to the side (positive: outward).
double outward_vote(const MultiPatch& mp, const Cage& cage, int f) {
  const CageFaceOrigin& o = cage.origin[f];
  const Patch& p = mp.patches[o.patch];
  const int d = o.side.direction();
  const int n = p.count(d);
  const int on = o.side.parameter() ? n - 1 : 0, in = o.side.parameter() ? n - 2 : 1;
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  for (const auto& ij : o.net)
    out += p.control_points.row(patch_index(p, o.side, ij[0], ij[1], on)) -
           p.control_points.row(patch_index(p, o.side, ij[0], ij[1], in));
  return face_normal(cage, f).dot(out) > 0 ? 1.0 : -1.0;
}

void orient_outward(const MultiPatch& mp, Cage& cage) {
  const std::vector<int> component = orient_consistently(cage);
  const int components = component.empty() ? 0 : *std::max_element(component.begin(), component.end()) + 1;
  std::vector<double> votes(components, 0.0);
  for (size_t f = 0; f < cage.faces.size(); ++f) votes[component[f]] += outward_vote(mp, cage, static_cast<int>(f));
  for (size_t f = 0; f < cage.faces.size(); ++f)
    if (votes[component[f]] < 0) flip_face(cage, static_cast<int>(f));
}

void mark_creases(Cage& cage, double crease_angle) {
  for (size_t e = 0; e < cage.edges.size(); ++e) {
    const auto& f = cage.edges[e].faces;
    if (f[1] < 0) continue;
    const CageFaceOrigin &a = cage.origin[f[0]], &b = cage.origin[f[1]];
    if (a.patch == b.patch && a.side == b.side) continue;
    if (angle_degrees(face_normal(cage, f[0]), face_normal(cage, f[1])) > crease_angle)
      cage.edges[e].sharpness = kInfiniteSharpness;
  }
}

}  // namespace

void build_cage_edges(Cage& cage) {
  cage.edges.clear();
  cage.face_edges.assign(cage.faces.size(), {{-1, -1, -1, -1}});
  std::unordered_map<std::uint64_t, int> index;
  for (size_t f = 0; f < cage.faces.size(); ++f) {
    const auto& c = cage.faces[f];
    for (int k = 0; k < 4; ++k) {
      const int a = c[k], b = c[(k + 1) % 4];
      if (a == b) throw bad_input("T-NURCC cage: face " + std::to_string(f) + " repeats vertex " + std::to_string(a));
      auto [it, added] = index.emplace(edge_key(a, b), static_cast<int>(cage.edges.size()));
      if (added) {
        CageEdge e;
        e.vertices = {{a, b}};
        cage.edges.push_back(e);
      }
      auto& faces = cage.edges[it->second].faces;
      if (faces[1] >= 0)
        throw bad_input("T-NURCC cage: edge (" + std::to_string(a) + ", " + std::to_string(b) +
                        ") has more than two faces");
      (faces[0] < 0 ? faces[0] : faces[1]) = static_cast<int>(f);
      cage.face_edges[f][k] = it->second;
    }
  }
}

Cage surface_cage(const MultiPatch& mp, int label, const CageOptions& options) {
  if (label < 0 || label >= static_cast<int>(mp.labels.size()))
    throw bad_input("T-NURCC cage: label " + std::to_string(label) + " does not exist");
  const std::vector<std::pair<int, Side>> sides = sides_on_surface(mp, label);
  if (sides.empty()) throw bad_input("T-NURCC cage: no patch side stands for label '" + mp.labels[label] + "'");
  const GlobalNumbering numbering = global_numbering(mp);
  std::vector<int> vertex_of_global(numbering.count, -1);
  std::vector<Eigen::Vector3d> points;
  Cage cage;
  std::vector<std::array<double, 2>> cell_intervals;  // per face: along i, along j
  for (const auto& ps : sides) {
    const int patch = ps.first;
    const Side side = ps.second;
    const Patch& p = mp.patches[patch];
    const auto td = side.tangent_directions();
    const std::vector<int> ids = side_control_points(p, side);
    const int na = p.count(td[0]), nb = p.count(td[1]);
    const std::vector<double> da = net_intervals(p.knots[td[0]], p.degrees[td[0]]);
    const std::vector<double> db = net_intervals(p.knots[td[1]], p.degrees[td[1]]);
    auto vertex = [&](int i, int j) {
      const int local = ids[i + na * j];
      int& v = vertex_of_global[numbering.global[patch][local]];
      if (v < 0) {
        v = static_cast<int>(points.size());
        points.push_back(p.control_points.row(local).transpose());
      }
      return v;
    };
    for (int j = 0; j + 1 < nb; ++j)
      for (int i = 0; i + 1 < na; ++i) {
        cage.faces.push_back({{vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1)}});
        cage.origin.push_back({patch, side, {{{{i, j}}, {{i + 1, j}}, {{i + 1, j + 1}}, {{i, j + 1}}}}});
        cell_intervals.push_back({{da[i], db[j]}});
      }
  }
  cage.points.resize(static_cast<int>(points.size()), 3);
  for (size_t v = 0; v < points.size(); ++v) cage.points.row(static_cast<int>(v)) = points[v].transpose();
  build_cage_edges(cage);
  orient_outward(mp, cage);
  // Intervals: an edge runs along i where its corners' j agree.
  std::vector<bool> assigned(cage.edges.size(), false);
  for (size_t f = 0; f < cage.faces.size(); ++f)
    for (int k = 0; k < 4; ++k) {
      const int e = cage.face_edges[f][k];
      if (assigned[e]) continue;
      const bool along_i = cage.origin[f].net[k][1] == cage.origin[f].net[(k + 1) % 4][1];
      cage.edges[e].interval = options.equal_intervals ? 1.0 : cell_intervals[f][along_i ? 0 : 1];
      assigned[e] = true;
    }
  mark_creases(cage, options.crease_angle);
  return cage;
}

std::vector<std::string> opposite_edge_violations(const Cage& cage, double tolerance) {
  std::vector<std::string> out;
  for (size_t f = 0; f < cage.faces.size(); ++f)
    for (int k = 0; k < 2; ++k) {
      const double a = cage.edges[cage.face_edges[f][k]].interval;
      const double b = cage.edges[cage.face_edges[f][k + 2]].interval;
      if (std::abs(a - b) > tolerance * std::max(std::abs(a), std::abs(b)))
        out.push_back("face " + std::to_string(f) + ": edges " + std::to_string(k) + " and " +
                      std::to_string(k + 2) + " carry intervals " + std::to_string(a) + " and " +
                      std::to_string(b));
    }
  return out;
}

std::vector<int> vertex_valences(const Cage& cage) {
  std::vector<int> valence(cage.points.rows(), 0);
  for (const auto& e : cage.edges) {
    ++valence[e.vertices[0]];
    ++valence[e.vertices[1]];
  }
  return valence;
}

bool uniform_intervals(const Cage& cage, double tolerance) {
  if (cage.edges.empty()) return true;
  const double first = cage.edges[0].interval;
  for (const auto& e : cage.edges)
    if (std::abs(e.interval - first) > tolerance * std::max(std::abs(first), std::abs(e.interval))) return false;
  return true;
}

}  // namespace igaprep::spline
