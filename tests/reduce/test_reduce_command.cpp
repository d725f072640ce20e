// igaprep reduce on a model file: the knot a family was given comes out,
// the output is the reduced model, bad input is named and writes nothing.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli/cli_runner.h"
#include "export/test_model.h"
#include "igaprep/export/hdf5_model.h"
#include "reduce_test_util.h"

namespace {

using namespace igaprep::spline;
using namespace reduce_test;

std::string scratch(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(IGAPREP_BINARY_DIR) / "tests" / "reduce_scratch" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

// The export tests' slab with a knot inserted into a family that holds a
// reversed member, written to DIR/in.h5.
MultiPatch write_refined_slab(const std::string& dir, KnotFamily* family) {
  MultiPatch mp = igaprep::test::make_test_model();
  *family = family_with_reversed_member(mp, 2);
  insert_family_knot(mp, *family, 0.37);
  igaprep::exporter::write_hdf5_model(mp, dir + "/in.h5");
  return mp;
}

TEST(ReduceCommand, RemovesTheInsertedKnotAndWritesTheModel) {
  const std::string dir = scratch("command");
  KnotFamily f;
  const MultiPatch refined = write_refined_slab(dir, &f);
  const CliResult r = run_cli("reduce " + dir + "/in.h5 --tolerance 1e-9 -o " + dir + "/out.h5 --report " + dir + "/report");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("check_fitted"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("reduce "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("PASS"), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::exists(dir + "/report/report.json"));
  const MultiPatch out = igaprep::exporter::read_hdf5_model(dir + "/out.h5");
  for (const FamilyMember& m : f.members)
    EXPECT_LT(out.patches[m.patch].knots[m.direction].size(), refined.patches[m.patch].knots[m.direction].size());
  EXPECT_TRUE(check_conformity(out, 0.0).conforming);
}

TEST(ReduceCommand, AToleranceIsRequiredAndOnlyOne) {
  const std::string dir = scratch("bad_input");
  KnotFamily f;
  write_refined_slab(dir, &f);
  for (const std::string& flags : {std::string(""), std::string("--tolerance 1e-3 --relative-tolerance 1e-3"),
                                   std::string("--tolerance -1")}) {
    const CliResult r = run_cli("reduce " + dir + "/in.h5 " + flags + " -o " + dir + "/out.h5");
    EXPECT_NE(r.exit_code, 0) << flags;
    EXPECT_NE(r.exit_code, 2) << flags;
    EXPECT_NE(r.out.find("tolerance"), std::string::npos) << r.out;
    EXPECT_FALSE(std::filesystem::exists(dir + "/out.h5")) << flags;
  }
}

TEST(ReduceCommand, RefusesToReplaceItsInput) {
  const std::string dir = scratch("replace");
  KnotFamily f;
  write_refined_slab(dir, &f);
  const CliResult r = run_cli("reduce " + dir + "/in.h5 --tolerance 1e-9 -o " + dir + "/in.h5");
  EXPECT_EQ(r.exit_code, 1) << r.out;
}

}  // namespace
