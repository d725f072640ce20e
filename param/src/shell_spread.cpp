#include "igaprep/param/shell_spread.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <list>
#include <utility>

#include <Eigen/LU>

#include "igaprep/core/error.h"
#include "igaprep/core/parallel.h"
#include "cell_geometry.h"

namespace igaprep::param {
namespace {

struct CurvePoint {
  double s;
  Eigen::Vector3d end;
};

double chord_length(const std::vector<Eigen::Vector3d>& ends) {
  double total = 0.0;
  for (std::size_t i = 1; i < ends.size(); ++i) total += (ends[i] - ends[i - 1]).norm();
  return total;
}

bool uneven(const std::vector<Eigen::Vector3d>& ends, double ratio) {
  double largest = 0.0;
  for (std::size_t i = 1; i < ends.size(); ++i) largest = std::max(largest, (ends[i] - ends[i - 1]).norm());
  const double mean = chord_length(ends) / static_cast<double>(ends.size() - 1);
  return largest > ratio * mean;
}

// The cubic through the ends at params[first .. first + 3] (Lagrange), at x.
Eigen::Vector3d cubic_through(const std::vector<double>& params, const std::vector<Eigen::Vector3d>& ends,
                              std::size_t first, double x) {
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  for (std::size_t a = first; a < first + 4; ++a) {
    double l = 1.0;
    for (std::size_t b = first; b < first + 4; ++b)
      if (b != a) l *= (x - params[b]) / (params[a] - params[b]);
    out += l * ends[a];
  }
  return out;
}

// Whether the end from the middle of some gap lies farther than `deviation`
// from the cubic through the four nearest ends: a bulge the samples do not
// see. A smooth curve's own bend is not one (the cubic follows it; the
// chord would not, and ring2's shells were spread for nothing).
bool bulging(const std::function<Eigen::Vector3d(double)>& end, const std::vector<double>& params,
             const std::vector<Eigen::Vector3d>& ends, double deviation) {
  if (!(deviation > 0.0) || params.size() < 4) return false;
  for (std::size_t i = 0; i + 1 < params.size(); ++i) {
    const double mid = 0.5 * (params[i] + params[i + 1]);
    const std::size_t first = std::min(i > 0 ? i - 1 : 0, params.size() - 4);
    if ((end(mid) - cubic_through(params, ends, first, mid)).norm() > deviation) return true;
  }
  return false;
}

// Halves every interval whose chord is longer than `target`, or whose
// middle end lies farther than `deviation` from it, depth first.
void refine(const std::function<Eigen::Vector3d(double)>& end, std::list<CurvePoint>& curve,
            std::list<CurvePoint>::iterator a, double target, double deviation, int depth) {
  const auto b = std::next(a);
  const bool short_chord = (b->end - a->end).norm() <= target;
  if (depth == 0 || (short_chord && !(deviation > 0.0))) return;
  const double mid = 0.5 * (a->s + b->s);
  const Eigen::Vector3d e = end(mid);
  if (short_chord && detail::distance_to_segment<3>(e, a->end, b->end) <= deviation) return;
  const auto m = curve.insert(b, {mid, e});
  refine(end, curve, a, target, deviation, depth - 1);
  refine(end, curve, m, target, deviation, depth - 1);
}

// The parameters at k / (count - 1) of the curve's chord length.
std::vector<double> even_by_chord(const std::list<CurvePoint>& curve, std::size_t count) {
  std::vector<double> s, c;
  double run = 0.0;
  const CurvePoint* prev = nullptr;
  for (const CurvePoint& p : curve) {
    if (prev) run += (p.end - prev->end).norm();
    s.push_back(p.s);
    c.push_back(run);
    prev = &p;
  }
  std::vector<double> out(count);
  out.front() = 0.0;
  out.back() = 1.0;
  for (std::size_t k = 1; k + 1 < count; ++k) {
    const double target = run * static_cast<double>(k) / static_cast<double>(count - 1);
    const std::size_t hi = static_cast<std::size_t>(std::lower_bound(c.begin(), c.end(), target) - c.begin());
    const std::size_t lo = hi - 1;
    const double t = c[hi] > c[lo] ? (target - c[lo]) / (c[hi] - c[lo]) : 0.0;
    out[k] = (1.0 - t) * s[lo] + t * s[hi];
  }
  return out;
}

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// Whether grid cell (i, j) is a strictly convex, positively turning quad.
bool positive_cell(const std::vector<Eigen::Vector2d>& g, std::size_t m, std::size_t i, std::size_t j) {
  const std::array<Eigen::Vector2d, 4> c{g[i + m * j], g[i + 1 + m * j], g[i + 1 + m * (j + 1)], g[i + m * (j + 1)]};
  for (std::size_t k = 0; k < 4; ++k)
    if (!(cross(c[(k + 1) % 4] - c[k], c[(k + 3) % 4] - c[k]) > 0.0)) return false;
  return true;
}

bool any_folded(const std::vector<Eigen::Vector2d>& g, std::size_t m) {
  for (std::size_t j = 0; j + 1 < m; ++j)
    for (std::size_t i = 0; i + 1 < m; ++i)
      if (!positive_cell(g, m, i, j)) return true;
  return false;
}

// Marks the corners of the folded cells free; returns whether any cell
// was folded.
bool free_folded_points(const std::vector<Eigen::Vector2d>& g, std::size_t m, std::vector<char>& free) {
  bool any = false;
  for (std::size_t j = 0; j + 1 < m; ++j)
    for (std::size_t i = 0; i + 1 < m; ++i) {
      if (positive_cell(g, m, i, j)) continue;
      any = true;
      for (std::size_t b = j; b <= j + 1; ++b)
        for (std::size_t a = i; a <= i + 1; ++a) free[a + m * b] = 1;
    }
  return any;
}

// Each free point inside the square halfway to the mean of its four
// neighbours, in place; the sides are never moved.
void relax(std::vector<Eigen::Vector2d>& g, std::size_t m, const std::vector<char>& free) {
  for (std::size_t j = 1; j + 1 < m; ++j)
    for (std::size_t i = 1; i + 1 < m; ++i)
      if (free[i + m * j]) {
        const Eigen::Vector2d mean =
            0.25 * (g[i - 1 + m * j] + g[i + 1 + m * j] + g[i + m * (j - 1)] + g[i + m * (j + 1)]);
        g[i + m * j] = 0.5 * (g[i + m * j] + mean);
      }
}

// Relaxes the corners of the folded cells, a little at a time, until none
// is folded or `rounds` rounds have passed; the rest of the grid keeps its
// spread (a fan's samples crowd into a small part of the face, and a wider
// smoothing undoes that). Returns whether the grid is free of folds.
bool untangle(std::vector<Eigen::Vector2d>& g, std::size_t m, int rounds) {
  std::vector<char> free(m * m);
  for (int round = 0; round < rounds; ++round) {
    std::fill(free.begin(), free.end(), 0);
    if (!free_folded_points(g, m, free)) return true;
    relax(g, m, free);
  }
  return !any_folded(g, m);
}

// The rows spread one by one, each along s at its own t (fold-free: every
// cell a trapezoid). row_ends: the ends at the new points.
std::vector<Eigen::Vector2d> spread_rows(const std::function<Eigen::Vector3d(const Eigen::Vector2d&)>& end,
                                         const std::vector<double>& params, const std::vector<Eigen::Vector3d>& ends,
                                         const std::array<bool, 4>& fixed_sides, const SpreadOptions& options,
                                         std::vector<Eigen::Vector3d>& row_ends) {
  const std::size_t m = params.size();
  std::vector<Eigen::Vector2d> rows(m * m);
  row_ends.resize(m * m);
  parallel_for(m, [&](std::size_t j) {
    const double t = params[j];
    std::vector<Eigen::Vector3d> e(ends.begin() + static_cast<std::ptrdiff_t>(m * j),
                                   ends.begin() + static_cast<std::ptrdiff_t>(m * (j + 1)));
    const bool fixed = (j == 0 && fixed_sides[0]) || (j == m - 1 && fixed_sides[2]);
    const std::vector<double> s =
        fixed ? params : even_end_params([&](double x) { return end(Eigen::Vector2d(x, t)); }, params, e, options);
    for (std::size_t i = 0; i < m; ++i) {
      rows[i + m * j] = Eigen::Vector2d(s[i], t);
      row_ends[i + m * j] = s[i] == params[i] ? e[i] : end(rows[i + m * j]);
    }
  });
  return rows;
}

// Every column through the rows' points (a polyline in (s, t)) spread
// along its length.
std::vector<Eigen::Vector2d> spread_columns(const std::function<Eigen::Vector3d(const Eigen::Vector2d&)>& end,
                                            const std::vector<double>& params, const std::vector<Eigen::Vector2d>& rows,
                                            const std::vector<Eigen::Vector3d>& row_ends,
                                            const std::array<bool, 4>& fixed_sides, const SpreadOptions& options) {
  const std::size_t m = params.size();
  std::vector<Eigen::Vector2d> out(m * m);
  parallel_for(m, [&](std::size_t i) {
    auto at = [&](double u) {
      const ParamCell c = param_cell(params, u);
      return Eigen::Vector2d((1.0 - c.w) * rows[i + m * c.i] + c.w * rows[i + m * (c.i + 1)]);
    };
    std::vector<Eigen::Vector3d> e(m);
    for (std::size_t j = 0; j < m; ++j) e[j] = row_ends[i + m * j];
    const bool fixed = (i == 0 && fixed_sides[3]) || (i == m - 1 && fixed_sides[1]);
    const std::vector<double> u =
        fixed ? params : even_end_params([&](double x) { return end(at(x)); }, params, e, options);
    for (std::size_t j = 0; j < m; ++j) out[i + m * j] = u == params ? rows[i + m * j] : at(u[j]);
  });
  return out;
}

// Whether moving inner point q of the grid to x keeps its four cells unfolded.
bool keeps_cells(std::vector<Eigen::Vector2d>& g, std::size_t m, std::size_t q, const Eigen::Vector2d& x) {
  const Eigen::Vector2d was = g[q];
  g[q] = x;
  const std::size_t i = q % m, j = q / m;
  const bool ok = positive_cell(g, m, i - 1, j - 1) && positive_cell(g, m, i, j - 1) && positive_cell(g, m, i - 1, j) &&
                  positive_cell(g, m, i, j);
  g[q] = was;
  return ok;
}

// The step of inner point q towards the mean of its neighbours' ends, from
// the round's grid g and ends e (zero where the end map's local Jacobian
// is singular); *mean receives that mean.
Eigen::Vector2d step_to_mean(const std::vector<Eigen::Vector2d>& g, const std::vector<Eigen::Vector3d>& e, std::size_t m,
                             std::size_t q, Eigen::Vector3d* mean) {
  Eigen::Matrix<double, 3, 2> EP = Eigen::Matrix<double, 3, 2>::Zero();
  Eigen::Matrix2d PP = Eigen::Matrix2d::Zero();
  *mean = Eigen::Vector3d::Zero();
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t n : {q - 1, q + 1, q - m, q + m}) {
    const Eigen::Vector2d dp = g[n] - g[q];
    EP += (e[n] - e[q]) * dp.transpose();
    PP += dp * dp.transpose();
    *mean += 0.25 * e[n];
    nearest = std::min(nearest, dp.norm());
  }
  if (!(std::abs(PP.determinant()) > 0.0)) return Eigen::Vector2d::Zero();
  const Eigen::Matrix<double, 3, 2> A = EP * PP.inverse();  // the end map's Jacobian, least squares
  const Eigen::Matrix2d AA = A.transpose() * A;
  if (!(std::abs(AA.determinant()) > 0.0)) return Eigen::Vector2d::Zero();
  Eigen::Vector2d step = 0.5 * (AA.inverse() * (A.transpose() * (*mean - e[q])));
  if (step.norm() > 0.5 * nearest) step *= 0.5 * nearest / step.norm();
  return step;
}

// Moves the inner parameters so that their ends approach the mean of their
// four neighbours' ends (on T1: a discrete harmonic grid of the face's
// footprint), each step mapped back through the end map's local Jacobian
// (least squares over the four neighbours) and at most half the way to the
// nearest neighbour; a step that would fold one of the point's cells is
// not made. The sides stay. Spreading rows and columns one by one leaves
// the ends even along each but not across: torus_genus3's shells folded on
// T1 where the fans turn.
void smooth_ends(const std::function<Eigen::Vector3d(const Eigen::Vector2d&)>& end, std::vector<Eigen::Vector2d>& g,
                 std::size_t m, int rounds) {
  if (rounds <= 0) return;
  std::vector<Eigen::Vector3d> e(m * m);
  parallel_for(m * m, [&](std::size_t q) { e[q] = end(g[q]); });
  std::vector<Eigen::Vector2d> step(m * m);
  std::vector<Eigen::Vector3d> mean(m * m), first_end(m * m);
  std::vector<char> traced(m * m);
  for (int round = 0; round < rounds; ++round) {
    // Every point's first step depends on the round's grid alone: their
    // ends are traced on all cores, the steps then taken in order.
    // (Only those that keep their cells unfolded on the round's grid; a
    // step that keeps them only after its neighbours' moves is traced then.)
    std::fill(traced.begin(), traced.end(), 0);
    for (std::size_t j = 1; j + 1 < m; ++j)
      for (std::size_t i = 1; i + 1 < m; ++i) {
        const std::size_t q = i + m * j;
        step[q] = step_to_mean(g, e, m, q, &mean[q]);
        const Eigen::Vector2d x = g[q] + step[q];
        traced[q] = !step[q].isZero(0.0) && x.allFinite() && keeps_cells(g, m, q, x);
      }
    parallel_for(m * m, [&](std::size_t q) {
      if (traced[q]) first_end[q] = end(g[q] + step[q]);
    });
    std::vector<Eigen::Vector2d> next = g;
    std::vector<Eigen::Vector3d> next_e = e;
    double largest = 0.0;
    for (std::size_t j = 1; j + 1 < m; ++j)
      for (std::size_t i = 1; i + 1 < m; ++i) {
        const std::size_t q = i + m * j;
        if (step[q].isZero(0.0)) continue;
        const Eigen::Vector3d to_mean = mean[q] - e[q];
        // Half way to the mean, kept only if the end comes nearer it and not
        // past it (damped Jacobi steps): across a wide parameter gap (a fan's
        // first cell) the Jacobian is far off, and steps taken on trust
        // overshot and diverged. Halved twice at most.
        Eigen::Vector2d s = step[q];
        for (int halving = 0; halving < 3; ++halving, s *= 0.5) {
          const Eigen::Vector2d x = g[q] + s;
          if (!x.allFinite() || !keeps_cells(next, m, q, x)) continue;
          const Eigen::Vector3d ex = halving == 0 && traced[q] ? first_end[q] : end(x);
          if (!((ex - mean[q]).norm() < to_mean.norm() && (ex - e[q]).dot(to_mean) <= to_mean.squaredNorm())) continue;
          next[q] = x;
          next_e[q] = ex;
          largest = std::max(largest, s.norm());
          break;
        }
      }
    g = std::move(next);
    e = std::move(next_e);
    if (!(largest > 1e-4 / static_cast<double>(m))) return;  // settled (parameters run from 0 to 1)
  }
}

}  // namespace

