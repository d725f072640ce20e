// The certificate on a model in extraction form (issue 18: `check` on
// T-splines certifies every Bezier element): the same status and bounds as
// on the multipatch it came from, a folded element found, bad input refused.
#include <gtest/gtest.h>

#include "check/check_models.h"
#include "igaprep/core/error.h"
#include "igaprep/core/parallel.h"
#include "igaprep/iga_check/quality_metrics.h"
#include "igaprep/iga_check/topology_checks.h"
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

namespace {
using namespace igaprep::iga_check;
namespace spline = igaprep::spline;

// Issue 22: the check's per-patch work runs on all cores; one thread or two
// give the same certificates and quality figures, bit for bit.
TEST(CheckThreads, OneOrTwoThreadsGiveTheSameReport) {
  const spline::MultiPatch mp = check_test::sphere_shell(0.5, 1.0);
  igaprep::set_thread_count(1);
  const std::vector<ElementCertificate> one = certify_model(mp);
  const QualityReport q_one = quality_metrics(mp);
  const TopologyReport t_one = topology_checks(mp, {}, 1.0, 1e-9);
  igaprep::set_thread_count(2);
  const std::vector<ElementCertificate> two = certify_model(mp);
  const QualityReport q_two = quality_metrics(mp);
  const TopologyReport t_two = topology_checks(mp, {}, 1.0, 1e-9);
  igaprep::set_thread_count(0);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].patch, two[i].patch);
    EXPECT_EQ(one[i].element, two[i].element);
    EXPECT_EQ(one[i].lower_bound, two[i].lower_bound);
    EXPECT_EQ(one[i].upper_bound, two[i].upper_bound);
  }
  EXPECT_EQ(q_one.overall.scaled_jacobian.mean, q_two.overall.scaled_jacobian.mean);
  EXPECT_EQ(t_one.patch_volumes, t_two.patch_volumes);
  EXPECT_EQ(t_one.material_volumes, t_two.material_volumes);
  EXPECT_GT(t_one.material_volumes[0], 0.0);
  EXPECT_EQ(q_one.overall.det_j.histogram.counts, q_two.overall.det_j.histogram.counts);
  ASSERT_EQ(q_one.worst.size(), q_two.worst.size());
  for (std::size_t i = 0; i < q_one.worst.size(); ++i) EXPECT_EQ(q_one.worst[i].det_j, q_two.worst[i].det_j);
}
}  // namespace
