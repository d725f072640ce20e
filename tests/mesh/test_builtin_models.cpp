// The built-in models: genus, validity, nesting, and that the committed files
// in models/<name>/ are exactly what the generators make.
#include <gtest/gtest.h>

#include "igaprep/mesh/check_surface.h"
#include "igaprep/mesh/nesting.h"
#include "igaprep/mesh/read_surface.h"
#include "igaprep/models/builtin_models.h"

namespace {

using igaprep::models::make_builtin_model;

class BuiltinModel : public ::testing::TestWithParam<std::string> {};

TEST_P(BuiltinModel, SurfacesAreValidWithExpectedGenusAndSize) {
  const auto model = make_builtin_model(GetParam());
  long faces = 0;
  for (std::size_t i = 0; i < model.surfaces.size(); ++i) {
    auto report = igaprep::mesh::check_surface(model.surfaces[i], GetParam() + "/" + model.labels[i]);
    EXPECT_TRUE(report.ok()) << (report.errors.empty() ? "" : report.errors.front());
    EXPECT_TRUE(report.warnings.empty()) << "generated surfaces must already be outward";
    EXPECT_EQ(report.genus, model.expected_genus);
    EXPECT_EQ(report.components, 1);
    EXPECT_EQ(report.self_intersections, 0);
    EXPECT_GT(report.volume, 0.0);
    faces += report.faces;
  }
  EXPECT_GE(faces, 2000);
  EXPECT_LE(faces, 20000);
}

TEST_P(BuiltinModel, CommittedFilesMatchTheGenerator) {
  auto model = make_builtin_model(GetParam());
  for (std::size_t i = 0; i < model.surfaces.size(); ++i) {
    const std::string file = std::string(IGAPREP_SOURCE_DIR) + "/models/" + GetParam() + "/" + model.labels[i] + ".off";
    auto committed = igaprep::mesh::read_surface(file);
    ASSERT_EQ(committed.F.rows(), model.surfaces[i].F.rows()) << file;
    ASSERT_EQ(committed.V.rows(), model.surfaces[i].V.rows()) << file;
    EXPECT_EQ(committed.F, model.surfaces[i].F) << file;
    // OFF keeps 17 significant digits: the round trip is exact.
    EXPECT_EQ((committed.V - model.surfaces[i].V).cwiseAbs().maxCoeff(), 0.0) << file;
  }
}

INSTANTIATE_TEST_SUITE_P(All, BuiltinModel, ::testing::Values("sphere2", "ring2", "torus3"));

TEST(BuiltinModels, TwoMaterialModelsAreNested) {
  for (const char* name : {"sphere2", "ring2"}) {
    auto model = make_builtin_model(name);
    ASSERT_EQ(model.surfaces.size(), 2u);
    auto nesting = igaprep::mesh::check_nesting(model.surfaces, model.labels);
    EXPECT_TRUE(nesting.nested) << name;
    EXPECT_TRUE(nesting.errors.empty()) << name;
  }
}

TEST(BuiltinModels, ExactEllipsoidVolumeIsApproachedFromBelow) {
  // The inscribed polyhedron of the 1.0 x 0.8 x 0.6 ellipsoid: its volume is
  // below 4/3 pi abc and within 1 % of it at 5120 triangles.
  const auto model = make_builtin_model("sphere2");
  const auto report = igaprep::mesh::check_surface(model.surfaces[0], "sphere2/outer");
  const double exact = 4.0 / 3.0 * M_PI * 1.0 * 0.8 * 0.6;
  EXPECT_LT(report.volume, exact);
  EXPECT_NEAR(report.volume, exact, 0.01 * exact);
}

TEST(BuiltinModels, UnknownNameIsRefused) {
  try {
    make_builtin_model("cube7");
    FAIL() << "expected an error";
  } catch (const igaprep::Error& e) {
    EXPECT_NE(std::string(e.what()).find("unknown built-in model 'cube7'"), std::string::npos);
  }
}

}  // namespace
