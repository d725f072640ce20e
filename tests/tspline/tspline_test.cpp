// Trivariate T-splines (issue 18): analysis-suitable local refinement of
// cubic patches in index space, the blending functions it makes, and their
// Bezier extraction. Each refined model must keep the geometry (1e-12 of
// the diagonal at 1,000 random points per patch), be dual compatible after
// every step, hold a partition of unity on every element (1e-14) and have
// linearly independent functions (full rank of the stacked extraction).
#include <gtest/gtest.h>

#include <Eigen/SVD>
#include <random>

#include "igaprep/core/error.h"
#include "igaprep/core/parallel.h"
#include "igaprep/spline/basis.h"
#include "igaprep/spline/evaluate.h"
#include "igaprep/spline/extraction_model.h"
#include "igaprep/spline/multipatch_topology.h"
#include "igaprep/spline/tspline_functions.h"
#include "igaprep/spline/tspline_model.h"
#include "spline/spline_test_util.h"

using namespace spline_test;

namespace {

MultiPatch one_patch(std::mt19937& rng, bool rational) {
  MultiPatch mp;
  mp.patches = {random_patch(rng, {{3, 3, 3}}, {{7, 6, 5}}, rational, 1)};
  mp.labels = {"outer"};
  mp.materials = {Material{"steel", 210e3, 0.3}};
  for (const Side s : Side::all()) mp.boundaries.push_back({0, s, 0});
  return mp;
}

// glued_patches in cubics (patch 1 on the u1 face of patch 0, reoriented),
// every free side labelled.
MultiPatch two_patches(std::mt19937& rng) {
  MultiPatch mp = glued_patches(rng, {{3, 3, 3}}, {{6, 7, 5}}, {0, 0, 0, 0, 0.3, 0.6, 1, 1, 1, 1});
  mp.materials = {Material{"steel", 210e3, 0.3}};
  for (const Side s : Side::all()) {
    if (s != kU1) mp.boundaries.push_back({0, s, 0});
    if (s != kW0) mp.boundaries.push_back({1, s, 0});
  }
  return mp;
}

// The largest distance between the extraction model and the multipatch at
// 1,000 random points per patch, each in a random element of that patch.
double geometry_error(const ExtractionModel& m, const MultiPatch& mp, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0;
  for (int p = 0; p < static_cast<int>(mp.patches.size()); ++p) {
    std::vector<int> elements;
    for (int e = 0; e < static_cast<int>(m.elements.size()); ++e)
      if (m.elements[static_cast<std::size_t>(e)].patch == p) elements.push_back(e);
    std::uniform_int_distribution<std::size_t> pick(0, elements.size() - 1);
    for (int s = 0; s < 1000; ++s) {
      const int e = elements[pick(rng)];
      const ExtractionElement& el = m.elements[static_cast<std::size_t>(e)];
      const Eigen::Vector3d t(unit(rng), unit(rng), unit(rng));
      Eigen::Vector3d xi;
      for (int d = 0; d < 3; ++d) xi[d] = el.domain[d][0] + t[d] * (el.domain[d][1] - el.domain[d][0]);
      worst = std::max(worst, (evaluate_element(m, e, t) - evaluate_point(mp.patches[static_cast<std::size_t>(p)], xi)).norm());
    }
  }
  return worst;
}

// The largest |sum of a column of C_e - 1| over every element.
double partition_of_unity_error(const ExtractionModel& m) {
  double worst = 0.0;
  for (std::size_t e = 0; e < m.elements.size(); ++e)
    worst = std::max(worst, (m.C(static_cast<int>(e)).colwise().sum().array() - 1.0).abs().maxCoeff());
  return worst;
}

// Every function as the row of its Bernstein coefficients on all elements;
// the smallest singular value over the largest (0 for dependent functions).
double stacked_extraction_conditioning(const ExtractionModel& m) {
  Eigen::Index columns = 0;
  for (std::size_t e = 0; e < m.elements.size(); ++e) columns += m.C(static_cast<int>(e)).cols();
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(m.function_count(), columns);
  Eigen::Index at = 0;
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const Eigen::MatrixXd& C = m.C(static_cast<int>(e));
    for (std::size_t r = 0; r < m.elements[e].functions.size(); ++r)
      S.block(m.elements[e].functions[r], at, 1, C.cols()) = C.row(static_cast<Eigen::Index>(r));
    at += C.cols();
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(S);
  return svd.singularValues().minCoeff() / svd.singularValues().maxCoeff();
}

// Box corners inside a face or an edge of another box: T-junctions.
int t_junctions(const TMesh& mesh) {
  int n = 0;
  for (const TBox& b : mesh.boxes())
    for (int c = 0; c < 8; ++c) {
      const std::array<TCoord, 3> v{{(c & 1) ? b.hi[0] : b.lo[0], (c & 2) ? b.hi[1] : b.lo[1], (c & 4) ? b.hi[2] : b.lo[2]}};
      for (const TBox& q : mesh.boxes()) {
        bool inside = true, corner = true;
        for (std::size_t d = 0; d < 3; ++d) {
          inside = inside && q.lo[d] <= v[d] && v[d] <= q.hi[d];
          corner = corner && (v[d] == q.lo[d] || v[d] == q.hi[d]);
        }
        if (inside && !corner) {
          ++n;
          break;
        }
      }
    }
  return n;
}

bool dual_compatible(const TSplineModel& t) {
  for (const TMesh& mesh : t.meshes)
    if (dual_compatibility_violation(mesh, tspline_functions(mesh))) return false;
  return true;
}

TEST(TSpline, TheTensorMeshIsThePatch) {
  std::mt19937 rng(3);
  const MultiPatch mp = two_patches(rng);
  const TSplineModel t = tspline_model(mp);
  const ExtractionModel m = extraction_model(t);
  const ExtractionModel reference = extraction_model(mp);
  EXPECT_EQ(m.function_count(), reference.function_count());
  EXPECT_EQ(m.elements.size(), reference.elements.size());
  EXPECT_EQ(m.boundary_faces.size(), reference.boundary_faces.size());
  EXPECT_EQ(static_cast<int>(tspline_functions(t.meshes[0]).size()), mp.patches[0].count(0) * mp.patches[0].count(1) * mp.patches[0].count(2));
  EXPECT_LT(geometry_error(m, mp, rng), 1e-12 * diagonal(mp));
  EXPECT_LT(partition_of_unity_error(m), 1e-14);
  EXPECT_EQ(t_junctions(t.meshes[0]), 0);
}

TEST(TSpline, LocalRefinementKeepsTheGeometryAndIsAnalysisSuitable) {
  for (const bool rational : {false, true}) {
    std::mt19937 rng(rational ? 7 : 5);
    const MultiPatch mp = one_patch(rng, rational);
    TSplineModel t = tspline_model(mp);
    for (int step = 0; step < 6; ++step) {
      std::uniform_int_distribution<int> pick(0, static_cast<int>(t.meshes[0].boxes().size()) - 1);
      refine_boxes(t, {{0, pick(rng)}, {0, pick(rng)}});
      ASSERT_TRUE(dual_compatible(t)) << "step " << step;
      const ExtractionModel m = extraction_model(t);
      EXPECT_LT(geometry_error(m, mp, rng), 1e-12 * diagonal(mp)) << "step " << step;
      EXPECT_LT(partition_of_unity_error(m), 1e-14) << "step " << step;
    }
    const ExtractionModel m = extraction_model(t);
    EXPECT_GT(t_junctions(t.meshes[0]), 0);
    EXPECT_GT(stacked_extraction_conditioning(m), 1e-8);
  }
}

// A scalar field with coefficient c[f] per function at parameter xi of a
// patch: the sum over the functions of the element holding xi.
double field_at(const ExtractionModel& m, int patch, const Eigen::Vector3d& xi, const Eigen::VectorXd& c) {
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const ExtractionElement& el = m.elements[e];
    if (el.patch != patch) continue;
    Eigen::Vector3d t;
    bool inside = true;
    for (int d = 0; d < 3; ++d) {
      t[d] = (xi[d] - el.domain[d][0]) / (el.domain[d][1] - el.domain[d][0]);
      inside = inside && t[d] >= 0.0 && t[d] <= 1.0;
    }
    if (!inside) continue;
    std::array<std::vector<double>, 3> B;
    for (int d = 0; d < 3; ++d) {
      B[d].resize(static_cast<std::size_t>(el.degrees[d]) + 1);
      bernstein_basis(el.degrees[d], t[d], B[d].data());
    }
    const Eigen::MatrixXd& C = m.C(static_cast<int>(e));
    double value = 0.0;
    for (std::size_t r = 0; r < el.functions.size(); ++r)
      for (Eigen::Index k = 0; k < C.cols(); ++k) {
        const int iu = static_cast<int>(k % (el.degrees[0] + 1)), iv = static_cast<int>(k / (el.degrees[0] + 1) % (el.degrees[1] + 1)),
                  iw = static_cast<int>(k / ((el.degrees[0] + 1) * (el.degrees[1] + 1)));
        value += c[el.functions[r]] * C(static_cast<Eigen::Index>(r), k) * B[0][static_cast<std::size_t>(iu)] * B[1][static_cast<std::size_t>(iv)] *
                 B[2][static_cast<std::size_t>(iw)];
      }
    return value;
  }
  ADD_FAILURE() << "no element of patch " << patch << " holds the point";
  return 0.0;
}

