// Fit-driven refinement of T-splines (issue 18): a cube whose target surface
// has a bump near one corner is fitted, refined only where its faces stay
// farther than the tolerance, and stays certified, analysis-suitable and a
// partition of unity; fidelity measures an extraction model as it measures
// the multipatch it came from; the repair takes back a fit that folds an
// element; interface faces survive the HDF5 file.
#include <gtest/gtest.h>

#include <cmath>

#include "export/test_util.h"
#include "igaprep/core/error.h"
#include "igaprep/export/hdf5_extraction.h"
#include "igaprep/iga_check/fidelity.h"
#include "igaprep/iga_check/jacobian_certificate.h"
#include "igaprep/iga_check/tspline_surface_fit.h"
#include "igaprep/spline/tspline_functions.h"
#include "igaprep/spline/tspline_model.h"
#include "solve/solve_models.h"

using namespace igaprep;
using namespace solve_test;

namespace {

constexpr double kBump = 0.03;  // height of the bump on the top face

// Centred at (0.65, 0.65) and narrow enough to vanish (below 1e-6) at the
// cube's edges, so that the raised top still meets the sides.
double bump(double x, double y) { return kBump * std::exp(-((x - 0.65) * (x - 0.65) + (y - 0.65) * (y - 0.65)) / (0.1 * 0.1)); }

// The unit cube's surface, n x n quads per face in two triangles each, the
// top face raised by the bump.
mesh::TriMesh bumped_cube(int n) {
  mesh::TriMesh m;
  m.V.resize(6 * (n + 1) * (n + 1), 3);
  m.F.resize(6 * 2 * n * n, 3);
  int v = 0, f = 0;
  for (int axis = 0; axis < 3; ++axis)
    for (int high = 0; high < 2; ++high) {
      const int first = v;
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
          Eigen::Vector3d x;
          x[axis] = high;
          x[(axis + 1) % 3] = static_cast<double>(i) / n;
          x[(axis + 2) % 3] = static_cast<double>(j) / n;
          if (axis == 2 && high) x.z() += bump(x.x(), x.y());
          m.V.row(v++) = x.transpose();
        }
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const int a = first + j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
          m.F.row(f++) << a, b, d;
          m.F.row(f++) << a, d, c;
        }
    }
  return m;
}

MultiPatch unit_cube(int elements) {
  MultiPatch mp;
  mp.patches = {box_patch({0, 0, 0}, {1, 1, 1}, {3, 3, 3}, {elements, elements, elements})};
  mp.materials = {{"steel", 1000.0, 0.3}};
  label_boundaries(mp, [](const Eigen::Vector3d&) { return std::string("outer"); });
  return mp;
}

long uncertified(const spline::ExtractionModel& m) {
  long n = 0;
  for (const iga_check::ElementCertificate& c : iga_check::certify_extraction_model(m))
    if (!iga_check::element_certified(c, false)) ++n;
  return n;
}

double partition_of_unity_error(const spline::ExtractionModel& m) {
  double worst = 0.0;
  for (std::size_t e = 0; e < m.elements.size(); ++e)
    worst = std::max(worst, (m.C(static_cast<int>(e)).colwise().sum().array() - 1.0).abs().maxCoeff());
  return worst;
}

TEST(TSplineFit, RefinesOnlyAtTheBumpAndReachesTheTolerance) {
  const MultiPatch mp = unit_cube(4);
  const std::vector<mesh::TriMesh> surfaces{bumped_cube(30)};
  spline::TSplineModel t = spline::tspline_model(mp);
  spline::TSplineFitOptions options;
  options.tolerance = 5e-3;
  options.max_rounds = 4;
  const iga_check::TSplineSurfaceFitResult r = iga_check::fit_tspline_to_surfaces(t, surfaces, options);
  const spline::TSplineFitResult& fit = r.fit;
  ASSERT_GE(fit.rounds.size(), 2u);
  EXPECT_GT(fit.rounds.front().max_distance, 2.0 * options.tolerance);  // the coarse faces cannot follow the bump
  EXPECT_TRUE(fit.reached);
  EXPECT_LE(fit.rounds.back().max_distance, options.tolerance);
  // The finest level reached, uniformly, would have (4 * 2^L + 3)^3 functions.
  const int levels = static_cast<int>(fit.rounds.size()) - 1;
  const double uniform = std::pow(4 * (1 << levels) + 3, 3);
  EXPECT_LT(fit.model.function_count(), 0.5 * uniform);
  EXPECT_GT(fit.model.function_count(), 7 * 7 * 7);
  for (const spline::TMesh& mesh : t.meshes) EXPECT_FALSE(spline::dual_compatibility_violation(mesh, spline::tspline_functions(mesh)));
  EXPECT_LT(partition_of_unity_error(fit.model), 1e-14);
  EXPECT_EQ(r.repair.uncertified_after, 0);
  EXPECT_EQ(uncertified(fit.model), 0);
  // The check's fidelity both ways: model to surface at the fit's own
  // samples, so within the tolerance; surface to model at the mesh's
  // vertices, where the fit's pairs start at triangle centroids (measured
  // 5.3e-3 here).
  const std::vector<iga_check::SurfaceFidelity> f = iga_check::fidelity(fit.model, surfaces, std::sqrt(3.0));
  ASSERT_EQ(f.size(), 1u);
  EXPECT_LE(f[0].spline_to_mesh.max, options.tolerance);
  EXPECT_LE(f[0].mesh_to_spline.max, options.tolerance * 1.25);
  // The bottom face, far from the bump, is not refined: its elements keep the starting size.
  for (const spline::ExtractionElement& e : fit.model.elements)
    if (e.domain[2][0] == 0.0) EXPECT_NEAR(e.domain[2][1], 0.25, 1e-15);
}

