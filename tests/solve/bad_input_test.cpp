// Bad input to the solver: singular constraints, unknown labels, invalid
// materials: clear bad_input errors. Through the CLI: exit 1 and no output.
// Also the two linear solvers agree, and the CLI result file round-trips.
#include <gtest/gtest.h>

#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include "igaprep/core/error.h"
#include "igaprep/export/hdf5_model.h"
#include "igaprep/iga_check/elasticity_solve.h"
#include "solve_models.h"
#include "solve/expect_bad_input.h"

using namespace igaprep;
using namespace solve_test;
namespace fs = std::filesystem;

namespace {

using solve_test::expect_bad_input;

iga_check::ElasticityProblem clamped_pulled() {
  iga_check::ElasticityProblem p;
  p.fixed = {{"base", {{true, true, true}}}};
  p.tractions = {{"end", Eigen::Vector3d(1.0, 0.5, -0.25)}};
  return p;
}


}  // namespace

// Issue 21, item 4: a mirrored patch no longer meets its neighbour at the
// interface (glued by index, its control points are 1 apart): refused with
// the interface named, not solved into a wrong answer.
TEST(SolveBadInput, AMirroredPatchIsRefusedNotSolved) {
  MultiPatch mp = two_box_bar(2);
  Eigen::MatrixXd& P = mp.patches[1].control_points;
  P.col(0) = (3.0 - P.col(0).array()).matrix();  // x -> 3 - x: the same box, left-handed
  expect_bad_input([&] { iga_check::solve_elasticity(mp, clamped_pulled()); },
                   {"the model's interfaces do not conform (interface 0 (patch 0 side 2 / patch 1 side 1)",
                    "igaprep check"});
  // Mirrored as a whole, the model still solves: left-handed patches are
  // valid for the solver (its patch tests use them), only their interfaces
  // must match.
  MultiPatch both = two_box_bar(2);
  for (auto& p : both.patches) p.control_points.col(1) = (1.0 - p.control_points.col(1).array()).matrix();
  const auto right = iga_check::solve_elasticity(two_box_bar(2), clamped_pulled());
  iga_check::ElasticityProblem mirrored_load = clamped_pulled();
  mirrored_load.tractions[0].traction.y() *= -1.0;
  const auto left = iga_check::solve_elasticity(both, mirrored_load);
  EXPECT_NEAR(left.report.strain_energy, right.report.strain_energy, 1e-10 * right.report.strain_energy);
}

// Issue 21, item 6: the size of the refined problem is estimated first; 10
// refinements of a 16-element bar (8 * 2^30 elements) are refused at once.
TEST(SolveBadInput, AProblemBeyondTheSizeLimitIsRefusedBeforeAnyWork) {
  iga_check::ElasticityOptions options;
  options.refine = 10;
  expect_bad_input([&] { iga_check::solve_elasticity(two_box_bar(2), clamped_pulled(), options); },
                   {"the refined model would have about ", "more than the limit of 1000000",
                    "ElasticityOptions::max_unknowns"});
  // The estimate counts each patch's control points: refine 1 gives 2 * 3 * 6^3.
  options.refine = 1;
  options.max_unknowns = 2 * 3 * 216 - 1;
  expect_bad_input([&] { iga_check::solve_elasticity(two_box_bar(2), clamped_pulled(), options); },
                   {"about 1296 unknowns (2 patches, elevate 0, refine 1)"});
  options.max_unknowns = 2 * 3 * 216;
  EXPECT_GT(iga_check::solve_elasticity(two_box_bar(2), clamped_pulled(), options).report.unknowns, 0);
}

// Issue 21, item 13: a degree-0 patch and coordinates near 1e200 were
// reported as "3 rigid-body motions free"; they are named for what they are.
TEST(SolveBadInput, DegreeZeroAndHugeCoordinatesAreNamedNotCalledSingular) {
  MultiPatch huge = two_box_bar(2);
  huge.patches[1].control_points(5, 1) = 1e200;
  expect_bad_input([&] { iga_check::solve_elasticity(huge, clamped_pulled()); },
                   {"patch 1 has a control point coordinate of 1e+200: beyond 1e100 the stiffness overflows"});
  MultiPatch flat;
  flat.patches = {box_patch({0, 0, 0}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1})};
  spline::Patch& p = flat.patches[0];  // degree 0 along w: one layer of control points
  p.degrees[2] = 0;
  p.knots[2] = {0.0, 1.0};
  p.control_points.conservativeResize(4, 3);
  flat.materials = {{"steel", 1000.0, 0.3}};
  label_boundaries(flat, [](const Eigen::Vector3d&) { return std::string("all"); });
  iga_check::ElasticityProblem fix_all;
  fix_all.fixed = {{"all", {{true, true, true}}}};
  expect_bad_input([&] { iga_check::solve_elasticity(flat, fix_all); },
                   {"patch 0 has degree 0 in direction 2: its displacement has no derivative there"});
}