TEST(TSpline, RefinementAtAnInterfaceIsMirroredAndTheSpaceStaysC0) {
  std::mt19937 rng(9);
  const MultiPatch mp = two_patches(rng);
  TSplineModel t = tspline_model(mp);
  const std::size_t b_boxes = t.meshes[1].boxes().size();
  // Patch 0's boxes on its u1 face (the interface), twice.
  for (int round = 0; round < 2; ++round) {
    std::vector<std::pair<int, int>> face;
    for (std::size_t b = 0; b < t.meshes[0].boxes().size(); ++b)
      if (t.meshes[0].boxes()[b].hi[0] == t.meshes[0].extent(0) && t.meshes[0].boxes()[b].lo[1] == 0) face.push_back({0, static_cast<int>(b)});
    refine_boxes(t, face);
  }
  EXPECT_GT(t.meshes[1].boxes().size(), b_boxes);
  EXPECT_TRUE(dual_compatible(t));
  const ExtractionModel m = extraction_model(t);
  EXPECT_LT(geometry_error(m, mp, rng), 1e-12 * diagonal(mp));
  EXPECT_LT(partition_of_unity_error(m), 1e-14);
  // Fewer functions than the two patches' own: the interface's are shared.
  const long own = static_cast<long>(tspline_functions(t.meshes[0]).size() + tspline_functions(t.meshes[1]).size());
  EXPECT_LT(m.function_count(), own);
  // A random field of the space is continuous across the interface:
  // patch 0 at (1, v, w) is patch 1 at (1 - v, w, 0).
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Eigen::VectorXd c = Eigen::VectorXd::Random(m.function_count());
  double jump = 0.0;
  for (int s = 0; s < 200; ++s) {
    const double v = unit(rng), w = unit(rng);
    jump = std::max(jump, std::abs(field_at(m, 0, {1.0, v, w}, c) - field_at(m, 1, {1.0 - v, w, 0.0}, c)));
  }
  EXPECT_LT(jump, 1e-12);
}

