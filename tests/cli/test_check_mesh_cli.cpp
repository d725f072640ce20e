// igaprep check-mesh: tables, --json keys and values, exit codes.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "cli/cli_runner.h"

namespace {

nlohmann::json json_of(const CliResult& r) {
  // stderr lines (if any) come after the JSON object; parse up to its end.
  const auto end = r.out.rfind('}');
  return nlohmann::json::parse(r.out.substr(0, end + 1));
}

TEST(CheckMeshCli, NestedRingReportsGenusAndNesting) {
  const auto r = run_cli("check-mesh --json " + models_dir() + "/ring2/outer.off " + models_dir() + "/ring2/inner.off");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto j = json_of(r);
  ASSERT_EQ(j.at("surfaces").size(), 2u);
  for (const char* key : {"file", "vertices", "faces", "components", "genus", "closed", "manifold", "oriented",
                          "self_intersections", "volume", "bbox"})
    EXPECT_TRUE(j["surfaces"][0].contains(key)) << key;
  EXPECT_EQ(j["surfaces"][0]["genus"], 1);
  EXPECT_EQ(j["surfaces"][1]["genus"], 1);
  EXPECT_EQ(j["surfaces"][0]["faces"], 4608);
  EXPECT_EQ(j["surfaces"][0]["self_intersections"], 0);
  // Inscribed polyhedron of the torus R = 1, r = 0.45: volume 2 pi^2 R r^2, less 1 %.
  const double exact = 2.0 * M_PI * M_PI * 1.0 * 0.45 * 0.45;
  EXPECT_NEAR(j["surfaces"][0]["volume"].get<double>(), exact, 0.01 * exact);
  EXPECT_EQ(j["nested"], true);
  EXPECT_TRUE(j["errors"].empty());
}

TEST(CheckMeshCli, ReversedOrderIsNotNested) {
  const auto r = run_cli("check-mesh --json " + models_dir() + "/sphere2/inner.off " + models_dir() + "/sphere2/outer.off");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  const auto j = json_of(r);
  EXPECT_EQ(j["nested"], false);
  EXPECT_FALSE(j["errors"].empty());
}

TEST(CheckMeshCli, OpenSurfaceIsADefectWithExitCode1) {
  const auto r = run_cli("check-mesh --json " + std::string(IGAPREP_TEST_DATA_DIR) + "/cli/open_box.off");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  const auto j = json_of(r);
  EXPECT_EQ(j["surfaces"][0]["closed"], false);
  EXPECT_TRUE(j["nested"].is_null());
  ASSERT_FALSE(j["errors"].empty());
  EXPECT_NE(j["errors"][0].get<std::string>().find("open_box.off"), std::string::npos);
  EXPECT_NE(j["errors"][0].get<std::string>().find("boundary"), std::string::npos);
}

TEST(CheckMeshCli, MissingFileIsReportedNotCrashed) {
  const auto r = run_cli("check-mesh /nonexistent/none.stl");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("none.stl"), std::string::npos) << r.out;
}

TEST(CheckMeshCli, TableNamesTheFileAndTheVerdict) {
  const auto r = run_cli("check-mesh " + models_dir() + "/torus3/outer.off");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("outer.off"), std::string::npos);
  EXPECT_NE(r.out.find("one surface"), std::string::npos) << r.out;
}

}  // namespace

namespace {

TEST(CheckMeshCli, UnreadableFileHasNullFieldsNotZeros) {
  const auto r = run_cli("check-mesh --json /nonexistent/none.stl " + models_dir() + "/torus3/outer.off");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  const auto j = json_of(r);
  ASSERT_EQ(j["surfaces"].size(), 2u);
  EXPECT_EQ(j["surfaces"][0]["readable"], false);
  for (const char* key : {"vertices", "faces", "components", "genus", "volume", "bbox", "closed"})
    EXPECT_TRUE(j["surfaces"][0][key].is_null()) << key;
  EXPECT_EQ(j["surfaces"][1]["readable"], true);
  EXPECT_EQ(j["surfaces"][1]["genus"], 3);
  EXPECT_TRUE(j["nested"].is_null());
}

}  // namespace
