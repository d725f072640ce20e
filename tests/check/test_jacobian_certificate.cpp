// Certified Jacobian sign: exactness of the Bernstein numerator, positive,
// folded, hidden-negative and collapsed-face volumes.
#include <gtest/gtest.h>

#include <cmath>
#include <Eigen/LU>
#include <random>

#include "check/check_models.h"
#include "igaprep/core/error.h"
#include "igaprep/iga_check/jacobian_certificate.h"
#include "igaprep/iga_check/report.h"
#include "igaprep/spline/bezier_extraction.h"
#include "igaprep/spline/evaluate.h"
#include "igaprep/spline/refine.h"

using namespace igaprep;
using namespace igaprep::iga_check;
using check_test::bezier_patch;

namespace {

double detj(const spline::Patch& p, const Eigen::Vector3d& u) {
  return spline::evaluate_jacobian(p, u).determinant();
}

// min det J over a regular n^3 grid of each element.
double sampled_min(const spline::Patch& p, const ElementCertificate& c, const spline::PatchExtraction& ex, int n) {
  double m = 1e300;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int idx[3] = {i, j, k};
        Eigen::Vector3d u;
        for (int d = 0; d < 3; ++d) {
          const auto& b = ex.dirs[d].breaks;
          const int e = c.element[d];
          u[d] = b[e] + (b[e + 1] - b[e]) * idx[d] / (n - 1);
        }
        m = std::min(m, detj(p, u));
      }
  return m;
}

void expect_numerator_matches(const spline::Patch& p) {
  const spline::PatchExtraction ex = spline::bezier_extraction(p);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int e = 0; e < std::min(ex.element_count(0), 2); ++e) {
    const spline::BezierElement el = spline::bernstein_control_points(p, ex, e, 0, 0);
    const Bernstein3 N = jacobian_numerator(el, p.degrees);
    for (int d = 0; d < 3; ++d) EXPECT_EQ(N.degree[d], (p.rational() ? 4 : 3) * p.degrees[d] - 1);
    double h = 1.0;
    for (int d = 0; d < 3; ++d) h *= el.domain[d][1] - el.domain[d][0];
    for (int s = 0; s < 20; ++s) {
      const Eigen::Vector3d t(U(rng), U(rng), U(rng));
      Eigen::Vector3d u;
      for (int d = 0; d < 3; ++d) u[d] = el.domain[d][0] + t[d] * (el.domain[d][1] - el.domain[d][0]);
      double w4 = 1.0;
      if (p.rational()) {
        Bernstein3 w(p.degrees);
        for (int i = 0; i < el.weights.size(); ++i) w.coeffs[i] = el.weights[i];
        w4 = std::pow(bernstein_evaluate(w, t), 4);
      }
      const double expect = detj(p, u);
      EXPECT_NEAR(bernstein_evaluate(N, t) / (h * w4), expect, 1e-10 * std::max(1.0, std::abs(expect)));
    }
  }
}

}  // namespace

TEST(Bernstein3, ProductAndSubdivisionAreExact) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  Bernstein3 a(std::array<int, 3>{{2, 1, 3}}), b(std::array<int, 3>{{1, 2, 2}});
  for (double& c : a.coeffs) c = U(rng);
  for (double& c : b.coeffs) c = U(rng);
  const Bernstein3 ab = bernstein_product(a, b);
  ASSERT_EQ(ab.degree, (std::array<int, 3>{{3, 3, 5}}));
  Bernstein3 lo, hi;
  bernstein_subdivide(ab, 1, 0.3, &lo, &hi);
  for (int s = 0; s < 20; ++s) {
    const Eigen::Vector3d t(0.5 * (U(rng) + 1), 0.5 * (U(rng) + 1), 0.5 * (U(rng) + 1));
    const double expect = bernstein_evaluate(a, t) * bernstein_evaluate(b, t);
    EXPECT_NEAR(bernstein_evaluate(ab, t), expect, 1e-13);
    Eigen::Vector3d tl = t, th = t;
    tl[1] = 0.3 * t[1];
    th[1] = 0.3 + 0.7 * t[1];
    EXPECT_NEAR(bernstein_evaluate(lo, t), bernstein_evaluate(ab, tl), 1e-13);
    EXPECT_NEAR(bernstein_evaluate(hi, t), bernstein_evaluate(ab, th), 1e-13);
  }
}

TEST(JacobianCertificate, NumeratorEqualsDeterminantPolynomialAndRational) {
  spline::Patch twisted = spline::refine_uniformly(bezier_patch(check_test::twisted, {{3, 3, 3}}), 1);
  expect_numerator_matches(twisted);
  spline::Patch annulus = spline::refine_uniformly(
      spline::elevate_degree(spline::elevate_degree(check_test::quarter_annulus(), 1), 2), 1);
  ASSERT_TRUE(annulus.rational());
  expect_numerator_matches(annulus);
}