TEST(SolveBadInput, SingularConstraintsNameTheFreeMotion) {
  MultiPatch mp = two_box_bar(2);
  ASSERT_EQ(mp.interfaces.size(), 1u);
  auto problem = clamped_pulled();
  problem.fixed = {{"base", {{true, false, false}}}};  // only u_x = 0 on a plane: y, z, rotation about x free
  expect_bad_input([&] { iga_check::solve_elasticity(mp, problem); }, {"rigid-body", "free", "'base', 'free', 'end'"});
  problem.fixed.clear();
  expect_bad_input([&] { iga_check::solve_elasticity(mp, problem); },
                   {"no boundary", "6 rigid-body motions", "patches 0, 1", "'base', 'free', 'end'"});
  // Without the interface the second box floats: caught per connected part.
  MultiPatch apart = mp;
  apart.interfaces.clear();
  apart.boundaries.push_back({0, 2, 2});
  apart.boundaries.push_back({1, 1, 2});
  expect_bad_input([&] { iga_check::solve_elasticity(apart, clamped_pulled()); }, {"patch 1", "rigid-body"});
}

TEST(SolveBadInput, UnknownLabelsAndLabelsWithoutSides) {
  MultiPatch mp = two_box_bar(2);
  auto problem = clamped_pulled();
  problem.fixed.push_back({"nowhere", {{true, true, true}}});
  expect_bad_input([&] { iga_check::solve_elasticity(mp, problem); }, {"unknown label 'nowhere'", "base"});
  problem = clamped_pulled();
  problem.pressures.push_back({"missing", 1.0});
  expect_bad_input([&] { iga_check::solve_elasticity(mp, problem); }, {"pressure load", "'missing'"});
  problem = clamped_pulled();
  mp.labels.push_back("unused");
  problem.tractions.push_back({"unused", Eigen::Vector3d(1, 0, 0)});
  expect_bad_input([&] { iga_check::solve_elasticity(mp, problem); }, {"'unused'", "no boundary side"});
}

TEST(SolveBadInput, ErrorsNameTheBoundaryAtFault) {
  MultiPatch mp = two_box_bar(2);
  auto problem = clamped_pulled();
  problem.fixed = {{"base", {{false, false, false}}}};
  expect_bad_input([&] { iga_check::solve_elasticity(mp, problem); }, {"fixed boundary 'base'", "no displacement component"});
  problem = clamped_pulled();
  problem.tractions[0].traction(1) = std::nan("");
  expect_bad_input([&] { iga_check::solve_elasticity(mp, problem); }, {"traction on 'end'", "not finite"});
  problem = clamped_pulled();
  problem.pressures.push_back({"end", std::numeric_limits<double>::infinity()});
  expect_bad_input([&] { iga_check::solve_elasticity(mp, problem); }, {"pressure on 'end'", "not finite"});
}

TEST(SolveBadInput, InvalidMaterials) {
  MultiPatch mp = two_box_bar(2);
  mp.materials[0].young_modulus = -5.0;
  expect_bad_input([&] { iga_check::solve_elasticity(mp, clamped_pulled()); }, {"steel", "Young's modulus", "-5"});
  mp = two_box_bar(2);
  mp.materials[0].poisson_ratio = 0.5;
  expect_bad_input([&] { iga_check::solve_elasticity(mp, clamped_pulled()); }, {"Poisson ratio", "0.5"});
  mp.materials[0].poisson_ratio = 0.62;
  expect_bad_input([&] { iga_check::solve_elasticity(mp, clamped_pulled()); }, {"Poisson ratio"});
}

