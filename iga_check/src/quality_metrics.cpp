#include "igaprep/iga_check/quality_metrics.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "igaprep/core/error.h"
#include "igaprep/iga_check/elasticity_quadrature.h"
#include "igaprep/spline/evaluate.h"
#include "igaprep/spline/knot_vector.h"

namespace igaprep::iga_check {

double scaled_jacobian(const Eigen::Matrix3d& J) {
  const double n = J.col(0).norm() * J.col(1).norm() * J.col(2).norm();
  if (!(n > 0.0)) return 0.0;
  return J.determinant() / n;
}

double condition_number(const Eigen::Matrix3d& J) {
  const double det = J.determinant();
  const double fro = J.norm();
  if (det == 0.0 || !std::isfinite(det)) return std::numeric_limits<double>::infinity();
  const double c = fro * J.inverse().norm() / 3.0;
  return std::isfinite(c) ? c : std::numeric_limits<double>::infinity();
}

namespace {

struct Values {
  std::vector<double> det, scaled, cond;
};

MetricStats stats(const std::vector<double>& v, double lo, double hi, int bins) {
  MetricStats s;
  s.min = std::numeric_limits<double>::infinity();
  s.max = -std::numeric_limits<double>::infinity();
  double sum = 0.0;
  s.histogram.lo = lo;
  s.histogram.hi = hi;
  s.histogram.counts.assign(bins, 0);
  const double width = (hi - lo) / bins;
  for (double x : v) {
    if (!std::isfinite(x)) continue;
    s.min = std::min(s.min, x);
    s.max = std::max(s.max, x);
    sum += x;
    ++s.count;
    int b = width > 0.0 ? static_cast<int>(std::floor((x - lo) / width)) : 0;
    b = std::clamp(b, 0, bins - 1);
    ++s.histogram.counts[b];
  }
  if (s.count == 0) {
    s.min = s.max = 0.0;
  } else {
    s.mean = sum / s.count;
  }
  return s;
}

std::pair<double, double> finite_range(const std::vector<Values>& all, std::vector<double> Values::*member) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Values& v : all)
    for (double x : v.*member)
      if (std::isfinite(x)) {
        lo = std::min(lo, x);
        hi = std::max(hi, x);
      }
  if (!(lo <= hi)) lo = hi = 0.0;
  if (hi == lo) {  // a constant gets a bin of its own around it
    const double pad = lo == 0.0 ? 1.0 : 1e-6 * std::abs(lo);
    lo -= pad;
    hi += pad;
  }
  return {lo, hi};
}

}  // namespace

