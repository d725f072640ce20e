#include "igaprep/param/trace_gradient.h"

#include <cmath>
#include <limits>
#include <string>

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

}  // namespace

template <int K>
TraceResult GradientTracer::run(int c, const Eigen::Vector4d& bary_in, const TraceTarget& target,
                                const TraceOptions& opt) const {
  const double sign = opt.descend ? -1.0 : 1.0;
  const double tiny = opt.tiny_gradient * grad_scale_;
  const bool have_marks = !target.marked.empty();
  if (have_marks && target.marked.size() != static_cast<size_t>(C_.rows()) * K)
    throw bad_input("trace: marked facets were built for another mesh");
  if (c < 0 || c >= C_.rows()) throw bad_input("trace: start cell " + std::to_string(c) + " out of range");
  VecK<K> b = bary_in.head<K>();
  if (!b.allFinite()) throw bad_input("trace: start coordinates are not finite");
  b = b.cwiseMax(0.0);
  if (!(b.sum() > 0)) throw bad_input("trace: start coordinates are all zero");
  clean<K>(b);

  std::vector<Eigen::Vector3d> path;
  path.reserve(64);
  auto position = [&](int x, const VecK<K>& bx) {
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (int k = 0; k < K; ++k) p += bx(k) * detail::vrow(V_, C_(x, k));
    return p;
  };
  auto value = [&](int x, const VecK<K>& bx) {
    double v = 0.0;
    for (int k = 0; k < K; ++k) v += bx(k) * u_(C_(x, k));
    return v;
  };
  auto grad_phi = [&](int x, GradPhi<K>& gp) { return detail::cell_grad_phi(V_, C_, x, gp) != 0.0; };
  auto field_grad = [&](int x, const GradPhi<K>& gp) {
    Eigen::Vector3d g = Eigen::Vector3d::Zero();
    for (int k = 0; k < K; ++k) g += u_(C_(x, k)) * gp.row(k).transpose();
    return g;
  };
  // The continuous (vertex-averaged) gradient at bx, in the plane of a triangle.
  auto averaged_dir = [&](int x, const VecK<K>& bx, const GradPhi<K>& gp) {
    Eigen::Vector3d d = Eigen::Vector3d::Zero();
    for (int k = 0; k < K; ++k) d += bx(k) * vertex_gradient_.row(C_(x, k)).transpose();
    if constexpr (K == 3) {
      // Keep only the in-plane part: the span of the barycentric gradients.
      const Eigen::Vector3d n = gp.row(1).transpose().cross(gp.row(2).transpose());
      if (n.squaredNorm() > 0) d -= d.dot(n) / n.squaredNorm() * n;
    }
    return Eigen::Vector3d(sign * d);
  };

  TraceResult res;
  int steps = 0;
  auto finish = [&](TraceStatus st, int x, const VecK<K>& bx, int facet) {
    res.status = st;
    res.cell = x;
    res.facet = facet;
    res.face = (facet >= 0 && have_marks) ? target.marked[static_cast<size_t>(x) * K + facet] : -1;
    res.bary.setZero();
    res.bary.head<K>() = bx;
    res.end = position(x, bx);
    res.value = value(x, bx);
    res.steps = steps;
    if (path.empty() || (path.back() - res.end).norm() > 0) path.push_back(res.end);
    res.path.resize(static_cast<Eigen::Index>(path.size()), 3);
    for (size_t i = 0; i < path.size(); ++i) res.path.row(static_cast<Eigen::Index>(i)) = path[i].transpose();
    return res;
  };
  // Cells holding the point (c, bx): those around the smallest simplex that carries it.
  std::vector<int> star;
  auto collect_star = [&](int x, const VecK<K>& bx) {
    star.clear();
    int carrier[K], nc = 0;
    for (int k = 0; k < K; ++k)
      if (bx(k) > kOnFacet) carrier[nc++] = C_(x, k);
    const int v0 = carrier[0];
    for (int s = topo_.vertex_cells_start[v0]; s < topo_.vertex_cells_start[v0 + 1]; ++s) {
      const int y = topo_.vertex_cells[s];
      bool all = true;
      for (int j = 1; j < nc && all; ++j) {
        bool in = false;
        for (int k = 0; k < K; ++k) in = in || C_(y, k) == carrier[j];
        all = in;
      }
      if (all) star.push_back(y);
    }
  };
  // A marked facet through the point, in any cell around it.
  auto marked_here = [&](int x, const VecK<K>& bx, int& mx, VecK<K>& mb, int& mf) {
    if (!have_marks) return false;
    int zeros = 0;
    for (int k = 0; k < K; ++k) zeros += bx(k) <= kOnFacet;
    if (zeros == 0) return false;
    if (zeros == 1) {
      for (int k = 0; k < K; ++k)
        if (bx(k) <= kOnFacet && target.marked[static_cast<size_t>(x) * K + k] >= 0) {
          mx = x, mb = bx, mf = k;
          return true;
        }
      return false;
    }
    collect_star(x, bx);
    for (int y : star) {
      const VecK<K> by = transfer<K>(C_, x, bx, y);
      for (int k = 0; k < K; ++k)
        if (by(k) <= kOnFacet && target.marked[static_cast<size_t>(y) * K + k] >= 0) {
          mx = y, mb = by, mf = k;
          return true;
        }
    }
    return false;
  };

  path.push_back(position(c, b));
  if (target.use_iso && sign * (value(c, b) - target.iso) >= 0) return finish(TraceStatus::Reached, c, b, -1);
  {
    int mx, mf;
    VecK<K> mb;
    if (marked_here(c, b, mx, mb, mf)) return finish(TraceStatus::Reached, mx, mb, mf);
  }

  GradPhi<K> gp;
  // Zeno guard: steps that stay positive but shrink towards a critical point
  // (typically sliding around a discrete maximum) move almost nowhere.
  constexpr int kWindow = 64;
  double window_length = 0.0;
  for (int iter = 0;; ++iter) {
    if (iter >= opt.max_steps) return finish(TraceStatus::StepBudget, c, b, -1);
    if (iter > 0 && iter % kWindow == 0) {
      if (window_length < 1e-9 * diag_) return finish(TraceStatus::Stalled, c, b, -1);
      window_length = 0.0;
    }
    // 1. The cell's own (piecewise-constant) gradient, or the averaged one where it is tiny.
    Step<K> st;
    Eigen::Vector3d d;
    if (grad_phi(c, gp)) {
      const Eigen::Vector3d g = field_grad(c, gp);
      d = g.norm() > tiny ? Eigen::Vector3d(sign * g) : averaged_dir(c, b, gp);
      if (d.norm() > tiny) st = step_in<K>(gp, b, d);
    }
    if (!st.ok) {
      // 2. The direction leaves the cell at once: on a facet, edge or vertex.
      // Look at every cell around the point for one that lets the field
      // grow along a segment of positive length: first with the cells' own
      // gradients, then with the continuous averaged gradient, then sliding
      // within a facet (a valley of the field, or the boundary), then along an
      // edge. Within a pass: the steepest candidate, then the longest segment.
      collect_star(c, b);
      int best = -1;
      double best_len = 0.0, best_cos = -1.0;
      VecK<K> best_b = VecK<K>::Zero();
      Step<K> best_st;
      Eigen::Vector3d best_d = Eigen::Vector3d::Zero();
      GradPhi<K> gy;
      for (int pass = 0; pass < 4 && best < 0; ++pass) {
        for (int y : star) {
          if (!grad_phi(y, gy)) continue;
          const VecK<K> by = transfer<K>(C_, c, b, y);
          const Eigen::Vector3d g = field_grad(y, gy);
          // Every candidate must let the field grow in y (not shrink, where y's gradient is tiny),
          // so the field is monotone along the whole trace and it cannot cycle.
          auto consider = [&](const Eigen::Vector3d& dy) {
            if (!(dy.norm() > tiny)) return;
            const double rate = dy.dot(sign * g);
            if (!(rate > 0 || (g.norm() <= tiny && rate >= 0))) return;
            const Step<K> sy = step_in<K>(gy, by, dy);
            if (!sy.ok) return;
            // Steepest first (closest to the cell's gradient), then the longest segment.
            const double cosine = g.norm() > tiny ? rate / (dy.norm() * g.norm()) : 0.0;
            if (best < 0 || cosine > best_cos + 1e-9 || (cosine > best_cos - 1e-9 && sy.length > best_len)) {
              best = y, best_len = sy.length, best_cos = cosine, best_b = by, best_st = sy, best_d = dy;
            }
          };
          if (pass == 0) {
            if (g.norm() > tiny) consider(sign * g);
          } else if (pass == 1) {
            consider(averaged_dir(y, by, gy));
          } else {
            // Slide within the facets (and, in tets, the edges) through the point:
            // the way on along a valley of the piecewise-constant field, or along the boundary.
            const Eigen::Vector3d dirs[2] = {Eigen::Vector3d(sign * g), averaged_dir(y, by, gy)};
            for (int k = 0; k < K; ++k) {
              if (by(k) > kOnFacet) continue;
              if (topo_.neighbor(y, k) < 0 && !opt.slide_on_boundary) continue;
              const Eigen::Vector3d nk = gy.row(k).transpose().normalized();
              if (pass == 2)  // within a facet
                for (const Eigen::Vector3d& dy : dirs) consider(dy - dy.dot(nk) * nk);
              if constexpr (K == 4) {  // along an edge, where facet sliding is blocked
                if (pass != 3) continue;
                for (int l = k + 1; l < K; ++l) {
                  if (by(l) > kOnFacet) continue;
                  if (topo_.neighbor(y, l) < 0 && !opt.slide_on_boundary) continue;
                  const Eigen::Vector3d e = nk.cross(gy.row(l).transpose()).normalized();
                  for (const Eigen::Vector3d& dy : dirs) consider(dy.dot(e) * e);
                }
              }
            }
          }
        }
      }
      if (best < 0) {
        // Nothing goes on: the boundary, or a critical point of the field.
        for (int y : star) {
          const VecK<K> by = transfer<K>(C_, c, b, y);
          for (int k = 0; k < K; ++k)
            if (by(k) <= kOnFacet && topo_.neighbor(y, k) < 0) return finish(TraceStatus::HitBoundary, y, by, k);
        }
        return finish(TraceStatus::Stalled, c, b, -1);
      }
      c = best, b = best_b, st = best_st, d = best_d;
      grad_phi(c, gp);
    }
    // 3. Move along the segment; stop early at the target iso-value.
    const VecK<K> delta = st.s * st.db;
    if (target.use_iso) {
      const double v0 = value(c, b);
      double dv = 0.0;
      for (int k = 0; k < K; ++k) dv += delta(k) * u_(C_(c, k));
      if (sign * (v0 + dv - target.iso) >= 0 && dv != 0.0) {
        const double t = std::clamp((target.iso - v0) / dv, 0.0, 1.0);
        b += t * delta;
        if (t >= 1.0) b(st.exit) = 0.0;
        clean<K>(b);
        int facet = -1;
        for (int k = 0; k < K; ++k)
          if (b(k) == 0.0) facet = k;
        return finish(TraceStatus::Reached, c, b, facet);
      }
    }
    b += delta;
    b(st.exit) = 0.0;
    clean<K>(b);
    path.push_back(position(c, b));
    window_length += (path.back() - path[path.size() - 2]).norm();
    {
      int mx, mf;
      VecK<K> mb;
      if (marked_here(c, b, mx, mb, mf)) return finish(TraceStatus::Reached, mx, mb, mf);
    }
    const int n = topo_.neighbor(c, st.exit);
    if (n < 0) {
      if (!opt.slide_on_boundary) return finish(TraceStatus::HitBoundary, c, b, st.exit);
      continue;  // the next round finds the way along the boundary, or stops there
    }
    b = transfer<K>(C_, c, b, n);
    c = n;
    ++steps;
  }
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
