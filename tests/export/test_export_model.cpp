// export_model / parse_formats, and the `igaprep export` command when the
// executable has it registered.
#include <gtest/gtest.h>

#include <filesystem>

#include "igaprep/core/error.h"
#include "igaprep/export/export_model.h"
#include "igaprep/export/hdf5_model.h"
#include "test_model.h"
#include "test_util.h"

namespace {
using namespace igaprep::test;
using igaprep::exporter::Format;

TEST(ExportModel, ParsesFormatListsAndRefusesUnknownOnes) {
  EXPECT_EQ(igaprep::exporter::parse_formats("hdf5,gismo, MFEM,vtu,bext,vtu"),
            (std::vector<Format>{Format::Hdf5, Format::Gismo, Format::Mfem, Format::Vtu, Format::Bext}));
  try {
    igaprep::exporter::parse_formats("vtu,stl");
    ADD_FAILURE() << "accepted stl";
  } catch (const igaprep::Error& e) {
    EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput);
    EXPECT_NE(std::string(e.what()).find("'stl'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(igaprep::exporter::parse_formats(" , "), igaprep::Error);
}

TEST(ExportModel, WritesEveryFormatWithItsExtension) {
  const std::string dir = scratch_dir("all_formats");
  const auto written = igaprep::exporter::export_model(
      make_test_model(), dir + "/slab", igaprep::exporter::parse_formats("hdf5,gismo,mfem,vtu,bext"));
  ASSERT_EQ(written.size(), 5u);
  for (const char* ext : {".h5", ".xml", ".mesh", ".vtu", ".bext"}) {
    EXPECT_TRUE(std::filesystem::exists(dir + "/slab" + ext)) << ext;
    EXPECT_GT(std::filesystem::file_size(dir + "/slab" + ext), 1000u) << ext;
  }
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) (void)e, ++files;
  EXPECT_EQ(files, 5) << "no temporary files left";
  std::filesystem::remove_all(dir);
}

TEST(ExportCommand, WritesFilesAndRejectsUnknownFormat) {
  const std::string cli = IGAPREP_CLI;
  if (!std::filesystem::exists(cli) || run_command(shell_quote(cli) + " export --help >/dev/null 2>&1").status != 0)
    GTEST_SKIP() << "the igaprep executable at " << cli
                 << " is not built or has no 'export' command registered yet (cli/commands.cpp)";
  const std::string dir = scratch_dir("cli");
  igaprep::exporter::write_hdf5_model(make_test_model(), dir + "/in.h5");
  const CommandResult ok = run_command(shell_quote(cli) + " export " + shell_quote(dir + "/in.h5") +
                                       " --to mfem,vtu -o " + shell_quote(dir + "/out") + " 2>&1");
  EXPECT_EQ(ok.status, 0) << ok.output;
  EXPECT_TRUE(std::filesystem::exists(dir + "/out.mesh"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/out.vtu"));
  const CommandResult bad = run_command(shell_quote(cli) + " export " + shell_quote(dir + "/in.h5") +
                                        " --to vtu,obj -o " + shell_quote(dir + "/x") + " 2>&1");
  EXPECT_EQ(WEXITSTATUS(bad.status), 1) << bad.output;
  EXPECT_NE(bad.output.find("obj"), std::string::npos) << bad.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.vtu"));
  std::filesystem::remove_all(dir);
}

}  // namespace

#include "igaprep/spline/multipatch_topology.h"

namespace {
TEST(ExportTestModel, IsAConformingMultipatch) {
  // The writers of shared-node formats (MFEM, BEXT) rely on conforming
  // interfaces; the test model must be one, in all its orientations.
  const igaprep::spline::MultiPatch mp = igaprep::test::make_test_model();
  EXPECT_NO_THROW(igaprep::spline::validate_multipatch(mp));
  const auto report = igaprep::spline::check_conformity(mp, 1e-12);
  EXPECT_TRUE(report.conforming) << (report.problems.empty() ? "" : report.problems.front());
  EXPECT_LT(report.max_deviation, 1e-12);
  EXPECT_EQ(mp.patches.size(), 4u);
  EXPECT_EQ(mp.materials.size(), 2u);
}
}  // namespace