TEST(TSplineFit, FidelityOfTheConversionIsTheMultipatchFidelity) {
  const MultiPatch mp = unit_cube(3);
  const std::vector<mesh::TriMesh> surfaces{bumped_cube(20)};
  const auto a = iga_check::fidelity(mp, surfaces, 1.0);
  const auto b = iga_check::fidelity(spline::extraction_model(mp), surfaces, 1.0);
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_NEAR(a[0].spline_to_mesh.max, b[0].spline_to_mesh.max, 1e-12);
  EXPECT_NEAR(a[0].mesh_to_spline.max, b[0].mesh_to_spline.max, 1e-12);
  EXPECT_NEAR(a[0].mesh_to_spline.max, kBump, 1e-6);  // the bump's top vertex, which the flat face misses
}

TEST(TSplineFit, TheRepairTakesBackAMoveThatFoldsAnElement) {
  const MultiPatch mp = unit_cube(3);
  spline::ExtractionModel m = spline::extraction_model(mp);
  const Eigen::MatrixXd unfitted = m.control_points;
  ASSERT_EQ(uncertified(m), 0);
  // A corner's control point pushed through the cube folds the elements on it.
  m.control_points.row(0) = Eigen::RowVector3d(0.9, 0.9, 0.9);
  ASSERT_GT(uncertified(m), 0);
  const iga_check::TSplineRepairResult r = iga_check::back_off_uncertified(m, unfitted);
  EXPECT_GT(r.uncertified_before, 0);
  EXPECT_EQ(r.uncertified_after, 0);
  EXPECT_GE(r.steps, 1);
  EXPECT_GE(r.functions_backed_off, 1);
  EXPECT_EQ(uncertified(m), 0);
  EXPECT_THROW(iga_check::back_off_uncertified(m, unfitted.topRows(3)), Error);
}

TEST(TSplineFit, InterfaceFacesAreReadBackFromTheFile) {
  MultiPatch mp;
  mp.patches = {box_patch({0, 0, 0}, {1, 1, 1}, {3, 3, 3}, {2, 2, 2}), box_patch({1, 0, 0}, {2, 1, 1}, {3, 3, 3}, {2, 2, 2})};
  mp.labels = {"outer", "inner"};
  mp.materials = {{"a", 1000.0, 0.3}, {"b", 100.0, 0.3}};
  mp.patches[1].material = 1;
  find_interfaces(mp);
  ASSERT_EQ(mp.interfaces.size(), 1u);
  mp.interfaces[0].surface = 1;
  for (const spline::Side s : spline::Side::all()) {
    if (s != spline::kU1) mp.boundaries.push_back({0, s, 0});
    if (s != spline::kU0) mp.boundaries.push_back({1, s, 0});
  }
  const spline::ExtractionModel m = spline::extraction_model(mp);
  ASSERT_EQ(m.interface_faces.size(), 4u);  // 2 x 2 element faces on patch a's side
  const std::string path = igaprep::test::scratch_dir("tspline_interface_faces") + "/m.h5";
  exporter::write_hdf5_extraction(m, path);
  const spline::ExtractionModel back = exporter::read_hdf5_extraction(path);
  ASSERT_EQ(back.interface_faces.size(), m.interface_faces.size());
  for (std::size_t i = 0; i < m.interface_faces.size(); ++i) {
    EXPECT_EQ(back.interface_faces[i].element, m.interface_faces[i].element);
    EXPECT_EQ(static_cast<int>(back.interface_faces[i].side), static_cast<int>(m.interface_faces[i].side));
    EXPECT_EQ(back.interface_faces[i].label, 1);
  }
}

}  // namespace
