#include "igaprep/iga_check/quality_metrics.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "igaprep/core/error.h"
#include "igaprep/core/parallel.h"
#include "igaprep/spline/evaluate.h"
#include "igaprep/spline/gauss_legendre.h"
#include "igaprep/spline/knot_vector.h"

namespace igaprep::iga_check {

double condition_number(const Eigen::Matrix3d& J) {
  const double det = J.determinant();
  if (det == 0.0 || !std::isfinite(det)) return std::numeric_limits<double>::infinity();
  // J^-1 = cof(J)^T / det J, and the cofactor matrix's columns are the cross
  // products of J's columns: no inverse needed.
  const Eigen::Vector3d a = J.col(0), b = J.col(1), c = J.col(2);
  const double cof2 = b.cross(c).squaredNorm() + c.cross(a).squaredNorm() + a.cross(b).squaredNorm();
  const double cn = std::sqrt(J.squaredNorm() * cof2) / (3.0 * std::abs(det));
  return std::isfinite(cn) ? cn : std::numeric_limits<double>::infinity();
}

namespace {

// Running statistics; the histogram is filled once its range is known.
struct Accumulator {
  double min = std::numeric_limits<double>::infinity(), max = -std::numeric_limits<double>::infinity(), sum = 0.0;
  long count = 0;
  Histogram hist;
  void add(double x) {
    if (!std::isfinite(x)) return;
    min = std::min(min, x);
    max = std::max(max, x);
    sum += x;
    ++count;
  }
  void set_range(double lo, double hi, int bins) {
    hist.lo = lo;
    hist.hi = hi;
    hist.counts.assign(bins, 0);
  }
  void bin(double x) {
    if (!std::isfinite(x)) return;
    const int bins = static_cast<int>(hist.counts.size());
    const double width = (hist.hi - hist.lo) / bins;
    int b = width > 0.0 ? static_cast<int>(std::floor((x - hist.lo) / width)) : 0;
    ++hist.counts[std::clamp(b, 0, bins - 1)];
  }
  MetricStats stats() const {
    MetricStats s;
    s.count = count;
    if (count > 0) {
      s.min = min;
      s.max = max;
      s.mean = sum / count;
    }
    s.histogram = hist;
    return s;
  }
};

// A constant gets a small range around it.
std::pair<double, double> padded(double lo, double hi) {
  if (!(lo <= hi)) return {-1.0, 1.0};
  if (hi == lo) {
    const double pad = lo == 0.0 ? 1.0 : 1e-6 * std::abs(lo);
    return {lo - pad, hi + pad};
  }
  return {lo, hi};
}

struct PatchSampling {
  std::array<std::vector<double>, 3> params;
  std::array<std::vector<int>, 3> tag;  // element of each parameter
  std::array<int, 3> ne{{0, 0, 0}};
};

PatchSampling sampling(const spline::Patch& p, size_t pi, const QualityOptions& options) {
  PatchSampling s;
  for (int d = 0; d < 3; ++d) {
    const std::vector<double> brk = spline::unique_knots(p.knots[d]);
    s.ne[d] = static_cast<int>(brk.size()) - 1;
    if (s.ne[d] < 1) throw bad_input("patch " + std::to_string(pi) + ": empty parameter domain");
    std::vector<double> local;
    for (int g = 0; g < options.grid; ++g) local.push_back(double(g) / (options.grid - 1));
    if (options.gauss) {
      Eigen::VectorXd gp, gw;
      spline::gauss_legendre(p.degrees[d] + 1, gp, gw);
      for (int g = 0; g < gp.size(); ++g) local.push_back(gp[g]);
    }
    std::sort(local.begin(), local.end());
    for (int e = 0; e < s.ne[d]; ++e)
      for (double t : local) {
        s.params[d].push_back(brk[e] + t * (brk[e + 1] - brk[e]));
        s.tag[d].push_back(e);
      }
  }
  return s;
}

// Calls f(J, i, j, k, x) for every sample point, evaluating one layer of
// elements along w at a time (bounded memory for large patches).
template <class F>
void for_each_point(const spline::Patch& p, const PatchSampling& s, F&& f) {
  const int nw = static_cast<int>(s.params[2].size());
  int k0 = 0;
  while (k0 < nw) {
    int k1 = k0;
    while (k1 < nw && s.tag[2][k1] == s.tag[2][k0]) ++k1;
    std::array<std::vector<double>, 3> params = s.params;
    params[2].assign(s.params[2].begin() + k0, s.params[2].begin() + k1);
    const spline::GridEvaluation ev = spline::evaluate_grid(p, params, 1);
    const int nu = static_cast<int>(params[0].size()), nv = static_cast<int>(params[1].size());
    long at = 0;
    for (int k = k0; k < k1; ++k)
      for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i, ++at) {
          f(spline::grid_jacobian(ev, at), i, j, k, ev.points.row(at));
        }
    k0 = k1;
  }
}

}  // namespace

