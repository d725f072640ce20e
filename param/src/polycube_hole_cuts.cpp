// Cuts from the holes' corners (polycube_hole_cuts.h).
#include "polycube_hole_cuts.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <limits>

#include "edge_graph.h"
#include "igaprep/param/polycube_2d.h"

namespace igaprep::param::detail {
namespace {

using Vec2 = Eigen::Vector2d;

// A cut leaves a hole corner along `dir`; where its end must snap to a
// vertex, it snaps to the `slant` side, away from the hole, so that the part
// whose side the cut continues stays convex.
struct CornerRay {
  Vec2 origin, dir, slant;
};

// The pinwheel: bottom-left down, bottom-right right, top-right up, top-left left.
std::array<CornerRay, 4> corner_rays(const Eigen::Vector4d& box) {
  return {CornerRay{{box(0), box(1)}, {0, -1}, {-1, 0}}, CornerRay{{box(2), box(1)}, {1, 0}, {0, -1}},
          CornerRay{{box(2), box(3)}, {0, 1}, {1, 0}}, CornerRay{{box(0), box(3)}, {-1, 0}, {0, 1}}};
}

struct Hit {
  double t = std::numeric_limits<double>::infinity();
  std::vector<int> candidates;  // the vertices the cut may end on
};

// 2D cross product.
double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 e = b - a;
  const double len2 = e.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(e) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * e)).norm();
}

// A bijective map of the sheet with every hole filled by a fan round its
// centroid, the outer loop fixed where the domain puts it: a
// convex-combination (mean-value) map of a disk onto a convex region
// (Floater). The holes come out as blobs about where the domain's rectangles
// are, and the map does not fold, so paths drawn along it part the sheet as
// the lines part the domain.
Eigen::MatrixXd filled_guide(const mesh::TriMesh& sheet, const Polycube2D& pc, const Eigen::MatrixXd& buv) {
  mesh::TriMesh filled = sheet;
  std::vector<Eigen::RowVector3d> centres;
  std::vector<std::array<int, 3>> fans;
  for (const PolycubeLoop& L : pc.loops) {
    if (L.outer) continue;
    const int c = static_cast<int>(sheet.V.rows() + static_cast<Eigen::Index>(centres.size()));
    Eigen::RowVector3d centre = Eigen::RowVector3d::Zero();
    for (int v : L.vertices) centre += sheet.V.row(v);
    centres.push_back(centre / static_cast<double>(L.vertices.size()));
    // The sheet runs each boundary edge a -> b (sheet on the left); the fan runs it b -> a.
    for (std::size_t i = 0; i < L.vertices.size(); ++i)
      fans.push_back({L.vertices[(i + 1) % L.vertices.size()], L.vertices[i], c});
  }
  filled.V.conservativeResize(sheet.V.rows() + static_cast<Eigen::Index>(centres.size()), 3);
  for (std::size_t i = 0; i < centres.size(); ++i) filled.V.row(sheet.V.rows() + static_cast<Eigen::Index>(i)) = centres[i];
  filled.F.conservativeResize(sheet.F.rows() + static_cast<Eigen::Index>(fans.size()), 3);
  for (std::size_t i = 0; i < fans.size(); ++i)
    filled.F.row(sheet.F.rows() + static_cast<Eigen::Index>(i)) << fans[i][0], fans[i][1], fans[i][2];
  std::vector<char> fixed(static_cast<std::size_t>(filled.V.rows()), 0);
  Eigen::MatrixXd fixed_uv = Eigen::MatrixXd::Zero(filled.V.rows(), 2);
  for (const PolycubeLoop& L : pc.loops)
    if (L.outer)
      for (int v : L.vertices) fixed[static_cast<std::size_t>(v)] = 1, fixed_uv.row(v) = buv.row(v);
  return harmonic_uv(filled, fixed_uv, fixed, UvWeights::MeanValue).topRows(sheet.V.rows());
}

// Tried ends per cut: the nearest few to the hit point.
constexpr std::size_t kEndsTried = 6;

