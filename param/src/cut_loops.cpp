#include "igaprep/param/cut_loops.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <cstdint>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>

#include <Eigen/Geometry>
#include <Eigen/Eigenvalues>

#include "igaprep/core/edge_key.h"
#include "igaprep/core/error.h"
#include "igaprep/core/text.h"
#include "igaprep/mesh/principal_axes.h"
#include "igaprep/core/union_find.h"

namespace igaprep::param {
namespace {

// Faces of each undirected edge.
std::unordered_map<std::uint64_t, std::vector<int>> edge_faces(const Eigen::MatrixXi& F) {
  std::unordered_map<std::uint64_t, std::vector<int>> map;
  map.reserve(static_cast<std::size_t>(F.rows()) * 2);
  for (int f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) map[edge_key(F(f, k), F(f, (k + 1) % 3))].push_back(f);
  return map;
}

const char* kAdvice =
    "give a plane ({\"midsurface\": {\"cut\": {\"plane\": {\"point\": [x,y,z], \"normal\": [x,y,z]}}}}) "
    "or loops drawn as points ({\"cut\": {\"waypoints\": [[[x,y,z], ...], ...]}}) in the case file";

double mean_edge_length(const mesh::TriMesh& m) {
  double sum = 0.0;
  for (int f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) sum += (m.V.row(m.F(f, k)) - m.V.row(m.F(f, (k + 1) % 3))).norm();
  return m.F.rows() ? sum / (3.0 * static_cast<double>(m.F.rows())) : 0.0;
}

// Splits, one pass at a time, T1 edges with both ends on loops that are no
// loop edge, at their midpoints (each face at most once per pass).
void split_chords(mesh::TriMesh& m, Eigen::VectorXi& side) {
  for (int pass = 0; pass < 16; ++pass) {
    const auto ef = edge_faces(m.F);
    std::vector<int> loop_degree(static_cast<std::size_t>(m.V.rows()), 0);
    for (const auto& [key, fs] : ef)
      if (fs.size() == 2 && side(fs[0]) != side(fs[1])) {
        ++loop_degree[key >> 32];
        ++loop_degree[key & 0xffffffffu];
      }
    std::vector<char> touched(static_cast<std::size_t>(m.F.rows()), 0);
    std::vector<std::pair<int, int>> chords;
    std::vector<std::uint64_t> keys;
    for (const auto& [key, fs] : ef) keys.push_back(key);
    std::sort(keys.begin(), keys.end());
    for (std::uint64_t key : keys) {
      const auto& fs = ef.at(key);
      const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
      if (fs.size() != 2 || side(fs[0]) != side(fs[1]) || !loop_degree[a] || !loop_degree[b]) continue;
      if (touched[fs[0]] || touched[fs[1]]) continue;
      touched[fs[0]] = touched[fs[1]] = 1;
      chords.emplace_back(a, b);
    }
    if (chords.empty()) return;
    std::vector<std::array<int, 3>> faces;
    std::vector<int> sides;
    std::unordered_map<std::uint64_t, int> mid;
    std::vector<Eigen::RowVector3d> newV;
    for (const auto& [a, b] : chords) {
      mid[edge_key(a, b)] = static_cast<int>(m.V.rows() + static_cast<Eigen::Index>(newV.size()));
      newV.push_back(0.5 * (m.V.row(a) + m.V.row(b)));
    }
    for (int f = 0; f < m.F.rows(); ++f) {
      bool split = false;
      for (int k = 0; k < 3 && !split; ++k) {
        const int a = m.F(f, k), b = m.F(f, (k + 1) % 3), c = m.F(f, (k + 2) % 3);
        auto it = mid.find(edge_key(a, b));
        if (it == mid.end()) continue;
        faces.push_back({a, it->second, c});
        faces.push_back({it->second, b, c});
        sides.push_back(side(f));
        sides.push_back(side(f));
        split = true;
      }
      if (!split) {
        faces.push_back({m.F(f, 0), m.F(f, 1), m.F(f, 2)});
        sides.push_back(side(f));
      }
    }
    const Eigen::Index nv = m.V.rows();
    m.V.conservativeResize(nv + static_cast<Eigen::Index>(newV.size()), 3);
    for (std::size_t i = 0; i < newV.size(); ++i) m.V.row(nv + static_cast<Eigen::Index>(i)) = newV[i];
    m.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
    side.resize(static_cast<Eigen::Index>(faces.size()));
    for (std::size_t f = 0; f < faces.size(); ++f) {
      for (int k = 0; k < 3; ++k) m.F(static_cast<Eigen::Index>(f), k) = faces[f][k];
      side(static_cast<Eigen::Index>(f)) = sides[f];
    }
  }
  throw internal_error("cut loops: splitting chord edges did not finish");
}

}  // namespace

int closed_surface_genus(const Eigen::MatrixXi& F) {
  const auto ef = edge_faces(F);
  std::set<int> verts(F.data(), F.data() + F.size());
  const long chi = static_cast<long>(verts.size()) - static_cast<long>(ef.size()) + static_cast<long>(F.rows());
  return static_cast<int>((2 - chi) / 2);
}

CutLoops validate_cut(const mesh::TriMesh& T1, const Eigen::VectorXi& face_side, const std::string& name,
                      const std::string& source) {
  if (face_side.size() != T1.F.rows()) throw bad_input(name + ": face labels do not match the faces");
  CutLoops cut;
  cut.source = source;
  cut.surface = T1;
  Eigen::VectorXi side = face_side;
  for (Eigen::Index f = 0; f < side.size(); ++f)
    if (side(f) != 1 && side(f) != -1) throw bad_input(name + ": face " + std::to_string(f) + " is in neither region");
  {
    const auto ef = edge_faces(T1.F);
    for (const auto& [key, fs] : ef)
      if (fs.size() != 2) throw bad_input(name + ": the surface is not closed and manifold (edge " +
                                          std::to_string(key >> 32) + "-" + std::to_string(key & 0xffffffffu) + ")");
  }
  cut.genus = closed_surface_genus(T1.F);
  const int wanted = cut.genus + 1;

  // Loop edges and their simplicity (exactly two loop edges at each loop vertex).
  auto loop_degrees = [&](const mesh::TriMesh& m, const Eigen::VectorXi& s) {
    std::vector<int> degree(static_cast<std::size_t>(m.V.rows()), 0);
    for (const auto& [key, fs] : edge_faces(m.F))
      if (s(fs[0]) != s(fs[1])) {
        ++degree[key >> 32];
        ++degree[key & 0xffffffffu];
      }
    return degree;
  };
  {
    const std::vector<int> degree = loop_degrees(T1, side);
    if (std::all_of(degree.begin(), degree.end(), [](int d) { return d == 0; }))
      throw bad_input(name + ": the cut does not cross the surface (one region only); " + kAdvice);
    for (std::size_t v = 0; v < degree.size(); ++v)
      if (degree[v] != 0 && degree[v] != 2)
        throw bad_input(name + ": the cut loops are not simple: " + std::to_string(degree[v]) +
                        " loop edges meet at vertex " + std::to_string(v) + " (loops may not touch or cross); " +
                        kAdvice);
  }
  split_chords(cut.surface, side);
  mesh::TriMesh& m = cut.surface;
  cut.face_side = side;
  const std::vector<int> degree = loop_degrees(m, side);

  // Loops from the half-edges of R+ faces on loop edges (R+ to the left).
  const auto ef = edge_faces(m.F);
  std::unordered_map<int, int> next;
  for (int f = 0; f < m.F.rows(); ++f) {
    if (side(f) != 1) continue;
    for (int k = 0; k < 3; ++k) {
      const int a = m.F(f, k), b = m.F(f, (k + 1) % 3);
      const auto& fs = ef.at(edge_key(a, b));
      if (side(fs[0]) != side(fs[1])) next[a] = b;
    }
  }
  std::vector<int> starts;
  for (const auto& [a, b] : next) starts.push_back(a);
  std::sort(starts.begin(), starts.end());
  std::set<int> done;
  for (int a0 : starts) {
    if (done.count(a0)) continue;
    std::vector<int> loop;
    int a = a0;
    do {
      loop.push_back(a);
      done.insert(a);
      auto it = next.find(a);
      if (it == next.end()) throw internal_error(name + ": a cut loop is open at vertex " + std::to_string(a));
      a = it->second;
    } while (a != a0 && loop.size() <= next.size());
    cut.loops.push_back(loop);
  }
  const int nloops = static_cast<int>(cut.loops.size());
  if (nloops != wanted)
    throw bad_input(name + ": the cut gives " + std::to_string(nloops) + (nloops == 1 ? " loop" : " loops") +
                    ", but the surface has genus " + std::to_string(cut.genus) + " and needs " +
                    std::to_string(wanted) + " (g + 1) loops that split it into two connected regions; " + kAdvice);

  // Each region connected across non-loop edges.
  UnionFind uf(static_cast<int>(m.F.rows()));
  for (const auto& [key, fs] : ef)
    if (side(fs[0]) == side(fs[1])) uf.unite(fs[0], fs[1]);
  for (int s : {1, -1}) {
    std::set<int> roots;
    for (int f = 0; f < m.F.rows(); ++f)
      if (side(f) == s) roots.insert(uf.find(f));
    if (roots.size() != 1)
      throw bad_input(name + ": the cut leaves region " + std::string(s > 0 ? "R+" : "R-") + " in " +
                      std::to_string(roots.size()) + " disconnected pieces (it must be one connected region); " +
                      kAdvice);
  }
  cut.vertex_side = Eigen::VectorXi::Zero(m.V.rows());
  for (int f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (!degree[m.F(f, k)]) cut.vertex_side(m.F(f, k)) = side(f);
  return cut;
}

namespace {

// T1 with the zero set of a vertex field (already snapped: exact zeros where
// the loops pass through vertices) inserted as edges, validated as a cut.
CutLoops insert_zero_set(const mesh::TriMesh& T1, const Eigen::VectorXd& s, const std::string& name,
                         const std::string& source) {
  mesh::TriMesh m;
  std::vector<Eigen::RowVector3d> V;
  for (Eigen::Index i = 0; i < T1.V.rows(); ++i) V.push_back(T1.V.row(i));
  std::vector<double> sv(s.data(), s.data() + s.size());
  std::unordered_map<std::uint64_t, int> cuts;
  auto cut_point = [&](int a, int b) {
    const std::uint64_t key = edge_key(a, b);
    auto it = cuts.find(key);
    if (it != cuts.end()) return it->second;
    const int lo = std::min(a, b), hi = std::max(a, b);
    const double t = sv[lo] / (sv[lo] - sv[hi]);
    V.push_back((1.0 - t) * T1.V.row(lo) + t * T1.V.row(hi));
    sv.push_back(0.0);
    const int id = static_cast<int>(V.size()) - 1;
    cuts[key] = id;
    return id;
  };
  std::vector<std::array<int, 3>> faces;
  std::vector<int> sides;
  for (int f = 0; f < T1.F.rows(); ++f) {
    std::vector<int> cyc;
    for (int k = 0; k < 3; ++k) {
      const int a = T1.F(f, k), b = T1.F(f, (k + 1) % 3);
      cyc.push_back(a);
      if (s(a) * s(b) < 0.0) cyc.push_back(cut_point(a, b));
    }
    bool any = false;
    for (int sgn : {1, -1}) {
      std::vector<int> poly;
      bool nonzero = false;
      for (int v : cyc)
        if (sgn * sv[static_cast<std::size_t>(v)] >= 0.0) {
          poly.push_back(v);
          if (sv[static_cast<std::size_t>(v)] != 0.0) nonzero = true;
        }
      if (poly.size() < 3 || !nonzero) continue;
      any = true;
      for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
        faces.push_back({poly[0], poly[i], poly[i + 1]});
        sides.push_back(sgn);
      }
    }
    if (!any)
      throw bad_input(name + ": the " + source + " contains face " + std::to_string(f) +
                      " (within the snapping tolerance); move the cut slightly");
  }
  m.V.resize(static_cast<Eigen::Index>(V.size()), 3);
  for (std::size_t i = 0; i < V.size(); ++i) m.V.row(static_cast<Eigen::Index>(i)) = V[i];
  m.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  Eigen::VectorXi side(static_cast<Eigen::Index>(faces.size()));
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (int k = 0; k < 3; ++k) m.F(static_cast<Eigen::Index>(f), k) = faces[f][k];
    side(static_cast<Eigen::Index>(f)) = sides[f];
  }
  return validate_cut(m, side, name, source);
}

}  // namespace