TEST(JacobianCertificate, SmoothVolumesCertifiedPositive) {
  const spline::Patch twisted = spline::refine_uniformly(bezier_patch(check_test::twisted, {{3, 3, 3}}), 2);
  const spline::Patch annulus = spline::refine_uniformly(
      spline::elevate_degree(spline::elevate_degree(check_test::quarter_annulus(), 1), 2), 2);
  for (const spline::Patch* p : {&twisted, &annulus}) {
    const auto certs = certify_patch(*p, 0);
    const spline::PatchExtraction ex = spline::bezier_extraction(*p);
    ASSERT_EQ(static_cast<int>(certs.size()), ex.element_count());
    ASSERT_EQ(ex.element_count(), 27);
    for (const auto& c : certs) {
      EXPECT_EQ(c.status, ElementStatus::Positive)
          << (p->rational() ? "annulus " : "twisted ") << to_string(c.status) << " at " << c.location.transpose()
          << " value " << c.upper_bound << " det there " << detj(*p, c.location);
      EXPECT_GT(c.lower_bound, 0.0);
      const double smin = sampled_min(*p, c, ex, 5);
      EXPECT_LE(c.lower_bound, smin * (1 + 1e-12));
      EXPECT_LE(c.lower_bound, c.upper_bound);
      EXPECT_NEAR(c.upper_bound, detj(*p, c.location), 1e-9 * std::abs(c.upper_bound));
    }
  }
}

TEST(JacobianCertificate, FoldedCubeCertifiedNegativeInsideFold) {
  // det J = 1 + 3 (1 - 2u) v: negative where (1 - 2u) v < -1/3 (near u = 1, v = 1).
  auto fold = [](const Eigen::Vector3d& t) {
    return Eigen::Vector3d(t[0] + 3.0 * t[0] * (1 - t[0]) * t[1], t[1], t[2]);
  };
  auto det = [](const Eigen::Vector3d& u) { return 1.0 + 3.0 * (1 - 2 * u[0]) * u[1]; };
  const spline::Patch p = spline::refine_uniformly(bezier_patch(fold, {{2, 2, 2}}), 1);
  const auto certs = certify_patch(p, 0);
  int negative = 0;
  for (const auto& c : certs) {
    if (c.status != ElementStatus::Negative) continue;
    ++negative;
    EXPECT_LT(det(c.location), 0.0) << "location " << c.location.transpose();
    EXPECT_LT(detj(p, c.location), 0.0);
    EXPECT_NEAR(c.upper_bound, det(c.location), 1e-10);
    EXPECT_LE(c.lower_bound, c.upper_bound);
  }
  // det J is bilinear in (u, v): an element folds exactly when a corner value is negative.
  int expected = 0;
  for (const auto& c : certs) {
    double corner_min = 1e300;
    for (double u : {0.5 * c.element[0], 0.5 * c.element[0] + 0.5})
      for (double v : {0.5 * c.element[1], 0.5 * c.element[1] + 0.5}) corner_min = std::min(corner_min, det({u, v, 0}));
    EXPECT_EQ(c.status, corner_min < 0 ? ElementStatus::Negative : ElementStatus::Positive);
    expected += corner_min < 0;
  }
  EXPECT_EQ(negative, expected);
  EXPECT_EQ(negative, 4);  // u in [1/2, 1]: 2 elements along v, 2 along w
}

TEST(JacobianCertificate, NegativeBetweenSamplesIsNotCertifiedPositive) {
  // det J = 1 - A h(u) s(v) s(w), h = 4u - 16u^2 (> 0 only for u in (0, 1/4),
  // <= 0 at every u of the 5-point grid), s = t(1 - t): at grid points det J >= 1,
  // but near (1/8, 1/2, 1/2) det J = 1 - 1.05 < 0.
  const double A = 1.05 / (0.25 * 0.0625);
  auto hidden = [A](const Eigen::Vector3d& t) {
    const double u = t[0], H = 2 * u * u - 16.0 * u * u * u / 3.0;
    return Eigen::Vector3d(u - A * H * t[1] * (1 - t[1]) * t[2] * (1 - t[2]), t[1], t[2]);
  };
  auto det = [A](const Eigen::Vector3d& u) {
    return 1.0 - A * (4 * u[0] - 16 * u[0] * u[0]) * u[1] * (1 - u[1]) * u[2] * (1 - u[2]);
  };
  const spline::Patch p = bezier_patch(hidden, {{3, 2, 2}});
  // Sampling alone sees only positive values.
  double smin = 1e300;
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 5; ++i) smin = std::min(smin, detj(p, Eigen::Vector3d(i / 4.0, j / 4.0, k / 4.0)));
  EXPECT_GE(smin, 1.0 - 1e-9);
  EXPECT_NEAR(detj(p, Eigen::Vector3d(0.125, 0.5, 0.5)), -0.05, 1e-9);
  const auto certs = certify_patch(p, 0);
  ASSERT_EQ(certs.size(), 1u);
  EXPECT_NE(certs[0].status, ElementStatus::Positive);
  EXPECT_EQ(certs[0].status, ElementStatus::Negative);
  EXPECT_LT(det(certs[0].location), 0.0);
  EXPECT_LT(certs[0].lower_bound, 0.0);
}

