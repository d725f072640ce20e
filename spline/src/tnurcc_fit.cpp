#include "igaprep/spline/tnurcc_fit.h"

#include <Eigen/SparseCholesky>
#include <cmath>

#include "igaprep/core/error.h"

namespace igaprep::spline {
namespace {

// Row i: point i minus the mean of its edge neighbours: the fairing term
// pulls each point towards its neighbours' mean.
StencilMatrix umbrella_laplacian(const Cage& cage) {
  const std::vector<int> valence = vertex_valences(cage);
  std::vector<Eigen::Triplet<double>> t;
  for (int v = 0; v < cage.points.rows(); ++v) t.emplace_back(v, v, 1.0);
  for (const auto& e : cage.edges) {
    const int a = e.vertices[0], b = e.vertices[1];
    t.emplace_back(a, b, -1.0 / valence[a]);
    t.emplace_back(b, a, -1.0 / valence[b]);
  }
  StencilMatrix L(cage.points.rows(), cage.points.rows());
  L.setFromTriplets(t.begin(), t.end());
  return L;
}

struct PairSystem {
  StencilMatrix A;          // limit stencils of the pairs' locations
  Eigen::MatrixXd targets;  // one row per pair
};

PairSystem pair_system(const Cage& cage, const FitPairsFn& pairs, const LimitOptions& limit) {
  const std::vector<FitPair> p = pairs(cage);
  if (p.empty()) throw bad_input("T-NURCC fit: no point pairs to fit");
  std::vector<LimitLocation> at(p.size());
  PairSystem s;
  s.targets.resize(static_cast<int>(p.size()), 3);
  for (size_t i = 0; i < p.size(); ++i) {
    at[i] = p[i].at;
    s.targets.row(static_cast<int>(i)) = p[i].target.transpose();
  }
  s.A = limit_stencils(cage, at, values_only(limit)).value;
  return s;
}

double rms(const Eigen::MatrixXd& residual) { return std::sqrt(residual.squaredNorm() / residual.rows()); }

}  // namespace

CageFitResult fit_cage(const Cage& start, const FitPairsFn& pairs, const CageFitOptions& options) {
  CageFitResult r;
  r.cage = start;
  const StencilMatrix L = umbrella_laplacian(start);
  const Eigen::SparseMatrix<double> LtL = Eigen::SparseMatrix<double>(L.transpose()) * L;
  PairSystem s = pair_system(r.cage, pairs, options.limit);
  Eigen::MatrixXd residual = s.targets - s.A * r.cage.points;
  r.rms.push_back(rms(residual));
  for (int it = 0; it < options.iterations; ++it) {
    const double lambda = options.smoothing * double(s.A.rows()) / double(r.cage.points.rows());
    const Eigen::SparseMatrix<double> At = s.A.transpose();
    const Eigen::SparseMatrix<double> N = At * s.A + lambda * LtL;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(N);
    if (solver.info() != Eigen::Success) throw internal_error("T-NURCC fit: the normal equations did not factorize");
    const Eigen::MatrixXd rhs = At * residual - lambda * (LtL * r.cage.points);
    const Eigen::MatrixXd step = solver.solve(rhs);
    r.cage.points += step;
    ++r.iterations;
    s = pair_system(r.cage, pairs, options.limit);
    residual = s.targets - s.A * r.cage.points;
    const double now = rms(residual), before = r.rms.back();
    r.rms.push_back(now);
    if (std::abs(before - now) < options.stop_improvement * before) break;
  }
  return r;
}

}  // namespace igaprep::spline