class CutFinder {
 public:
  CutFinder(const mesh::TriMesh& sheet, Polycube2D& pc, const Eigen::MatrixXd& buv, const std::vector<char>& fixed)
      : sheet_(sheet), pc_(pc), guide_(filled_guide(sheet, pc, buv)), uv_(buv), blocked_(fixed), graph_(edge_graph(sheet)) {
    scale_ = pc.domain.width + pc.domain.height;
  }

  // The cuts from the hole's four corners; a corner whose cut finds no path
  // (the parts of the sheet are not those of the domain there) is left.
  void cut(std::size_t hole) {
    const PolycubeLoop& loop = pc_.loops.at(static_cast<std::size_t>(pc_.domain.hole_loop.at(hole)));
    for (const CornerRay& ray : corner_rays(pc_.domain.holes[hole])) {
      const int from = nearest(loop.vertices, ray.origin);
      const Hit hit = first_hit(ray, hole);
      std::vector<int> path;
      for (int to : end_vertices(hit, ray)) {
        if (to == from) continue;
        const ShortestPaths paths = shortest_paths(guided_graph(guide(from), guide(to)), from, to, &blocked_);
        if (paths.prev[static_cast<std::size_t>(to)] < 0) continue;
        path = path_to(paths, to);
        break;
      }
      if (path.empty()) continue;
      place(path);
      pc_.hole_cuts.push_back(std::move(path));
    }
  }

 private:
  // The sheet's edges weighed by their length in the guide plus their
  // midpoints' distance from the segment a -> b there: the path runs
  // straight in a map that cannot fold, so the paths part the sheet as
  // straight lines part a plane.
  EdgeGraph guided_graph(const Vec2& a, const Vec2& b) const {
    EdgeGraph g = graph_;
    for (std::size_t v = 0; v < g.size(); ++v)
      for (auto& [w, weight] : g[v]) {
        const Vec2 p = guide(static_cast<int>(v)), q = guide(w);
        weight = (p - q).norm() + distance_to_segment(0.5 * (p + q), a, b);
      }
    return g;
  }

  Vec2 uv(int v) const { return uv_.row(v).transpose(); }
  Vec2 guide(int v) const { return guide_.row(v).transpose(); }

  int nearest(const std::vector<int>& vertices, const Vec2& p) const {
    int best = -1;
    double best_d = std::numeric_limits<double>::infinity();
    for (int v : vertices)
      if (const double d = (uv(v) - p).squaredNorm(); d < best_d) best = v, best_d = d;
    return best;
  }

  // The vertices of a loop on the line through the hit, across the ray.
  std::vector<int> on_line(const std::vector<int>& vertices, const CornerRay& ray, const Vec2& q) const {
    std::vector<int> out;
    for (int v : vertices)
      if (std::abs((uv(v) - q).dot(ray.dir)) < 1e-9 * scale_) out.push_back(v);
    return out;
  }

  void consider(Hit& best, double t, std::vector<int> candidates) const {
    if (t > 1e-12 * scale_ && t < best.t && !candidates.empty()) best = {t, std::move(candidates)};
  }

  Hit first_hit(const CornerRay& ray, std::size_t own) const {
    Hit best;
    const Vec2& o = ray.origin;
    const Vec2& d = ray.dir;
    const RectilinearDomain& dom = pc_.domain;
    // The outer rectangle.
    const double t_out = d.x() > 0 ? dom.width - o.x() : d.x() < 0 ? o.x() : d.y() > 0 ? dom.height - o.y() : o.y();
    for (const PolycubeLoop& L : pc_.loops)
      if (L.outer) consider(best, t_out, on_line(L.vertices, ray, o + t_out * d));
    // Other holes: the side facing the ray, when the ray meets it.
    const double tol = 1e-9 * scale_;
    for (std::size_t h = 0; h < dom.holes.size(); ++h) {
      if (h == own) continue;
      const Eigen::Vector4d& b = dom.holes[h];
      const bool across_u = o.x() >= b(0) - tol && o.x() <= b(2) + tol, across_v = o.y() >= b(1) - tol && o.y() <= b(3) + tol;
      double t = -1.0;
      if (d.y() < 0 && across_u) t = o.y() - b(3);
      if (d.y() > 0 && across_u) t = b(1) - o.y();
      if (d.x() > 0 && across_v) t = b(0) - o.x();
      if (d.x() < 0 && across_v) t = o.x() - b(2);
      if (t > 0)
        consider(best, t, on_line(pc_.loops.at(static_cast<std::size_t>(dom.hole_loop[h])).vertices, ray, o + t * d));
    }
    // Earlier cuts, straight in (u, v) between their ends.
    for (const std::vector<int>& path : pc_.hole_cuts) {
      const Vec2 a = uv(path.front()), e = uv(path.back()) - a;
      const double denom = cross(d, e);
      if (std::abs(denom) < 1e-14 * scale_) continue;
      const double t = cross(a - o, e) / denom, s = cross(a - o, d) / denom;
      if (s >= 0.0 && s <= 1.0) consider(best, t, path);
    }
    return best;
  }

