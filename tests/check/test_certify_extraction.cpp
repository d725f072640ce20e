// The certificate on a model in extraction form (issue 18: `check` on
// T-splines certifies every Bezier element): the same status and bounds as
// on the multipatch it came from, a folded element found, bad input refused.
#include <gtest/gtest.h>

#include "check/check_models.h"
#include "igaprep/core/error.h"
#include "igaprep/iga_check/jacobian_certificate.h"
#include "igaprep/spline/extraction_model.h"
#include "igaprep/spline/refine.h"

namespace {
using namespace igaprep::iga_check;
namespace spline = igaprep::spline;

void expect_same_certificates(const spline::MultiPatch& mp) {
  const std::vector<ElementCertificate> patches = certify_model(mp);
  const std::vector<ElementCertificate> elements = certify_extraction_model(spline::extraction_model(mp));
  ASSERT_EQ(elements.size(), patches.size());
  for (std::size_t i = 0; i < patches.size(); ++i) {
    EXPECT_EQ(elements[i].patch, patches[i].patch);
    EXPECT_EQ(elements[i].element, patches[i].element);
    EXPECT_EQ(elements[i].status, patches[i].status) << "element " << i;
    const double scale = std::max(1.0, std::abs(patches[i].lower_bound));
    EXPECT_NEAR(elements[i].lower_bound, patches[i].lower_bound, 1e-12 * scale) << "element " << i;
    EXPECT_NEAR(elements[i].upper_bound, patches[i].upper_bound, 1e-12 * scale) << "element " << i;
  }
}

TEST(CertifyExtraction, TheSameCertificatesAsTheMultipatch) {
  expect_same_certificates(check_test::sphere_shell(0.5, 1.0));  // NURBS, degenerate poles
  spline::MultiPatch folded;
  auto fold = [](const Eigen::Vector3d& t) { return Eigen::Vector3d(t[0] + 3.0 * t[0] * (1 - t[0]) * t[1], t[1], t[2]); };
  folded.patches.push_back(spline::refine_uniformly(check_test::bezier_patch(fold, {{2, 2, 2}}), 1));
  folded.materials = {{"m", 1.0, 0.3}};
  expect_same_certificates(folded);
  const auto c = certify_extraction_model(spline::extraction_model(folded));
  EXPECT_TRUE(std::any_of(c.begin(), c.end(), [](const ElementCertificate& e) { return e.status == ElementStatus::Negative; }));
}

TEST(CertifyExtraction, DegreeZeroAndBadWeightsAreRefused) {
  spline::ExtractionModel m = spline::extraction_model(check_test::sphere_shell(0.5, 1.0));
  spline::ExtractionModel zero = m;
  zero.elements[0].degrees[1] = 0;
  EXPECT_THROW(certify_extraction_model(zero), igaprep::Error);
  m.weights[3] = -1.0;
  EXPECT_THROW(certify_extraction_model(m), igaprep::Error);
}

}  // namespace