CutLoops cut_by_plane(const mesh::TriMesh& T1, const CutPlane& plane, const std::string& name, double snap) {
  const double nn = plane.normal.norm();
  if (!(nn > 0.0) || !plane.normal.allFinite() || !plane.point.allFinite())
    throw bad_input(name + ": the cut plane needs a finite point and a non-zero normal");
  const Eigen::Vector3d n = plane.normal / nn;
  const double size = (T1.V.colwise().maxCoeff() - T1.V.colwise().minCoeff()).norm();
  const std::string src = "plane through " + point_text(plane.point, size) + " with normal " + point_text(n, 1.0);
  Eigen::VectorXd d(T1.V.rows());
  for (Eigen::Index i = 0; i < T1.V.rows(); ++i) d(i) = n.dot(T1.V.row(i).transpose() - plane.point);
  // Where the solid is thinner across the plane than the snapping tolerance
  // (a plate a tenth of an edge thick, cut at its middle) every vertex would
  // count as on the plane: the tolerance is then cut down tenfold at a time,
  // to exact signs at last, until the plane leaves vertices on both sides.
  const double tol = snap * mean_edge_length(T1);
  for (double t : {tol, 0.1 * tol, 0.01 * tol, 0.0}) {
    Eigen::VectorXd s = d;
    for (Eigen::Index i = 0; i < s.size(); ++i)
      if (std::abs(s(i)) < t) s(i) = 0.0;
    if (s.maxCoeff() > 0.0 && s.minCoeff() < 0.0) return insert_zero_set(T1, s, name, src);
  }
  throw bad_input(name + ": the " + src + " does not cut the surface into two sides; " + kAdvice);
}

