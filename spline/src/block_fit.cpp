#include "igaprep/spline/block_fit.h"

#include <array>
#include <string>

#include "igaprep/core/error.h"
#include "igaprep/spline/fit.h"
#include "igaprep/spline/knot_vector.h"

namespace igaprep::spline {

namespace {

std::vector<double> block_knots(const BlockFitOptions& o) {
  if (o.degree < 1 || o.elements < 1 || o.oversample < 1)
    throw bad_input("block fit: degree, elements and oversample must be at least 1");
  return uniform_knot_vector(o.degree, o.elements + o.degree);
}

// A direction that is not fitted (a point of an edge or a face): degree 0, one control point.
const std::vector<double> kPointKnots{0.0, 1.0};
const std::vector<double> kPointParam{0.5};

}  // namespace

std::vector<double> block_sample_params(const BlockFitOptions& options) {
  const std::vector<double> g = greville_abscissae(block_knots(options), options.degree);
  std::vector<double> out;
  for (std::size_t i = 0; i + 1 < g.size(); ++i)
    for (int k = 0; k < options.oversample; ++k)
      out.push_back(g[i] + (g[i + 1] - g[i]) * k / options.oversample);
  out.push_back(1.0);
  out.front() = 0.0;  // exact ends: the sides are sampled at exactly 0 and 1
  return out;
}

Patch fit_block(const Eigen::MatrixXd& samples, const BlockFitOptions& options) {
  const std::vector<double> U = block_knots(options);
  const std::vector<double> g = block_sample_params(options);
  const int p = options.degree;
  const int m = static_cast<int>(g.size());
  const int n = options.elements + p;
  if (samples.rows() != static_cast<Eigen::Index>(m) * m * m || samples.cols() != 3)
    throw bad_input("block fit: expected " + std::to_string(m * m * m) + " x 3 samples, got " +
                    std::to_string(samples.rows()) + " x " + std::to_string(samples.cols()));
  auto sample = [&](int i, int j, int k) { return samples.row(i + m * (j + m * k)); };
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n) * n * n, 3);
  std::vector<char> known(static_cast<std::size_t>(n) * n * n, 0);
  auto cp = [&](int i, int j, int k) { return i + n * (j + n * k); };

  for (int c = 0; c < 8; ++c) {
    const int i = (c & 1) ? n - 1 : 0, j = (c & 2) ? n - 1 : 0, k = (c & 4) ? n - 1 : 0;
    P.row(cp(i, j, k)) = sample((c & 1) ? m - 1 : 0, (c & 2) ? m - 1 : 0, (c & 4) ? m - 1 : 0);
    known[static_cast<std::size_t>(cp(i, j, k))] = 1;
  }
  // Fits the sub-grid where the directions in `free` vary and the others sit
  // at the given end (0 or max), with every control point already known fixed.
  auto fit_part = [&](const std::array<bool, 3>& free, const std::array<int, 3>& end) {
    std::array<int, 3> deg, nn, mm;
    std::array<std::vector<double>, 3> knots, params;
    for (int d = 0; d < 3; ++d) {
      deg[d] = free[d] ? p : 0;
      knots[d] = free[d] ? U : kPointKnots;
      params[d] = free[d] ? g : kPointParam;
      nn[d] = free[d] ? n : 1;
      mm[d] = free[d] ? m : 1;
    }
    auto cp_index = [&](int a, int b, int c) {
      const int ijk[3] = {a, b, c};
      int full[3];
      for (int d = 0; d < 3; ++d) full[d] = free[d] ? ijk[d] : (end[d] ? n - 1 : 0);
      return cp(full[0], full[1], full[2]);
    };
    Eigen::MatrixXd S(static_cast<Eigen::Index>(mm[0]) * mm[1] * mm[2], 3);
    for (int c = 0; c < mm[2]; ++c)
      for (int b = 0; b < mm[1]; ++b)
        for (int a = 0; a < mm[0]; ++a) {
          const int ijk[3] = {a, b, c};
          int full[3];
          for (int d = 0; d < 3; ++d) full[d] = free[d] ? ijk[d] : (end[d] ? m - 1 : 0);
          S.row(a + mm[0] * (b + mm[1] * c)) = sample(full[0], full[1], full[2]);
        }
    FixedControlPoints fixed;
    std::vector<int> local;
    for (int c = 0; c < nn[2]; ++c)
      for (int b = 0; b < nn[1]; ++b)
        for (int a = 0; a < nn[0]; ++a)
          if (known[static_cast<std::size_t>(cp_index(a, b, c))]) {
            fixed.indices.push_back(a + nn[0] * (b + nn[1] * c));
            local.push_back(cp_index(a, b, c));
          }
    fixed.values.resize(static_cast<Eigen::Index>(local.size()), 3);
    for (std::size_t r = 0; r < local.size(); ++r) fixed.values.row(static_cast<Eigen::Index>(r)) = P.row(local[r]);
    const Patch part = fit_grid(deg, knots, params, S, fixed);
    for (int c = 0; c < nn[2]; ++c)
      for (int b = 0; b < nn[1]; ++b)
        for (int a = 0; a < nn[0]; ++a) {
          const int id = cp_index(a, b, c);
          if (known[static_cast<std::size_t>(id)]) continue;
          P.row(id) = part.control_points.row(a + nn[0] * (b + nn[1] * c));
          known[static_cast<std::size_t>(id)] = 1;
        }
  };
  for (int d = 0; d < 3; ++d)  // the 12 edges
    for (int e = 0; e < 4; ++e) {
      std::array<bool, 3> free{{false, false, false}};
      free[d] = true;
      std::array<int, 3> end{{0, 0, 0}};
      end[(d + 1) % 3] = e & 1;
      end[(d + 2) % 3] = (e >> 1) & 1;
      fit_part(free, end);
    }
  for (int d = 0; d < 3; ++d)  // the 6 faces, normal to d
    for (int e = 0; e < 2; ++e) {
      std::array<bool, 3> free{{true, true, true}};
      free[d] = false;
      std::array<int, 3> end{{0, 0, 0}};
      end[d] = e;
      fit_part(free, end);
    }
  fit_part({{true, true, true}}, {{0, 0, 0}});

  Patch out;
  out.degrees = {p, p, p};
  out.knots = {U, U, U};
  out.control_points = std::move(P);
  return out;
}

}  // namespace igaprep::spline
