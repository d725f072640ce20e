// export_model / parse_formats, and the `igaprep export` command when the
// executable has it registered.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "igaprep/core/error.h"
#include "igaprep/export/export_model.h"
#include "igaprep/export/hdf5_model.h"
#include "test_model.h"
#include "test_util.h"

namespace {
using namespace igaprep::test;
using igaprep::exporter::Format;

void write_text(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

template <class F>
void expect_bad_input_with(F f, const std::string& fragment) {
  try {
    f();
    ADD_FAILURE() << "no error";
  } catch (const igaprep::Error& e) {
    EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

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
  // vtu: the model and its labelled boundary; bext: the deck and a file per material
  ASSERT_EQ(written.size(), 8u);
  for (const char* ext : {".h5", ".xml", ".mesh", ".vtu", "_boundary.vtu", ".k", "_part1.bext", "_part2.bext"}) {
    EXPECT_TRUE(std::filesystem::exists(dir + "/slab" + ext)) << ext;
    EXPECT_GT(std::filesystem::file_size(dir + "/slab" + ext), 1000u) << ext;
  }
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) (void)e, ++files;
  EXPECT_EQ(files, 8) << "no temporary files left";
  std::filesystem::remove_all(dir);
}

// Issue 21, item 12: an export whose third format fails writes none of
// them and leaves the previous files; a model without patches, or with an
// interface that glues a side to itself, is refused.
TEST(ExportModel, AFormatThatFailsLeavesNoneOfThemWritten) {
  const std::string dir = scratch_dir("all_or_nothing");
  igaprep::spline::MultiPatch mp = make_test_model();
  // Patch 1's knots across its interface with patch 0 moved: every writer
  // but MFEM's (which needs one knot vector per edge class) takes it.
  mp.patches[1] = make_slab_patch({3, 2, 1}, {{{0, 0, 0, 0, 1.2, 2, 2, 2, 2}, {0, 0, 0, 0.6, 1, 1, 1}, {0, 0, 0.35, 1, 1}}},
                                  [](const Eigen::Vector3d& s) { return Eigen::Vector3d(1 + s[0], s[1], s[2]); });
  mp.patches[1].material = 0;
  write_text(dir + "/slab.xml", "old\n");
  EXPECT_THROW(igaprep::exporter::export_model(mp, dir + "/slab", igaprep::exporter::parse_formats("gismo,hdf5,mfem")),
               igaprep::Error);
  EXPECT_EQ(read_text(dir + "/slab.xml"), "old\n");
  EXPECT_FALSE(std::filesystem::exists(dir + "/slab.h5"));
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) (void)e, ++files;
  EXPECT_EQ(files, 1) << "temporary files left";

  igaprep::spline::MultiPatch none = make_test_model();
  none.patches.clear();
  none.interfaces.clear();
  none.boundaries.clear();
  expect_bad_input_with([&] { igaprep::exporter::export_model(none, dir + "/none", {Format::Gismo}); },
                        "the model has no patches");
  igaprep::spline::MultiPatch self = make_test_model();
  self.interfaces[0].patch_b = self.interfaces[0].patch_a;
  self.interfaces[0].side_b = self.interfaces[0].side_a;
  expect_bad_input_with([&] { igaprep::exporter::export_model(self, dir + "/self", {Format::Gismo}); },
                        "glues a side to itself");
  igaprep::spline::MultiPatch raw = make_test_model();
  raw.labels[1] = "incl\xffusion";  // read from an HDF5 file, any bytes are possible
  expect_bad_input_with([&] { igaprep::exporter::export_model(raw, dir + "/raw", {Format::Gismo}); },
                        "label 1 is not UTF-8 text (byte 4)");
  raw.labels[1] = "Einschlu\xc3\x9f \xe2\x80\x93 \xf0\x9f\x94\xa9";  // well-formed: accepted
  EXPECT_EQ(igaprep::exporter::export_model(raw, dir + "/raw", {Format::Gismo}).size(), 1u);
  raw.materials[0].name = "st\x01" "eel";
  expect_bad_input_with([&] { igaprep::exporter::export_model(raw, dir + "/raw2", {Format::Gismo}); },
                        "material 0's name is not UTF-8 text (byte 2)");
  raw.materials[0].name = "\xc0\xaf";  // overlong '/'
  expect_bad_input_with([&] { igaprep::exporter::export_model(raw, dir + "/raw3", {Format::Gismo}); },
                        "material 0's name is not UTF-8 text (byte 0)");
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