QualityReport quality_metrics(const spline::MultiPatch& mp, const QualityOptions& options) {
  if (options.grid < 2 || options.histogram_bins < 1)
    throw bad_input("quality metrics: grid must be >= 2 and histogram_bins >= 1");
  const int bins = options.histogram_bins;
  QualityReport report;
  const size_t np = mp.patches.size();
  std::vector<PatchSampling> samp(np);
  std::vector<std::array<Accumulator, 3>> acc(np);  // det, scaled, condition
  std::array<Accumulator, 3> all;
  std::vector<std::vector<QualityPoint>> patch_worst(np);
  report.patches.resize(np);
  // Pass 1, patches on all cores (each fills its own slots): statistics,
  // scaled-Jacobian histograms (fixed range), worst points.
  parallel_for(np, [&](size_t pi) {
    const spline::Patch& p = mp.patches[pi];
    samp[pi] = sampling(p, pi, options);
    const PatchSampling& s = samp[pi];
    acc[pi][1].set_range(-1.0, 1.0, bins);
    std::vector<QualityPoint> worst(static_cast<size_t>(s.ne[0]) * s.ne[1] * s.ne[2]);
    for (auto& q : worst) q.scaled_jacobian = std::numeric_limits<double>::infinity();
    PatchQuality pq;
    pq.patch = static_cast<int>(pi);
    for_each_point(p, s, [&](const Eigen::Matrix3d& J, int i, int j, int k, const Eigen::RowVector3d& x) {
      const double det = J.determinant(), sj = scaled_jacobian(J), cn = condition_number(J);
      ++pq.points;
      if (!std::isfinite(cn)) ++pq.singular_points;
      acc[pi][0].add(det);
      acc[pi][1].add(sj);
      acc[pi][1].bin(sj);
      acc[pi][2].add(cn);
      const int e = s.tag[0][i] + s.ne[0] * (s.tag[1][j] + s.ne[1] * s.tag[2][k]);
      QualityPoint& q = worst[e];
      if (sj < q.scaled_jacobian) {
        q.patch = static_cast<int>(pi);
        q.element = {{s.tag[0][i], s.tag[1][j], s.tag[2][k]}};
        q.uvw = Eigen::Vector3d(s.params[0][i], s.params[1][j], s.params[2][k]);
        q.x = x.transpose();
        q.det_j = det;
        q.scaled_jacobian = sj;
        q.condition = cn;
      }
    });
    patch_worst[pi] = std::move(worst);
    report.patches[pi] = pq;
  });
  std::vector<QualityPoint> element_worst;
  for (const auto& w : patch_worst) element_worst.insert(element_worst.end(), w.begin(), w.end());
  // Model-wide ranges of det J and condition, then pass 2 fills their histograms.
  double dlo = std::numeric_limits<double>::infinity(), dhi = -dlo, clo = dlo, chi = -dlo;
  for (const auto& a : acc) {
    if (a[0].count) dlo = std::min(dlo, a[0].min), dhi = std::max(dhi, a[0].max);
    if (a[2].count) clo = std::min(clo, a[2].min), chi = std::max(chi, a[2].max);
  }
  const auto det_range = padded(dlo, dhi), cond_range = padded(clo, chi);
  for (int m = 0; m < 3; ++m) {
    const auto range = m == 0 ? det_range : m == 1 ? std::make_pair(-1.0, 1.0) : cond_range;
    all[m].set_range(range.first, range.second, bins);
  }
  parallel_for(np, [&](size_t pi) {
    acc[pi][0].set_range(det_range.first, det_range.second, bins);
    acc[pi][2].set_range(cond_range.first, cond_range.second, bins);
    for_each_point(mp.patches[pi], samp[pi], [&](const Eigen::Matrix3d& J, int, int, int, const Eigen::RowVector3d&) {
      acc[pi][0].bin(J.determinant());
      acc[pi][2].bin(condition_number(J));
    });
  });
  for (size_t pi = 0; pi < np; ++pi) {
    PatchQuality& pq = report.patches[pi];
    pq.det_j = acc[pi][0].stats();
    pq.scaled_jacobian = acc[pi][1].stats();
    pq.condition = acc[pi][2].stats();
    report.overall.points += pq.points;
    report.overall.singular_points += pq.singular_points;
    for (int m = 0; m < 3; ++m) {
      const Accumulator& a = acc[pi][m];
      Accumulator& t = all[m];
      if (a.count) {
        t.min = std::min(t.min, a.min);
        t.max = std::max(t.max, a.max);
      }
      t.sum += a.sum;
      t.count += a.count;
      for (int b = 0; b < bins; ++b) t.hist.counts[b] += a.hist.counts[b];
    }
  }
  report.overall.det_j = all[0].stats();
  report.overall.scaled_jacobian = all[1].stats();
  report.overall.condition = all[2].stats();
  // Stable order: by scaled Jacobian, ties by patch and element.
  std::stable_sort(element_worst.begin(), element_worst.end(), [](const QualityPoint& a, const QualityPoint& b) {
    return a.scaled_jacobian < b.scaled_jacobian;
  });
  if (static_cast<int>(element_worst.size()) > options.worst_count) element_worst.resize(options.worst_count);
  report.worst = element_worst;
  return report;
}

}  // namespace igaprep::iga_check