// The patches' cells are made on all cores: one thread or two give the same
// extraction bit for bit.
TEST(TSpline, OneOrTwoThreadsGiveTheSameExtraction) {
  std::mt19937 rng(12);
  TSplineModel t = tspline_model(two_patches(rng));
  ASSERT_GT(refine_in_region(t, Eigen::AlignedBox3d(Eigen::Vector3d(0.5, -9, -9), Eigen::Vector3d(9, 9, 9)), 1), 0);
  igaprep::set_thread_count(1);
  const ExtractionModel one = extraction_model(t);
  igaprep::set_thread_count(2);
  const ExtractionModel two = extraction_model(t);
  igaprep::set_thread_count(0);
  EXPECT_EQ(one.control_points, two.control_points);
  EXPECT_EQ(one.weights, two.weights);
  ASSERT_EQ(one.elements.size(), two.elements.size());
  for (std::size_t e = 0; e < one.elements.size(); ++e) {
    EXPECT_EQ(one.elements[e].functions, two.elements[e].functions);
    EXPECT_EQ(one.C(static_cast<int>(e)), two.C(static_cast<int>(e)));
  }
}

// Four splits made by hand without the closure (a 2-D pattern of crossing
// T-junction extensions, extruded through the one element of w): not dual
// compatible, so refused; the same boxes refined with the closure are.
TEST(TSpline, ANonAnalysisSuitableMeshIsRefusedAndTheClosureAvoidsIt) {
  auto box_at = [](const TMesh& m, double u, double v) {
    for (std::size_t b = 0; b < m.boxes().size(); ++b)
      if (m.boxes()[b].lo[0] == static_cast<TCoord>(u * kTScale) && m.boxes()[b].lo[1] == static_cast<TCoord>(v * kTScale))
        return static_cast<int>(b);
    return -1;
  };
  const double corners[4][2] = {{0, 2}, {2, 2}, {0, 3}, {0.5, 2}};
  TMesh raw({{4, 4, 1}}, {{3, 3, 3}}), closed = raw;
  for (const auto& c : corners) {
    raw.split(box_at(raw, c[0], c[1]));
    closed.refine(box_at(closed, c[0], c[1]));
  }
  EXPECT_THROW(check_analysis_suitable(raw), igaprep::Error);
  EXPECT_TRUE(dual_compatibility_violation(raw, tspline_functions(raw)).has_value());
  EXPECT_NO_THROW(check_analysis_suitable(closed));
  EXPECT_GT(closed.boxes().size(), raw.boxes().size());
}

TEST(TSpline, EvenDegreesAndRepeatedKnotsAreRefusedForRefinement) {
  auto message = [](const MultiPatch& mp) {
    try {
      tspline_model(mp);
    } catch (const igaprep::Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  std::mt19937 rng(1);
  MultiPatch mp = one_patch(rng, false);
  mp.patches[0] = random_patch(rng, {{2, 3, 3}}, {{6, 6, 6}}, false, 1);
  EXPECT_NE(message(mp).find("odd degrees"), std::string::npos) << message(mp);
  mp.patches[0] = random_patch(rng, {{3, 3, 3}}, {{7, 6, 6}}, false, 1);
  mp.patches[0].knots[0] = {0, 0, 0, 0, 0.4, 0.4, 0.7, 1, 1, 1, 1};
  EXPECT_NE(message(mp).find("multiplicity above 1"), std::string::npos) << message(mp);
}

}  // namespace