QualityReport quality_metrics(const spline::MultiPatch& mp, const QualityOptions& options) {
  if (options.grid < 2 || options.histogram_bins < 1)
    throw bad_input("quality metrics: grid must be >= 2 and histogram_bins >= 1");
  QualityReport report;
  std::vector<Values> values(mp.patches.size());
  std::vector<QualityPoint> element_worst;
  for (size_t pi = 0; pi < mp.patches.size(); ++pi) {
    const spline::Patch& p = mp.patches[pi];
    // Parameters per direction, each tagged with its element.
    std::array<std::vector<double>, 3> params;
    std::array<std::vector<int>, 3> tag;
    std::array<int, 3> ne;
    for (int d = 0; d < 3; ++d) {
      const std::vector<double> brk = spline::unique_knots(p.knots[d]);
      ne[d] = static_cast<int>(brk.size()) - 1;
      if (ne[d] < 1) throw bad_input("patch " + std::to_string(pi) + ": empty parameter domain");
      std::vector<double> local;
      for (int g = 0; g < options.grid; ++g) local.push_back(double(g) / (options.grid - 1));
      if (options.gauss) {
        Eigen::VectorXd gp, gw;
        gauss_legendre(p.degrees[d] + 1, gp, gw);
        for (int g = 0; g < gp.size(); ++g) local.push_back(gp[g]);
      }
      std::sort(local.begin(), local.end());
      for (int e = 0; e < ne[d]; ++e)
        for (double t : local) {
          params[d].push_back(brk[e] + t * (brk[e + 1] - brk[e]));
          tag[d].push_back(e);
        }
    }
    const spline::GridEvaluation ev = spline::evaluate_grid(p, params, 1);
    const int nu = static_cast<int>(params[0].size()), nv = static_cast<int>(params[1].size()),
              nw = static_cast<int>(params[2].size());
    Values& val = values[pi];
    val.det.resize(static_cast<size_t>(nu) * nv * nw);
    val.scaled.resize(val.det.size());
    val.cond.resize(val.det.size());
    std::vector<QualityPoint> worst(static_cast<size_t>(ne[0]) * ne[1] * ne[2]);
    for (auto& q : worst) q.scaled_jacobian = std::numeric_limits<double>::infinity();
    long singular = 0;
    for (int k = 0; k < nw; ++k)
      for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
          const long at = i + static_cast<long>(nu) * (j + static_cast<long>(nv) * k);
          Eigen::Matrix3d J;
          for (int c = 0; c < 3; ++c)
            for (int d = 0; d < 3; ++d) J(c, d) = ev.jacobians(at, 3 * c + d);
          const double det = J.determinant(), sj = scaled_jacobian(J), cn = condition_number(J);
          if (!std::isfinite(cn)) ++singular;
          val.det[at] = det;
          val.scaled[at] = sj;
          val.cond[at] = cn;
          const int e = tag[0][i] + ne[0] * (tag[1][j] + ne[1] * tag[2][k]);
          QualityPoint& q = worst[e];
          if (sj < q.scaled_jacobian) {
            q.patch = static_cast<int>(pi);
            q.element = {{tag[0][i], tag[1][j], tag[2][k]}};
            q.uvw = Eigen::Vector3d(params[0][i], params[1][j], params[2][k]);
            q.x = ev.points.row(at).transpose();
            q.det_j = det;
            q.scaled_jacobian = sj;
            q.condition = cn;
          }
        }
    element_worst.insert(element_worst.end(), worst.begin(), worst.end());
    PatchQuality pq;
    pq.patch = static_cast<int>(pi);
    pq.points = static_cast<long>(val.det.size());
    pq.singular_points = singular;
    report.patches.push_back(pq);
  }
  const auto det_range = finite_range(values, &Values::det);
  const auto cond_range = finite_range(values, &Values::cond);
  const int bins = options.histogram_bins;
  Values all;
  for (size_t pi = 0; pi < values.size(); ++pi) {
    PatchQuality& pq = report.patches[pi];
    pq.det_j = stats(values[pi].det, det_range.first, det_range.second, bins);
    pq.scaled_jacobian = stats(values[pi].scaled, -1.0, 1.0, bins);
    pq.condition = stats(values[pi].cond, cond_range.first, cond_range.second, bins);
    all.det.insert(all.det.end(), values[pi].det.begin(), values[pi].det.end());
    all.scaled.insert(all.scaled.end(), values[pi].scaled.begin(), values[pi].scaled.end());
    all.cond.insert(all.cond.end(), values[pi].cond.begin(), values[pi].cond.end());
    report.overall.points += pq.points;
    report.overall.singular_points += pq.singular_points;
  }
  report.overall.det_j = stats(all.det, det_range.first, det_range.second, bins);
  report.overall.scaled_jacobian = stats(all.scaled, -1.0, 1.0, bins);
  report.overall.condition = stats(all.cond, cond_range.first, cond_range.second, bins);
  // Stable order: by scaled Jacobian, ties by patch and element.
  std::stable_sort(element_worst.begin(), element_worst.end(), [](const QualityPoint& a, const QualityPoint& b) {
    return a.scaled_jacobian < b.scaled_jacobian;
  });
  if (static_cast<int>(element_worst.size()) > options.worst_count) element_worst.resize(options.worst_count);
  report.worst = element_worst;
  return report;
}

}  // namespace igaprep::iga_check