TEST(SolveLinearSolvers, ConjugateGradientsAgreeWithCholesky) {
  iga_check::ElasticityOptions options;
  options.refine = 1;
  const auto chol = iga_check::solve_elasticity(two_box_bar(2), clamped_pulled(), options);
  options.solver = iga_check::LinearSolver::ConjugateGradient;
  options.cg_tolerance = 1e-12;
  const auto cg = iga_check::solve_elasticity(two_box_bar(2), clamped_pulled(), options);
  EXPECT_GT(cg.report.cg_iterations, 0);
  EXPECT_EQ(cg.report.unknowns, chol.report.unknowns);
  EXPECT_NEAR(cg.report.strain_energy, chol.report.strain_energy, 1e-9 * chol.report.strain_energy);
  double diff = 0;
  for (size_t p = 0; p < 2; ++p)
    diff = std::max(diff, (cg.model.patches[p].displacement - chol.model.patches[p].displacement).cwiseAbs().maxCoeff());
  EXPECT_LT(diff, 1e-9 * chol.report.max_displacement);
  // Work of the load equals twice the strain energy (Clapeyron).
  EXPECT_GT(chol.report.strain_energy, 0.0);
}

// The CLI: a good run writes the result (checked by reading it back), bad
// input writes nothing. Needs the igaprep executable with its solve command
// (IGAPREP_SOLVE_CLI in the environment overrides the path, for trying a
// build of the command before it is registered).
std::string cli_path() {
  const char* env = std::getenv("IGAPREP_SOLVE_CLI");
  return env && *env ? env : IGAPREP_CLI;
}

class SolveCli : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(cli_path())) GTEST_SKIP() << "igaprep executable not built: " << cli_path();
    dir_ = fs::temp_directory_path() / ("igaprep_solve_cli_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    const std::string help = (dir_ / "help.txt").string();
    std::system((cli_path() + " solve --help > " + help + " 2>&1").c_str());
    std::ifstream f(help);
    const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    if (text.find("--pressure") == std::string::npos)
      GTEST_SKIP() << "the igaprep executable has no solve command registered (cli/commands.cpp)";
    model_ = (dir_ / "model.h5").string();
    exporter::write_hdf5_model(two_box_bar(2), model_);
  }
  void TearDown() override {
    if (!dir_.empty()) fs::remove_all(dir_);
  }
  int run(const std::string& args, const std::string& out) {
    const std::string cmd = cli_path() + " solve " + model_ + " -o " + out + " " + args + " > " +
                            (dir_ / "log.txt").string() + " 2>&1";
    const int status = std::system(cmd.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  std::string log() {
    std::ifstream f(dir_ / "log.txt");
    return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  }
  fs::path dir_;
  std::string model_;
};

TEST_F(SolveCli, ResultFileCarriesTheSolution) {
  const std::string out = (dir_ / "result.h5").string();
  ASSERT_EQ(run("--fix base --traction end=1,0.5,-0.25 --refine 1", out), 0) << log();
  const MultiPatch r = exporter::read_hdf5_model(out);
  iga_check::ElasticityOptions options;
  options.refine = 1;
  const auto direct = iga_check::solve_elasticity(two_box_bar(2), clamped_pulled(), options);
  ASSERT_TRUE(r.has_solution);
  ASSERT_EQ(r.patches.size(), 2u);
  EXPECT_NEAR(r.strain_energy, direct.report.strain_energy, 1e-12 * direct.report.strain_energy);
  EXPECT_NEAR(r.max_displacement, direct.report.max_displacement, 1e-12 * direct.report.max_displacement);
  for (size_t p = 0; p < 2; ++p) {
    EXPECT_EQ(r.patches[p].control_points.rows(), direct.model.patches[p].control_points.rows());
    EXPECT_LT((r.patches[p].displacement - direct.model.patches[p].displacement).cwiseAbs().maxCoeff(),
              1e-12 * direct.report.max_displacement);
  }
}

// `--solver amg` (issue 22): the BoomerAMG-preconditioned CG, named with its
// iterations in the output, gives the direct solve's energy.
TEST_F(SolveCli, AmgSolverIsNamedAndAgreesWithTheDirectSolve) {
  const std::string out = (dir_ / "amg.h5").string();
  ASSERT_EQ(run("--fix base --traction end=1,0.5,-0.25 --refine 1 --solver amg", out), 0) << log();
  EXPECT_NE(log().find("(boomeramg-pcg, "), std::string::npos) << log();
  EXPECT_NE(log().find(" iterations)"), std::string::npos) << log();
  iga_check::ElasticityOptions options;
  options.refine = 1;
  options.solver = iga_check::LinearSolver::Cholesky;
  const auto direct = iga_check::solve_elasticity(two_box_bar(2), clamped_pulled(), options);
  EXPECT_NEAR(exporter::read_hdf5_model(out).strain_energy, direct.report.strain_energy,
              1e-8 * direct.report.strain_energy);
}

// The total force and the spin on the command line solve as through the
// library: the bar's end carries 2 N in y (area 1), the bar spins about x.
TEST_F(SolveCli, ForceAndRotationAreTheLibrarysLoads) {
  const std::string out = (dir_ / "loads.h5").string();
  ASSERT_EQ(run("--fix base --force end=0,2,0 --rotation 0.5,3,1,0,0,0,0.5,0.5", out), 0) << log();
  iga_check::ElasticityProblem problem;
  problem.fixed = {{"base", {{true, true, true}}}};
  problem.forces = {{{"end"}, Eigen::Vector3d(0, 2, 0)}};
  problem.rotation = iga_check::RotationLoad{0.5, 3.0, Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 0.5, 0.5)};
  const auto direct = iga_check::solve_elasticity(two_box_bar(2), problem);
  const MultiPatch r = exporter::read_hdf5_model(out);
  EXPECT_NEAR(r.strain_energy, direct.report.strain_energy, 1e-12 * direct.report.strain_energy);
  EXPECT_GT(direct.report.strain_energy, 0.0);
}

