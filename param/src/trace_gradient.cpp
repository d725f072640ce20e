#include "igaprep/param/trace_gradient.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "cell_geometry.h"
#include "igaprep/core/error.h"
#include "igaprep/param/gradient.h"

namespace igaprep::param {

const char* to_string(TraceStatus status) {
  switch (status) {
    case TraceStatus::Reached: return "reached";
    case TraceStatus::HitBoundary: return "hit boundary";
    case TraceStatus::StepBudget: return "step budget exhausted";
    case TraceStatus::Stalled: return "stalled";
  }
  return "?";
}

GradientTracer::GradientTracer(const Eigen::MatrixXd& V, const Eigen::MatrixXi& cells, const TetTopology& topology,
                               const Eigen::VectorXd& u)
    : V_(V), C_(cells), topo_(topology), u_(u) {
  if (cells.cols() != topology.cell_size || topology.neighbor.rows() != cells.rows())
    throw bad_input("GradientTracer: the topology was built for other cells");
  vertex_gradient_ = vertex_gradients(V, cells, u);
  const double range = u.size() ? u.maxCoeff() - u.minCoeff() : 0.0;
  const double diag = V.rows() ? (V.colwise().maxCoeff() - V.colwise().minCoeff()).norm() : 0.0;
  grad_scale_ = (range > 0 && diag > 0) ? range / diag : 1.0;
  diag_ = diag > 0 ? diag : 1.0;
}

namespace {

constexpr double kOnFacet = 1e-12;   // barycentric coordinate counted as zero
constexpr double kMinStep = 1e-12;   // smallest barycentric change that counts as a step

template <int K>
using VecK = Eigen::Matrix<double, K, 1>;
template <int K>
using GradPhi = Eigen::Matrix<double, K, 3>;

template <int K>
struct Step {
  bool ok = false;
  double s = 0.0;  // segment parameter: end = start + s * d
  int exit = -1;   // local facet left at the end
  VecK<K> db = VecK<K>::Zero();  // d(bary)/ds
  double length = 0.0;
};

// Straight segment from bary b along d inside a cell with barycentric gradients gp.
template <int K>
Step<K> step_in(const GradPhi<K>& gp, const VecK<K>& b, const Eigen::Vector3d& d) {
  Step<K> st;
  st.db = gp * d;
  const double scale = st.db.cwiseAbs().maxCoeff();
  if (!(scale > 0)) return st;
  st.s = std::numeric_limits<double>::infinity();
  for (int i = 0; i < K; ++i)
    if (st.db(i) < -1e-12 * scale) {
      const double si = std::max(b(i), 0.0) / -st.db(i);
      if (si < st.s) {
        st.s = si;
        st.exit = i;
      }
    }
  st.ok = st.exit >= 0 && st.s * scale > kMinStep;
  st.length = st.ok ? st.s * d.norm() : 0.0;
  return st;
}

// Barycentric coordinates in cell x of the point with coordinates b in cell c.
template <int K>
VecK<K> transfer(const Eigen::MatrixXi& C, int c, const VecK<K>& b, int x) {
  VecK<K> bx = VecK<K>::Zero();
  for (int k = 0; k < K; ++k)
    for (int l = 0; l < K; ++l)
      if (C(x, k) == C(c, l)) bx(k) = b(l);
  return bx;
}

template <int K>
void clean(VecK<K>& b) {
  for (int k = 0; k < K; ++k)
    if (b(k) < kOnFacet) b(k) = 0.0;
  b /= b.sum();
}

// A marked facet (or the point where the trace stops) in a cell.
template <int K>
struct Spot {
  int cell = -1;
  VecK<K> b = VecK<K>::Zero();
  int facet = -1;
};

// The best way on from a point where the cell's own direction leaves at once.
template <int K>
struct Candidate {
  int cell = -1;
  double length = 0.0, cosine = -1.0;
  VecK<K> b = VecK<K>::Zero();
  Step<K> step;
};

// The mesh and field a trace walks on (GradientTracer's data).
struct TraceField {
  const Eigen::MatrixXd& V;
  const Eigen::MatrixXi& C;
  const TetTopology& topo;
  const Eigen::VectorXd& u;
  const Eigen::MatrixXd& vertex_gradient;
  double grad_scale;  // field range / bounding-box diagonal
  double diag;        // bounding-box diagonal
};

// One trace: the walk from cell to cell, the path so far and the step count.
template <int K>
class TraceWalk {
 public:
  TraceWalk(const TraceField& field, const TraceTarget& target, const TraceOptions& opt)
      : f_(field),
        target_(target),
        opt_(opt),
        sign_(opt.descend ? -1.0 : 1.0),
        tiny_(opt.tiny_gradient * field.grad_scale),
        have_marks_(!target.marked.empty()) {}