CutLoops cut_by_field(const mesh::TriMesh& T1, const Eigen::VectorXd& field, const std::string& name,
                      const std::string& source, double snap) {
  if (field.size() != T1.V.rows() || !field.allFinite())
    throw internal_error(name + ": the cut field needs one finite value per vertex");
  // A vertex is on the zero set when it is closer to it than snap * (mean edge
  // length), the distance estimated from the field's steepest incident edge.
  Eigen::VectorXd slope = Eigen::VectorXd::Zero(field.size());
  for (Eigen::Index f = 0; f < T1.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = T1.F(f, k), b = T1.F(f, (k + 1) % 3);
      const double len = (T1.V.row(a) - T1.V.row(b)).norm();
      if (!(len > 0.0)) continue;
      const double g = std::abs(field(a) - field(b)) / len;
      slope(a) = std::max(slope(a), g);
      slope(b) = std::max(slope(b), g);
    }
  const double tol = snap * mean_edge_length(T1);
  Eigen::VectorXd s = field;
  for (Eigen::Index i = 0; i < s.size(); ++i)
    if (std::abs(s(i)) < tol * slope(i)) s(i) = 0.0;
  // A face with three snapped corners would lie on the zero set: its corner
  // farthest from it keeps its value.
  for (Eigen::Index f = 0; f < T1.F.rows(); ++f) {
    if (s(T1.F(f, 0)) != 0.0 || s(T1.F(f, 1)) != 0.0 || s(T1.F(f, 2)) != 0.0) continue;
    int far = T1.F(f, 0);
    for (int k = 1; k < 3; ++k)
      if (std::abs(field(T1.F(f, k))) > std::abs(field(far))) far = T1.F(f, k);
    s(far) = field(far);
  }
  if (s.maxCoeff() <= 0.0 || s.minCoeff() >= 0.0)
    throw bad_input(name + ": the " + source + " does not cut the surface into two sides; " + kAdvice);
  return insert_zero_set(T1, s, name, source);
}