ParamCell param_cell(const std::vector<double>& params, double x) {
  const auto it = std::upper_bound(params.begin(), params.end(), x);
  const std::size_t hi = std::clamp<std::size_t>(static_cast<std::size_t>(it - params.begin()), 1, params.size() - 1);
  return {hi - 1, (x - params[hi - 1]) / (params[hi] - params[hi - 1])};
}

std::vector<double> even_end_params(const std::function<Eigen::Vector3d(double)>& end,
                                    const std::vector<double>& params, const std::vector<Eigen::Vector3d>& ends,
                                    const SpreadOptions& options) {
  if (params.size() < 3 || params.size() != ends.size() || params.front() != 0.0 || params.back() != 1.0)
    throw internal_error("even_end_params: need at least 3 parameters from 0 to 1, one end each");
  if (!uneven(ends, options.uneven_ratio) && !bulging(end, params, ends, options.chord_deviation)) return params;
  std::list<CurvePoint> curve;
  for (std::size_t i = 0; i < params.size(); ++i) curve.push_back({params[i], ends[i]});
  const double target = chord_length(ends) / static_cast<double>((params.size() - 1) * options.per_gap);
  for (auto a = curve.begin(); std::next(a) != curve.end();) {
    const auto b = std::next(a);
    refine(end, curve, a, target, options.chord_deviation, options.refinements);
    a = b;
  }
  return even_by_chord(curve, params.size());
}