TEST(JacobianCertificate, CollapsedFaceIsDegenerateNotNegative) {
  // The face u = 1 collapses onto the edge y = 1/2: det J = 1 - u.
  auto wedge = [](const Eigen::Vector3d& t) {
    return Eigen::Vector3d(t[0], (1 - t[0]) * t[1] + 0.5 * t[0], t[2]);
  };
  for (int refine : {0, 1}) {
    const spline::Patch p = spline::refine_uniformly(bezier_patch(wedge, {{2, 2, 2}}), refine);
    const auto certs = certify_patch(p, 0);
    for (const auto& c : certs) {
      const bool touches = refine == 0 || c.element[0] == 1;
      EXPECT_EQ(c.status, touches ? ElementStatus::Degenerate : ElementStatus::Positive)
          << "element " << c.element[0] << " " << c.element[1] << " " << c.element[2] << ": " << to_string(c.status);
      if (touches) {
        EXPECT_NEAR(c.lower_bound, 0.0, 1e-12);
        EXPECT_NEAR(c.upper_bound, 0.0, 1e-12);
        EXPECT_NEAR(c.location[0], 1.0, 1e-12);
      }
    }
  }
}

TEST(JacobianCertificate, RejectsNonPositiveWeight) {
  spline::Patch p = check_test::quarter_annulus();
  p.weights[1] = -0.5;
  EXPECT_THROW(certify_patch(p, 3), igaprep::Error);
}

TEST(JacobianCertificate, InteriorZeroIsUndecidedNotDegenerate) {
  // det J = 3 (u - 1/2)^2: zero on the interior plane u = 1/2, never negative.
  // Neither positive nor degenerate (the zero is not on the element boundary).
  auto cubic = [](const Eigen::Vector3d& t) {
    return Eigen::Vector3d(std::pow(t[0] - 0.5, 3), t[1], t[2]);
  };
  const spline::Patch p = bezier_patch(cubic, {{3, 1, 1}});
  CertifyOptions opt;
  opt.max_depth = 10;
  opt.max_boxes = 200;
  const auto certs = certify_patch(p, 0, opt);
  ASSERT_EQ(certs.size(), 1u);
  EXPECT_EQ(certs[0].status, ElementStatus::Undecided);
  EXPECT_LE(certs[0].lower_bound, 0.0);
  EXPECT_GE(certs[0].upper_bound, -1e-12);
  EXPECT_LE(certs[0].boxes, opt.max_boxes);
  // An element that vanishes identically (all control points equal along w).
  auto flat = [](const Eigen::Vector3d& t) { return Eigen::Vector3d(t[0], t[1], 0.0); };
  const auto flat_certs = certify_patch(bezier_patch(flat, {{1, 1, 1}}), 0);
  EXPECT_EQ(flat_certs[0].status, ElementStatus::Undecided);
}

// Issue 21, item 5: control points near the largest double make det J
// overflow; such an element is undecided (it fails), never degenerate, so
// --allow-degenerate cannot pass it.
TEST(JacobianCertificate, AnOverflowingJacobianIsUndecidedNotDegenerate) {
  spline::MultiPatch mp =
      check_test::single(spline::refine_uniformly(bezier_patch(check_test::twisted, {{3, 3, 3}}), 1));
  mp.patches[0].control_points *= 1e307;
  const auto certs = certify_patch(mp.patches[0], 0);
  ASSERT_EQ(certs.size(), 8u);
  for (const auto& c : certs) EXPECT_EQ(c.status, ElementStatus::Undecided) << to_string(c.status);
  CheckOptions opt;
  opt.allow_degenerate = true;
  const CheckReport r = build_check_report(mp, {}, {}, opt, "huge");
  EXPECT_FALSE(r.passed);
  EXPECT_EQ(r.verdict.rfind("FAIL: jacobian: patches 0 not certified positive (0 negative, 0 degenerate allowed, 8 "
                            "undecided elements)",
                            0),
            0u)
      << r.verdict;
  EXPECT_NE(report_json(r).find("\"lower_bound\": null"), std::string::npos);
}

// Issue 21, item 6: a degree the certificate cannot afford is refused first.
TEST(JacobianCertificate, ADegreeAboveTheLimitIsRefusedBeforeAnyWork) {
  const spline::Patch p = bezier_patch(check_test::twisted, {{12, 3, 3}});
  try {
    certify_patch(p, 4);
    ADD_FAILURE() << "no error";
  } catch (const igaprep::Error& e) {
    EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput);
    EXPECT_NE(std::string(e.what()).find("patch 4: degree 12 in direction 0 is above the certificate's limit of 10 "
                                         "(CertifyOptions::max_degree): det J would have 46656 coefficients"),
              std::string::npos)
        << e.what();
  }
  CertifyOptions raised;
  raised.max_degree = 12;
  EXPECT_EQ(certify_patch(p, 4, raised).at(0).status, ElementStatus::Positive);
}
