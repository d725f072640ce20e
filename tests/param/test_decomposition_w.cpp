// The w-field on H (seed paper, section 5.1): 0 on T1, (i - 1)/n on Ti, 1 on
// M, harmonic elsewhere.
#include <gtest/gtest.h>

#include <cmath>

#include "decomposition_cache.h"

using namespace igaprep::param;

namespace {
class WFieldTest : public ::testing::TestWithParam<std::string> {};
}  // namespace

TEST_P(WFieldTest, BoundaryValuesRangeAndMaximumPrinciple) {
  const auto& c = decomposition_test::cached(GetParam());
  const auto& H = c.H;
  const auto& W = c.w;
  const auto& model = c.mid->model;
  const int n = static_cast<int>(model.surfaces.size());
  ASSERT_EQ(n, 2);
  ASSERT_EQ(W.w.size(), H.tets.V.rows());

  // Dirichlet values at every vertex of every surface.
  const double expected[3] = {0.0, 0.5, 1.0};
  for (int k = 0; k <= n; ++k) {
    const Eigen::Index nk = k < n ? model.surfaces[k].V.rows() : c.base.m.mesh.V.rows();
    double err = 0.0;
    for (Eigen::Index i = 0; i < nk; ++i)
      err = std::max(err, std::abs(W.w(decomposition_vertex(H, k, static_cast<int>(i))) - expected[k]));
    EXPECT_LT(err, 1e-12) << "surface " << k;
  }

  // 0 <= w <= 1, and per material the range between its bounding surfaces:
  // material 0 (between T1 and T2) in [0, 1/2], material 1 (inside T2) in [1/2, 1].
  EXPECT_GE(W.w.minCoeff(), -1e-12);
  EXPECT_LE(W.w.maxCoeff(), 1.0 + 1e-12);
  double below = 0.0, above = 0.0;
  for (Eigen::Index t = 0; t < H.tets.T.rows(); ++t)
    for (int k = 0; k < 4; ++k) {
      const double v = W.w(H.tets.T(t, k));
      const double lo = H.tets.material(t) == 0 ? 0.0 : 0.5, hi = H.tets.material(t) == 0 ? 0.5 : 1.0;
      below = std::max(below, lo - v);
      above = std::max(above, v - hi);
    }
  EXPECT_LT(below, 1e-12);
  EXPECT_LT(above, 1e-12);

  // Harmonic: the residual of the free rows, relative to the diagonal.
  const Eigen::VectorXd r = W.K * W.w;
  double res = 0.0;
  for (Eigen::Index i = 0; i < r.size(); ++i)
    if (!W.is_dirichlet[static_cast<std::size_t>(i)]) res = std::max(res, std::abs(r(i)) / W.K.coeff(i, i));
  EXPECT_LT(res, 1e-8);

  // Maximum principle, recomputed here at the default tolerance (1e-12 of the
  // range). At tolerance 0 ring2 shows one "extremum": a TetGen point whose
  // neighbours all lie on M, where w = 1 + 6e-14 (round-off of an exactly
  // flat value, not a violation), so 0 is no meaningful tolerance.
  const auto strict = find_interior_extrema(W.K, W.w, W.is_dirichlet);
  std::printf("%s: w on %ld vertices (%d free, %d CG iterations), min %.3g max 1%+.2g, interior extrema %zu "
              "(tolerance 1e-9), %zu (tolerance 1e-12)\n",
              GetParam().c_str(), static_cast<long>(W.w.size()), W.num_free, W.cg_iterations, W.min_value,
              W.max_value - 1.0, W.extrema.size(), strict.size());
  EXPECT_EQ(W.extrema.size(), 0u);
  EXPECT_EQ(strict.size(), 0u);
  EXPECT_EQ(W.min_value, W.w.minCoeff());
  EXPECT_EQ(W.max_value, W.w.maxCoeff());
}

INSTANTIATE_TEST_SUITE_P(Models, WFieldTest, ::testing::Values("sphere2", "ring2"),
                         [](const auto& info) { return info.param; });