  TraceResult run(int c, const Eigen::Vector4d& bary_in);

 private:
  VecK<K> start_coordinates(int c, const Eigen::Vector4d& bary_in) const;
  Step<K> own_step(int c, const VecK<K>& b) const;
  bool find_way_on(int c, const VecK<K>& b, Candidate<K>& best);
  void try_pass(int pass, int y, const VecK<K>& by, const GradPhi<K>& gy, const Eigen::Vector3d& g,
                Candidate<K>& best) const;
  void consider(int y, const VecK<K>& by, const GradPhi<K>& gy, const Eigen::Vector3d& g, const Eigen::Vector3d& dy,
                Candidate<K>& best) const;
  TraceResult end_where_stuck(int c, const VecK<K>& b);
  bool stop_at_iso(int c, VecK<K>& b, const Step<K>& st, const VecK<K>& delta, int& facet) const;
  bool marked_here(int x, const VecK<K>& bx, Spot<K>& spot);
  void collect_star(int x, const VecK<K>& bx);
  TraceResult finish(TraceStatus st, int x, const VecK<K>& bx, int facet);

  Eigen::Vector3d position(int x, const VecK<K>& bx) const {
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (int k = 0; k < K; ++k) p += bx(k) * detail::vrow(f_.V, f_.C(x, k));
    return p;
  }
  double value(int x, const VecK<K>& bx) const {
    double v = 0.0;
    for (int k = 0; k < K; ++k) v += bx(k) * f_.u(f_.C(x, k));
    return v;
  }
  bool grad_phi(int x, GradPhi<K>& gp) const { return detail::cell_grad_phi(f_.V, f_.C, x, gp) != 0.0; }
  Eigen::Vector3d field_grad(int x, const GradPhi<K>& gp) const {
    Eigen::Vector3d g = Eigen::Vector3d::Zero();
    for (int k = 0; k < K; ++k) g += f_.u(f_.C(x, k)) * gp.row(k).transpose();
    return g;
  }
  Eigen::Vector3d averaged_dir(int x, const VecK<K>& bx, const GradPhi<K>& gp) const;

