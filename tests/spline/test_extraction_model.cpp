// The extraction form of a conforming multipatch (issue 18): the same
// geometry, a partition of unity on every element, linearly independent
// functions, the labelled faces, and a non-conforming model refused.
#include <gtest/gtest.h>

#include <Eigen/QR>
#include <random>

#include "igaprep/core/error.h"
#include "igaprep/spline/bezier_extraction.h"
#include "igaprep/spline/evaluate.h"
#include "igaprep/spline/extraction_model.h"
#include "igaprep/spline/multipatch_topology.h"
#include "spline_test_util.h"

using namespace spline_test;

namespace {

// Two glued NURBS patches with their free sides labelled 0 (u0 of patch 0: label 1).
MultiPatch labelled_model(std::mt19937& rng) {
  MultiPatch mp = glued_patches(rng);
  mp.labels = {"outer", "inlet"};
  for (const Side s : Side::all()) {
    if (s != kU1) mp.boundaries.push_back({0, s, s == kU0 ? 1 : 0});
    if (s != kW0) mp.boundaries.push_back({1, s, 0});
  }
  return mp;
}

TEST(ExtractionModel, ReproducesTheMultipatchAtRandomPoints) {
  std::mt19937 rng(11);
  const MultiPatch mp = labelled_model(rng);
  const ExtractionModel m = extraction_model(mp);
  EXPECT_EQ(m.function_count(), global_numbering(mp).count);
  EXPECT_TRUE(m.rational());
  // 1,000 random points per patch, each in the element that holds it.
  double worst = 0.0;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int p = 0; p < static_cast<int>(mp.patches.size()); ++p) {
    std::vector<int> elements;
    for (int e = 0; e < static_cast<int>(m.elements.size()); ++e)
      if (m.elements[static_cast<std::size_t>(e)].patch == p) elements.push_back(e);
    ASSERT_EQ(static_cast<int>(elements.size()), bezier_extraction(mp.patches[static_cast<std::size_t>(p)]).element_count());
    for (int s = 0; s < 1000; ++s) {
      const int e = elements[static_cast<std::size_t>(s) % elements.size()];
      const ExtractionElement& el = m.elements[static_cast<std::size_t>(e)];
      const Eigen::Vector3d t(unit(rng), unit(rng), unit(rng));
      Eigen::Vector3d xi;
      for (int d = 0; d < 3; ++d) xi[d] = el.domain[d][0] + t[d] * (el.domain[d][1] - el.domain[d][0]);
      worst = std::max(worst, (evaluate_element(m, e, t) - evaluate_point(mp.patches[static_cast<std::size_t>(p)], xi)).norm());
    }
  }
  EXPECT_LT(worst, 1e-12 * diagonal(mp));
}

TEST(ExtractionModel, PartitionOfUnityAndLinearIndependence) {
  std::mt19937 rng(12);
  const ExtractionModel m = extraction_model(labelled_model(rng));
  // Each Bernstein polynomial's coefficients over the element's functions sum to 1.
  double worst = 0.0;
  Eigen::Index rows = 0;
  for (int e = 0; e < static_cast<int>(m.elements.size()); ++e) {
    worst = std::max(worst, (m.C(e).colwise().sum().array() - 1.0).abs().maxCoeff());
    rows += m.C(e).cols();
  }
  EXPECT_LT(m.operators.size(), m.elements.size());  // shared by elements with one knot pattern
  EXPECT_LT(worst, 1e-14);
  // The functions restricted to every element, stacked: full column rank.
  Eigen::MatrixXd stacked = Eigen::MatrixXd::Zero(rows, m.function_count());
  Eigen::Index at = 0;
  for (int e = 0; e < static_cast<int>(m.elements.size()); ++e) {
    const Eigen::MatrixXd& C = m.C(e);
    const std::vector<int>& functions = m.elements[static_cast<std::size_t>(e)].functions;
    for (std::size_t r = 0; r < functions.size(); ++r)
      stacked.block(at, functions[r], C.cols(), 1) += C.row(static_cast<Eigen::Index>(r)).transpose();
    at += C.cols();
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(stacked);
  qr.setThreshold(1e-10);
  EXPECT_EQ(qr.rank(), m.function_count());
}

TEST(ExtractionModel, LabelledFacesAreTheElementFacesOnTheSides) {
  std::mt19937 rng(13);
  const MultiPatch mp = labelled_model(rng);
  const ExtractionModel m = extraction_model(mp);
  std::size_t expected = 0;
  for (const BoundarySide& b : mp.boundaries) {
    const PatchExtraction ex = bezier_extraction(mp.patches[static_cast<std::size_t>(b.patch)]);
    std::size_t n = 1;
    for (const int d : b.side.tangent_directions()) n *= static_cast<std::size_t>(ex.element_count(d));
    expected += n;
  }
  ASSERT_EQ(m.boundary_faces.size(), expected);
  // Each face's element touches the patch side it came from.
  for (const ExtractionBoundaryFace& f : m.boundary_faces) {
    const ExtractionElement& e = m.elements[static_cast<std::size_t>(f.element)];
    const Patch& p = mp.patches[static_cast<std::size_t>(e.patch)];
    const double end = f.side.parameter() ? p.knots[f.side.direction()].back() : p.knots[f.side.direction()].front();
    EXPECT_EQ(e.domain[f.side.direction()][f.side.parameter() ? 1 : 0], end);
    if (f.side == kU0 && e.patch == 0) EXPECT_EQ(f.label, 1);
  }
}

TEST(ExtractionModel, ANonConformingModelIsRefused) {
  std::mt19937 rng(14);
  MultiPatch mp = glued_patches(rng);
  const auto pairs = interface_point_pairs(mp, mp.interfaces[0]);
  mp.patches[1].control_points.row(pairs[3].second) += Eigen::RowVector3d(0.01, 0, 0);
  EXPECT_THROW(extraction_model(mp), igaprep::Error);
  EXPECT_THROW(extraction_model(MultiPatch{}), igaprep::Error);
}

}  // namespace
