// Solves on several threads at once (a thread pool, Python) share no mutable
// state: each gives bitwise the result of the same solve run alone.
#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "igaprep/core/parallel.h"
#include "igaprep/iga_check/elasticity_solve.h"
#include "solve_models.h"

using namespace igaprep;
using namespace solve_test;

namespace {

iga_check::ElasticitySolution solve(int k, iga_check::LinearSolver solver = iga_check::LinearSolver::Automatic) {
  iga_check::ElasticityProblem problem;
  problem.fixed = {{"base", {{true, true, true}}}};
  problem.pressures = {{"end", 0.5 + k}};
  iga_check::ElasticityOptions options;
  options.extra_quadrature = k % 4;  // different Gauss rules on different threads
  options.solver = solver;
  return iga_check::solve_elasticity(two_box_bar(1 + k % 3), problem, options);
}

}  // namespace

TEST(SolveThreads, ConcurrentSolvesMatchSolvesAlone) {
  const int n = 8;
  std::vector<iga_check::ElasticitySolution> alone, together(n);
  for (int k = 0; k < n; ++k) alone.push_back(solve(k));
  std::vector<std::thread> threads;
  for (int k = 0; k < n; ++k) threads.emplace_back([k, &together] { together[k] = solve(k); });
  for (auto& t : threads) t.join();
  for (int k = 0; k < n; ++k) {
    EXPECT_EQ(together[k].report.strain_energy, alone[k].report.strain_energy) << k;
    EXPECT_EQ(together[k].report.quadrature_points, alone[k].report.quadrature_points) << k;
    for (size_t p = 0; p < alone[k].model.patches.size(); ++p)
      EXPECT_TRUE(together[k].model.patches[p].displacement == alone[k].model.patches[p].displacement) << k << " " << p;
  }
}

// Issue 22: the element matrices are computed on all cores and added in
// element order, so one thread or two give the same solve bit for bit.
TEST(SolveThreads, OneOrTwoAssemblyThreadsGiveTheSameSolve) {
  igaprep::set_thread_count(1);
  const iga_check::ElasticitySolution one = solve(5);
  igaprep::set_thread_count(2);
  const iga_check::ElasticitySolution two = solve(5);
  igaprep::set_thread_count(0);
  EXPECT_EQ(one.report.strain_energy, two.report.strain_energy);
  ASSERT_EQ(one.model.patches.size(), two.model.patches.size());
  for (std::size_t p = 0; p < one.model.patches.size(); ++p)
    EXPECT_EQ(one.model.patches[p].displacement, two.model.patches[p].displacement);
}

// hypre keeps global state: AMG solves from several threads are taken one at
// a time and give what they give alone; the thread count of the assembly
// does not change them (hypre runs on one thread here).
TEST(SolveThreads, ConcurrentAmgSolvesMatchSolvesAlone) {
  const int n = 4;
  std::vector<iga_check::ElasticitySolution> alone, together(n);
  for (int k = 0; k < n; ++k) alone.push_back(solve(k, iga_check::LinearSolver::Amg));
  std::vector<std::thread> threads;
  for (int k = 0; k < n; ++k)
    threads.emplace_back([k, &together] { together[k] = solve(k, iga_check::LinearSolver::Amg); });
  for (auto& t : threads) t.join();
  for (int k = 0; k < n; ++k) {
    EXPECT_EQ(together[k].report.solver, "boomeramg-pcg");
    EXPECT_EQ(together[k].report.strain_energy, alone[k].report.strain_energy) << k;
  }
}

TEST(SolveThreads, OneOrTwoAssemblyThreadsGiveTheSameAmgSolve) {
  igaprep::set_thread_count(1);
  const iga_check::ElasticitySolution one = solve(5, iga_check::LinearSolver::Amg);
  igaprep::set_thread_count(2);
  const iga_check::ElasticitySolution two = solve(5, iga_check::LinearSolver::Amg);
  igaprep::set_thread_count(0);
  EXPECT_EQ(one.report.strain_energy, two.report.strain_energy);
  for (std::size_t p = 0; p < one.model.patches.size(); ++p)
    EXPECT_EQ(one.model.patches[p].displacement, two.model.patches[p].displacement);
}