  // The candidates nearest the hit point, those on the slant side first.
  std::vector<int> end_vertices(const Hit& hit, const CornerRay& ray) const {
    const Vec2 q = ray.origin + hit.t * ray.dir;
    std::vector<int> ends = hit.candidates;
    auto key = [&](int v) {
      return std::pair{(uv(v) - q).dot(ray.slant) < -1e-12 * scale_, (uv(v) - q).squaredNorm()};
    };
    std::sort(ends.begin(), ends.end(), [&](int a, int b) { return key(a) < key(b); });
    if (ends.size() > kEndsTried) ends.resize(kEndsTried);
    return ends;
  }

  void place(const std::vector<int>& path) {
    spread_on_segment(sheet_, path, uv(path.front()), uv(path.back()), uv_, blocked_);
  }

  const mesh::TriMesh& sheet_;
  Polycube2D& pc_;
  const Eigen::MatrixXd guide_;  // filled_guide
  Eigen::MatrixXd uv_;
  std::vector<char> blocked_;
  const EdgeGraph graph_;
  double scale_ = 1.0;
};

}  // namespace

void spread_on_segment(const mesh::TriMesh& sheet, const std::vector<int>& path, const Eigen::Vector2d& a,
                       const Eigen::Vector2d& b, Eigen::MatrixXd& uv, std::vector<char>& fixed) {
  std::vector<double> s(path.size(), 0.0);
  for (std::size_t i = 1; i < path.size(); ++i) s[i] = s[i - 1] + (sheet.V.row(path[i]) - sheet.V.row(path[i - 1])).norm();
  for (std::size_t i = 0; i < path.size(); ++i) {
    const double t = s.back() > 0.0 ? s[i] / s.back() : 0.0;
    uv.row(path[i]) = ((1.0 - t) * a + t * b).transpose();
    fixed[static_cast<std::size_t>(path[i])] = 1;
  }
}

}  // namespace igaprep::param::detail

namespace igaprep::param {

bool find_hole_cuts(const mesh::TriMesh& sheet, Polycube2D& pc) {
  pc.hole_cuts.clear();
  if (pc.domain.holes.empty() || !pc.domain.arms.empty()) return false;
  pc.segments = boundary_segments(pc.loops, pc.domain);
  std::vector<char> fixed;
  const Eigen::MatrixXd buv = boundary_uv(sheet, pc.segments, fixed);
  detail::CutFinder finder(sheet, pc, buv, fixed);
  for (std::size_t h = 0; h < pc.domain.holes.size(); ++h) finder.cut(h);
  return !pc.hole_cuts.empty();
}

void fix_hole_cuts(const mesh::TriMesh& sheet, const Polycube2D& pc, Eigen::MatrixXd& uv, std::vector<char>& fixed) {
  for (const std::vector<int>& path : pc.hole_cuts) {
    const Eigen::Vector2d a = uv.row(path.front()).transpose(), b = uv.row(path.back()).transpose();
    detail::spread_on_segment(sheet, path, a, b, uv, fixed);
  }
}

}  // namespace igaprep::param