CutLoops cut_by_loops(const mesh::TriMesh& T1, const std::vector<std::vector<int>>& loops, const std::string& name) {
  if (loops.empty()) throw bad_input(name + ": no cut loops given");
  const auto ef = edge_faces(T1.F);
  std::set<std::uint64_t> loop_edges;
  std::map<int, std::size_t> loop_of;  // vertex -> the loop that passed it
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const auto& loop = loops[l];
    const std::string where = name + ": cut loop " + std::to_string(l);
    if (loop.size() < 3) throw bad_input(where + " has fewer than 3 vertices");
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const int a = loop[i], b = loop[(i + 1) % loop.size()];
      if (a < 0 || a >= T1.V.rows())
        throw bad_input(where + ": vertex index " + std::to_string(a) + " is out of range (the surface has " +
                        std::to_string(T1.V.rows()) + " vertices)");
      if (const auto [it, first] = loop_of.emplace(a, l); !first) {
        std::ostringstream at;
        at << "vertex " << a << " (" << T1.V.row(a) << ")";
        throw bad_input(it->second == l ? where + " is not simple: it passes " + at.str() + " twice"
                                        : name + ": cut loops " + std::to_string(it->second) + " and " +
                                              std::to_string(l) + " touch at " + at.str() +
                                              " (loops may not cross or touch: move them apart there)");
      }
      if (b < 0 || b >= T1.V.rows() || !ef.count(edge_key(a, b)))
        throw bad_input(where + ": vertices " + std::to_string(a) + " and " + std::to_string(b) +
                        " are not joined by an edge of the surface (a loop is a closed path along edges)");
      loop_edges.insert(edge_key(a, b));
    }
  }
  UnionFind uf(static_cast<int>(T1.F.rows()));
  for (const auto& [key, fs] : ef)
    if (!loop_edges.count(key) && fs.size() == 2) uf.unite(fs[0], fs[1]);
  std::map<int, int> regions;
  for (int f = 0; f < T1.F.rows(); ++f) regions.emplace(uf.find(f), static_cast<int>(regions.size()));
  if (regions.size() != 2)
    throw bad_input(name + ": the cut loops split the surface into " + std::to_string(regions.size()) +
                    " regions, but they must split it into exactly two connected regions R+ and R-; " + kAdvice);
  // R+ is on the left of loops[0][0] -> loops[0][1].
  int plus_root = -1;
  for (int f = 0; f < T1.F.rows() && plus_root < 0; ++f)
    for (int k = 0; k < 3; ++k)
      if (T1.F(f, k) == loops[0][0] && T1.F(f, (k + 1) % 3) == loops[0][1]) plus_root = uf.find(f);
  if (plus_root < 0) throw bad_input(name + ": cut loop 0 does not follow the surface's edges");
  Eigen::VectorXi side(T1.F.rows());
  for (int f = 0; f < T1.F.rows(); ++f) side(f) = uf.find(f) == plus_root ? 1 : -1;
  for (std::uint64_t key : loop_edges) {
    const auto& fs = ef.at(key);
    if (side(fs[0]) == side(fs[1]))
      throw bad_input(name + ": the loop edge " + std::to_string(key >> 32) + "-" + std::to_string(key & 0xffffffffu) +
                      " has the same region on both sides (every loop must separate R+ from R-); " + kAdvice);
  }
  return validate_cut(T1, side, name, "explicit loops");
}