// Issue 21, item 2: `solve b.h5 -o b.h5` refuses and keeps the model.
TEST_F(SolveCli, AnOutputThatIsTheModelIsRefused) {
  const auto before = fs::file_size(model_);
  EXPECT_EQ(run("--fix base --traction end=1,0,0", model_), 1) << log();
  EXPECT_NE(log().find("is the input '" + model_ + "' (the same file)"), std::string::npos) << log();
  EXPECT_EQ(fs::file_size(model_), before);
  EXPECT_FALSE(exporter::read_hdf5_model(model_).has_solution);
}

// Issue 23, item 5: an output that cannot be written is refused before the
// solve (it was found after 21 s of work on a large model), and a missing
// folder is made.
TEST_F(SolveCli, AnOutputFolderThatCannotBeWrittenIsRefusedFirst) {
  EXPECT_EQ(run("--fix base --traction end=1,0,0", "/proc/igaprep_nope/result.h5"), 1) << log();
  EXPECT_NE(log().find("/proc/igaprep_nope"), std::string::npos) << log();
  EXPECT_EQ(log().find("solve: "), std::string::npos) << "no solve ran: " << log();
  const std::string nested = (dir_ / "new" / "folder" / "result.h5").string();
  EXPECT_EQ(run("--fix base --traction end=1,0,0", nested), 0) << log();
  EXPECT_TRUE(exporter::read_hdf5_model(nested).has_solution);
}

TEST_F(SolveCli, BadInputExitsOneAndWritesNothing) {
  const std::vector<std::string> bad = {
      "--fix base:x --traction end=1,0,0",   // singular
      "--fix nowhere --traction end=1,0,0",  // unknown label
      "--fix base:q",                        // bad component
      "--fix base --pressure end=abc",       // not a number
      "--fix base --traction end=1,2",       // two components
      "--fix base --solver lu",              // unknown solver
      "--fix base --force end=1,0",          // two components
      "--fix base --rotation 1",             // one number
      "--fix base --rotation 1,2,0,0,0",     // zero axis
      "--fix base --traction end=1,0,0,",    // trailing comma
      "--fix base --fix end:x --traction end=1,0,0 --refine 11",  // out of range
  };
  for (const auto& args : bad) {
    const std::string out = (dir_ / "bad.h5").string();
    EXPECT_EQ(run(args, out), 1) << args << "\n" << log();
    // Our errors start with "error: "; CLI11's own parse errors name the option.
    const std::string text = log();
    EXPECT_TRUE(text.find("error: ") != std::string::npos || text.find("--refine") != std::string::npos) << text;
    EXPECT_FALSE(fs::exists(out)) << args;
  }
  // Invalid material in the file.
  MultiPatch mp = two_box_bar(2);
  mp.materials[0].poisson_ratio = 0.5;
  exporter::write_hdf5_model(mp, model_);
  const std::string out = (dir_ / "bad.h5").string();
  EXPECT_EQ(run("--fix base --traction end=1,0,0", out), 1) << log();
  EXPECT_NE(log().find("Poisson ratio"), std::string::npos) << log();
  EXPECT_FALSE(fs::exists(out));
}