std::vector<Eigen::Vector2d> spread_face_params(const std::function<Eigen::Vector3d(const Eigen::Vector2d&)>& end,
                                                const std::vector<double>& params,
                                                const std::vector<Eigen::Vector3d>& ends,
                                                const std::array<bool, 4>& fixed_sides, const SpreadOptions& options) {
  const std::size_t m = params.size();
  if (ends.size() != m * m) throw internal_error("spread_face_params: need one end per grid point");
  std::vector<Eigen::Vector3d> row_ends;
  const std::vector<Eigen::Vector2d> rows = spread_rows(end, params, ends, fixed_sides, options, row_ends);
  std::vector<Eigen::Vector2d> out = spread_columns(end, params, rows, row_ends, fixed_sides, options);
  // Columns spread one by one after the rows can fold the grid where their
  // moves differ (torus_genus3: 14 of its 32 spread faces, about 100
  // cells), and every depth of the shell would inherit the fold. Untangled
  // where folded; else the rows alone (trapezoids) with the spread sides
  // (the neighbouring faces share them), untangled; last, relaxed
  // throughout.
  if (!untangle(out, m, 100)) {
    std::vector<Eigen::Vector2d> rows_only = rows;
    for (std::size_t k = 0; k < m; ++k)
      for (std::size_t side : {m * k, m - 1 + m * k, k, k + m * (m - 1)}) rows_only[side] = out[side];
    if (untangle(rows_only, m, 100)) {
      out = std::move(rows_only);
    } else {
      const std::vector<char> inside(m * m, 1);
      for (int sweep = 0; sweep < 2000 && any_folded(out, m); ++sweep) relax(out, m, inside);
    }
  }
  bool spread = false;
  for (std::size_t q = 0; q < m * m; ++q) spread = spread || out[q] != Eigen::Vector2d(params[q % m], params[q / m]);
  if (spread) smooth_ends(end, out, m, options.end_smoothing);
  return out;
}

}  // namespace igaprep::param