  const TraceField& f_;
  const TraceTarget& target_;
  const TraceOptions& opt_;
  const double sign_;
  const double tiny_;
  const bool have_marks_;
  std::vector<Eigen::Vector3d> path_;
  std::vector<int> star_;
  int steps_ = 0;
};

// Clamped to >= 0 and normalized; bad_input for a bad cell or coordinates.
template <int K>
VecK<K> TraceWalk<K>::start_coordinates(int c, const Eigen::Vector4d& bary_in) const {
  if (have_marks_ && target_.marked.size() != static_cast<size_t>(f_.C.rows()) * K)
    throw bad_input("trace: marked facets were built for another mesh");
  if (c < 0 || c >= f_.C.rows()) throw bad_input("trace: start cell " + std::to_string(c) + " out of range");
  VecK<K> b = bary_in.head<K>();
  if (!b.allFinite()) throw bad_input("trace: start coordinates are not finite");
  b = b.cwiseMax(0.0);
  if (!(b.sum() > 0)) throw bad_input("trace: start coordinates are all zero");
  clean<K>(b);
  return b;
}

// The continuous (vertex-averaged) gradient at bx, in the plane of a triangle.
template <int K>
Eigen::Vector3d TraceWalk<K>::averaged_dir(int x, const VecK<K>& bx, const GradPhi<K>& gp) const {
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  for (int k = 0; k < K; ++k) d += bx(k) * f_.vertex_gradient.row(f_.C(x, k)).transpose();
  if constexpr (K == 3) {
    // Keep only the in-plane part: the span of the barycentric gradients.
    const Eigen::Vector3d n = gp.row(1).transpose().cross(gp.row(2).transpose());
    if (n.squaredNorm() > 0) d -= d.dot(n) / n.squaredNorm() * n;
  }
  return Eigen::Vector3d(sign_ * d);
}

template <int K>
TraceResult TraceWalk<K>::finish(TraceStatus st, int x, const VecK<K>& bx, int facet) {
  TraceResult res;
  res.status = st;
  res.cell = x;
  res.facet = facet;
  res.face = (facet >= 0 && have_marks_) ? target_.marked[static_cast<size_t>(x) * K + facet] : -1;
  res.bary.setZero();
  res.bary.head<K>() = bx;
  res.end = position(x, bx);
  res.value = value(x, bx);
  res.steps = steps_;
  if (path_.empty() || (path_.back() - res.end).norm() > 0) path_.push_back(res.end);
  res.path.resize(static_cast<Eigen::Index>(path_.size()), 3);
  for (size_t i = 0; i < path_.size(); ++i) res.path.row(static_cast<Eigen::Index>(i)) = path_[i].transpose();
  return res;
}

// Cells holding the point (x, bx): those around the smallest simplex that carries it.
template <int K>
void TraceWalk<K>::collect_star(int x, const VecK<K>& bx) {
  star_.clear();
  int carrier[K], nc = 0;
  for (int k = 0; k < K; ++k)
    if (bx(k) > kOnFacet) carrier[nc++] = f_.C(x, k);
  const int v0 = carrier[0];
  for (int s = f_.topo.vertex_cells_start[v0]; s < f_.topo.vertex_cells_start[v0 + 1]; ++s) {
    const int y = f_.topo.vertex_cells[s];
    bool all = true;
    for (int j = 1; j < nc && all; ++j) {
      bool in = false;
      for (int k = 0; k < K; ++k) in = in || f_.C(y, k) == carrier[j];
      all = in;
    }
    if (all) star_.push_back(y);
  }
}

// A marked facet through the point, in any cell around it.
template <int K>
bool TraceWalk<K>::marked_here(int x, const VecK<K>& bx, Spot<K>& spot) {
  if (!have_marks_) return false;
  int zeros = 0;
  for (int k = 0; k < K; ++k) zeros += bx(k) <= kOnFacet;
  if (zeros == 0) return false;
  if (zeros == 1) {
    for (int k = 0; k < K; ++k)
      if (bx(k) <= kOnFacet && target_.marked[static_cast<size_t>(x) * K + k] >= 0) {
        spot = {x, bx, k};
        return true;
      }
    return false;
  }
  collect_star(x, bx);
  for (int y : star_) {
    const VecK<K> by = transfer<K>(f_.C, x, bx, y);
    for (int k = 0; k < K; ++k)
      if (by(k) <= kOnFacet && target_.marked[static_cast<size_t>(y) * K + k] >= 0) {
        spot = {y, by, k};
        return true;
      }
  }
  return false;
}

// The cell's own (piecewise-constant) gradient, or the averaged one where it
// is tiny; not ok when that direction leaves the cell at once.
template <int K>
Step<K> TraceWalk<K>::own_step(int c, const VecK<K>& b) const {
  Step<K> st;
  GradPhi<K> gp;
  if (grad_phi(c, gp)) {
    const Eigen::Vector3d g = field_grad(c, gp);
    const Eigen::Vector3d d = g.norm() > tiny_ ? Eigen::Vector3d(sign_ * g) : averaged_dir(c, b, gp);
    if (d.norm() > tiny_) st = step_in<K>(gp, b, d);
  }
  return st;
}

// A segment of positive length from cell y along dy, if it lets the field
// grow in y (not shrink, where y's gradient is tiny): the field is then
// monotone along the whole trace and it cannot cycle. Kept when steeper
// (closer to y's gradient) than the best so far, or as steep and longer.
template <int K>
void TraceWalk<K>::consider(int y, const VecK<K>& by, const GradPhi<K>& gy, const Eigen::Vector3d& g,
                            const Eigen::Vector3d& dy, Candidate<K>& best) const {
  if (!(dy.norm() > tiny_)) return;
  const double rate = dy.dot(sign_ * g);
  if (!(rate > 0 || (g.norm() <= tiny_ && rate >= 0))) return;
  const Step<K> sy = step_in<K>(gy, by, dy);
  if (!sy.ok) return;
  const double cosine = g.norm() > tiny_ ? rate / (dy.norm() * g.norm()) : 0.0;
  if (best.cell < 0 || cosine > best.cosine + 1e-9 || (cosine > best.cosine - 1e-9 && sy.length > best.length))
    best = {y, sy.length, cosine, by, sy};
}

// The candidate directions of one pass in cell y: 0 its own gradient, 1 the
// averaged gradient, 2 sliding within the facets through the point (a valley
// of the piecewise-constant field, or the boundary), 3 (tets) along the edges
// through the point, where facet sliding is blocked.
template <int K>
void TraceWalk<K>::try_pass(int pass, int y, const VecK<K>& by, const GradPhi<K>& gy, const Eigen::Vector3d& g,
                            Candidate<K>& best) const {
  if (pass == 0) {
    if (g.norm() > tiny_) consider(y, by, gy, g, sign_ * g, best);
    return;
  }
  if (pass == 1) {
    consider(y, by, gy, g, averaged_dir(y, by, gy), best);
    return;
  }
  const Eigen::Vector3d dirs[2] = {Eigen::Vector3d(sign_ * g), averaged_dir(y, by, gy)};
  for (int k = 0; k < K; ++k) {
    if (by(k) > kOnFacet) continue;
    if (f_.topo.neighbor(y, k) < 0 && !opt_.slide_on_boundary) continue;
    const Eigen::Vector3d nk = gy.row(k).transpose().normalized();
    if (pass == 2)  // within a facet
      for (const Eigen::Vector3d& dy : dirs) consider(y, by, gy, g, dy - dy.dot(nk) * nk, best);
    if constexpr (K == 4) {  // along an edge
      if (pass != 3) continue;
      for (int l = k + 1; l < K; ++l) {
        if (by(l) > kOnFacet) continue;
        if (f_.topo.neighbor(y, l) < 0 && !opt_.slide_on_boundary) continue;
        const Eigen::Vector3d e = nk.cross(gy.row(l).transpose()).normalized();
        for (const Eigen::Vector3d& dy : dirs) consider(y, by, gy, g, dy.dot(e) * e, best);
      }
    }
  }
}

// On a facet, edge or vertex: every cell around the point, pass by pass,
// for one that lets the field grow along a segment of positive length.
template <int K>
bool TraceWalk<K>::find_way_on(int c, const VecK<K>& b, Candidate<K>& best) {
  collect_star(c, b);
  GradPhi<K> gy;
  for (int pass = 0; pass < 4 && best.cell < 0; ++pass) {
    for (int y : star_) {
      if (!grad_phi(y, gy)) continue;
      const VecK<K> by = transfer<K>(f_.C, c, b, y);
      try_pass(pass, y, by, gy, field_grad(y, gy), best);
    }
  }
  return best.cell >= 0;
}

// Nothing goes on: the boundary, or a critical point of the field.
template <int K>
TraceResult TraceWalk<K>::end_where_stuck(int c, const VecK<K>& b) {
  for (int y : star_) {
    const VecK<K> by = transfer<K>(f_.C, c, b, y);
    for (int k = 0; k < K; ++k)
      if (by(k) <= kOnFacet && f_.topo.neighbor(y, k) < 0) return finish(TraceStatus::HitBoundary, y, by, k);
  }
  return finish(TraceStatus::Stalled, c, b, -1);
}

// Whether the segment from b by delta reaches the target iso-value; if so b
// moves to where it does and facet is a facet it lies on (or -1).
template <int K>
bool TraceWalk<K>::stop_at_iso(int c, VecK<K>& b, const Step<K>& st, const VecK<K>& delta, int& facet) const {
  const double v0 = value(c, b);
  double dv = 0.0;
  for (int k = 0; k < K; ++k) dv += delta(k) * f_.u(f_.C(c, k));
  if (!(sign_ * (v0 + dv - target_.iso) >= 0 && dv != 0.0)) return false;
  const double t = std::clamp((target_.iso - v0) / dv, 0.0, 1.0);
  b += t * delta;
  if (t >= 1.0) b(st.exit) = 0.0;
  clean<K>(b);
  facet = -1;
  for (int k = 0; k < K; ++k)
    if (b(k) == 0.0) facet = k;
  return true;
}

template <int K>
TraceResult TraceWalk<K>::run(int c, const Eigen::Vector4d& bary_in) {
  VecK<K> b = start_coordinates(c, bary_in);
  path_.reserve(64);
  path_.push_back(position(c, b));
  if (target_.use_iso && sign_ * (value(c, b) - target_.iso) >= 0) return finish(TraceStatus::Reached, c, b, -1);
  Spot<K> spot;
  if (marked_here(c, b, spot)) return finish(TraceStatus::Reached, spot.cell, spot.b, spot.facet);
  // Zeno guard: steps that stay positive but shrink towards a critical point
  // (typically sliding around a discrete maximum) move almost nowhere.
  constexpr int kWindow = 64;
  double window_length = 0.0;
  for (int iter = 0;; ++iter) {
    if (iter >= opt_.max_steps) return finish(TraceStatus::StepBudget, c, b, -1);
    if (iter > 0 && iter % kWindow == 0) {
      if (window_length < 1e-9 * f_.diag) return finish(TraceStatus::Stalled, c, b, -1);
      window_length = 0.0;
    }
    Step<K> st = own_step(c, b);
    if (!st.ok) {
      Candidate<K> best;
      if (!find_way_on(c, b, best)) return end_where_stuck(c, b);
      c = best.cell, b = best.b, st = best.step;
    }
    // Move along the segment; stop early at the target iso-value.
    const VecK<K> delta = st.s * st.db;
    int facet = -1;
    if (target_.use_iso && stop_at_iso(c, b, st, delta, facet)) return finish(TraceStatus::Reached, c, b, facet);
    b += delta;
    b(st.exit) = 0.0;
    clean<K>(b);
    path_.push_back(position(c, b));
    window_length += (path_.back() - path_[path_.size() - 2]).norm();
    if (marked_here(c, b, spot)) return finish(TraceStatus::Reached, spot.cell, spot.b, spot.facet);
    const int n = f_.topo.neighbor(c, st.exit);
    if (n < 0) {
      if (!opt_.slide_on_boundary) return finish(TraceStatus::HitBoundary, c, b, st.exit);
      continue;  // the next round finds the way along the boundary, or stops there
    }
    b = transfer<K>(f_.C, c, b, n);
    c = n;
    ++steps_;
  }
}

}  // namespace

template <int K>
TraceResult GradientTracer::run(int c, const Eigen::Vector4d& bary, const TraceTarget& target,
                                const TraceOptions& options) const {
  const TraceField field{V_, C_, topo_, u_, vertex_gradient_, grad_scale_, diag_};
  return TraceWalk<K>(field, target, options).run(c, bary);
}

TraceResult GradientTracer::trace(int cell, const Eigen::Vector4d& bary, const TraceTarget& target,
                                  const TraceOptions& options) const {
  if (C_.cols() == 4) return run<4>(cell, bary, target, options);
  return run<3>(cell, bary, target, options);
}

TraceResult GradientTracer::trace(const Eigen::Vector3d& start, const TraceTarget& target,
                                  const TraceOptions& options) const {
  Eigen::Vector4d b;
  const int c = locate(start, -1, &b);
  if (c < 0)
    throw bad_input("trace: start point (" + std::to_string(start.x()) + ", " + std::to_string(start.y()) + ", " +
                    std::to_string(start.z()) + ") lies in no tet of the mesh");
  return run<4>(c, b, target, options);
}

int GradientTracer::locate(const Eigen::Vector3d& p, int hint, Eigen::Vector4d* bary) const {
  if (C_.cols() != 4) throw bad_input("locate: only for tet meshes");
  return locate_in_tets(V_, C_, topo_, p, hint, bary);
}

}  // namespace igaprep::param