std::vector<CutPlane> automatic_cut_planes(const mesh::TriMesh& T1) {
  const mesh::PrincipalAxes axes = mesh::surface_principal_axes(T1);
  const Eigen::Vector3d c = axes.centroid;
  std::vector<CutPlane> planes;
  for (int k = 0; k < 3; ++k) planes.push_back({c, axes.axes.col(k)});
  const Eigen::Vector3d n0 = planes[0].normal;
  double lo = 0.0, hi = 0.0;
  for (Eigen::Index i = 0; i < T1.V.rows(); ++i) {
    const double d = n0.dot(T1.V.row(i).transpose() - c);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  planes.push_back({c + 0.1 * hi * n0, n0});
  planes.push_back({c + 0.1 * lo * n0, n0});
  return planes;
}

CutLoops cut_automatic(const mesh::TriMesh& T1, const std::string& name) {
  std::string reasons;
  for (const CutPlane& p : automatic_cut_planes(T1)) {
    try {
      CutLoops cut = cut_by_plane(T1, p, name);
      cut.source = "automatic: " + cut.source;
      return cut;
    } catch (const Error& e) {
      if (e.kind() != ErrorKind::BadInput) throw;
      reasons += std::string("\n  ") + e.what();
    }
  }
  throw bad_input(name + ": no automatic cut plane gives valid loops:" + reasons);
}

}  // namespace igaprep::param

namespace igaprep::param {
namespace {

// A refusal's kind: its first clause with every number replaced by '#',
// every parenthesis by "(...)" and runs of spaces by one.
std::string refusal_kind(const std::string& message) {
  const std::string clause = message.substr(0, message.find(';'));
  std::string kind;
  for (std::size_t i = 0; i < clause.size(); ++i) {
    const char ch = clause[i];
    if (ch == '(') {
      kind += "(...)";
      while (i + 1 < clause.size() && clause[i] != ')') ++i;
    } else if (std::isdigit(static_cast<unsigned char>(ch))) {
      kind += '#';
      while (i + 1 < clause.size() && std::strchr("0123456789.e+-", clause[i + 1]) != nullptr) ++i;
    } else if (ch != ' ' || kind.empty() || kind.back() != ' ') {
      kind += ch;
    }
  }
  return kind;
}

std::vector<std::string> summarise(const std::map<std::string, int>& kinds) {
  std::vector<std::string> out;
  for (const auto& [kind, count] : kinds) out.push_back(std::to_string(count) + " x " + kind);
  return out;
}

}  // namespace

double loops_length(const CutLoops& cut) {
  double length = 0.0;
  for (const auto& loop : cut.loops)
    for (std::size_t i = 0; i < loop.size(); ++i)
      length += (cut.surface.V.row(loop[i]) - cut.surface.V.row(loop[(i + 1) % loop.size()])).norm();
  return length;
}

PlaneFamily cut_plane_family(const mesh::TriMesh& T1, int normals, int offsets, const std::string& name) {
  PlaneFamily family;
  const Eigen::Vector3d c = T1.V.colwise().mean().transpose();
  std::map<std::string, int> kinds;
  std::vector<std::pair<double, CutLoops>> found;
  for (int i = 0; i < normals; ++i) {
    const double z = 1.0 - (i + 0.5) / normals, r = std::sqrt(1.0 - z * z), phi = 2.399963229728653 * i;
    const Eigen::Vector3d n(r * std::cos(phi), r * std::sin(phi), z);
    const Eigen::VectorXd d = (T1.V.rowwise() - c.transpose()) * n;
    for (int k = 1; k <= offsets; ++k) {
      const double t = d.minCoeff() + (d.maxCoeff() - d.minCoeff()) * k / (offsets + 1.0);
      ++family.tried;
      try {
        CutLoops cut = cut_by_plane(T1, {c + t * n, n}, name);
        cut.source = "plane family: " + cut.source;
        found.emplace_back(loops_length(cut), std::move(cut));
      } catch (const Error& e) {
        if (e.kind() != ErrorKind::BadInput) throw;
        ++kinds[refusal_kind(e.what())];
      }
    }
  }
  std::stable_sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (auto& f : found) family.valid.push_back(std::move(f.second));
  family.refusals = summarise(kinds);
  return family;
}

}  // namespace igaprep::param
