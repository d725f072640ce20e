// The manufactured-solution study (manufactured_study.h): its field's
// derivatives and body force against finite differences, the L2 rate on a
// curved two-patch degree-3 model (a quarter of a thick cylinder in two
// reoriented NURBS sectors, two materials replaced by one), and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <utility>

#include "igaprep/core/error.h"
#include "igaprep/iga_check/elasticity_material.h"
#include "igaprep/iga_check/manufactured_study.h"
#include "solve_models.h"
#include "solve/expect_bad_input.h"

using namespace igaprep;
using namespace solve_test;

namespace {

using solve_test::expect_bad_input;

const double kPi = 3.14159265358979323846;

// 1 < r < 2, 0 < theta < pi/2, 0 < z < 1 as two sectors split at pi/4, degree
// 3 in every direction, `elements` elements per direction per patch; the
// second sector reoriented so the interface is not the identity. Every outer
// side is labelled T1 (label 0).
MultiPatch two_sector_cylinder(int elements) {
  std::vector<Patch> ps;
  for (int s = 0; s < 2; ++s) {
    Patch p = sector_patch(1.0, 2.0, s * kPi / 4, (s + 1) * kPi / 4, 0.0, 1.0);
    for (int d = 0; d < 3; ++d) p = spline::elevate_degree(p, d, 1);
    std::vector<double> X;
    for (int i = 1; i < elements; ++i) X.push_back(double(i) / elements);
    for (int d = 0; d < 3; ++d)
      if (!X.empty()) p = spline::insert_knots(p, d, X);
    p.material = s;
    ps.push_back(p);
  }
  MultiPatch mp;
  mp.patches = {ps[0], reorient(ps[1], {2, 0, 1}, {true, false, true})};
  mp.patches[1].material = 1;
  mp.materials = {{"steel", 200.0, 0.3}, {"aluminium", 70.0, 0.33}};
  find_interfaces(mp);
  label_boundaries(mp, [](const Eigen::Vector3d&) { return std::string("T1"); });
  return mp;
}


}  // namespace

// Gradient, Hessians and b = -div sigma by central differences (step h, error
// O(h^2) ~ 1e-8 relative at h = 1e-4 L).
TEST(SolveManufacturedStudy, FieldDerivativesMatchFiniteDifferences) {
  const auto f = iga_check::manufactured_field({-1.0, 0.5, 2.0}, {3.0, 2.5, 2.7}, 1e-3);
  EXPECT_NEAR(f.length, std::sqrt(16.0 + 4.0 + 0.49), 1e-12);
  const auto lame = iga_check::lame_parameters(1.0, 0.3);
  const double h = 1e-4 * f.length;
  for (const Eigen::Vector3d x : {Eigen::Vector3d(-0.7, 0.9, 2.1), Eigen::Vector3d(1.2, 2.2, 2.6),
                                  Eigen::Vector3d(2.9, 1.4, 2.3)}) {
    // The field is ~ amplitude * length, not small or polynomial.
    EXPECT_GT(f.displacement(x).norm(), 1e-4 * f.length);
    const Eigen::Matrix3d G = f.gradient(x);
    const auto H = f.hessians(x);
    Eigen::Matrix3d G_fd;
    std::array<Eigen::Matrix3d, 3> H_fd;
    Eigen::Vector3d div_sigma = Eigen::Vector3d::Zero();
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(j);
      G_fd.col(j) = (f.displacement(x + e) - f.displacement(x - e)) / (2 * h);
      const Eigen::Matrix3d dG = (f.gradient(x + e) - f.gradient(x - e)) / (2 * h);
      for (int i = 0; i < 3; ++i) H_fd[i].col(j) = dG.row(i).transpose();
      const Eigen::Matrix3d dS =
          (iga_check::isotropic_stress(lame, f.gradient(x + e)) - iga_check::isotropic_stress(lame, f.gradient(x - e))) /
          (2 * h);
      div_sigma += dS.col(j);
    }
    EXPECT_LT((G - G_fd).norm(), 1e-7 * G.norm());
    for (int i = 0; i < 3; ++i) {
      EXPECT_LT((H[i] - H_fd[i]).norm(), 1e-7 * H[i].norm()) << "component " << i;
      EXPECT_LT((H[i] - H[i].transpose()).norm(), 1e-15);
    }
    const Eigen::Vector3d b = f.body_force(x, lame);
    EXPECT_GT(b.norm(), 0.0);
    EXPECT_LT((b + div_sigma).norm(), 1e-7 * b.norm());
  }
}

// Two elements per direction per patch, refined once and twice: 4 and 8
// elements per direction per patch at degree 3.
TEST(SolveManufacturedStudy, CurvedTwoPatchDegree3ConvergesAtRatePPlusOne) {
  const MultiPatch mp = two_sector_cylinder(2);
  ASSERT_EQ(mp.interfaces.size(), 1u);
  ASSERT_EQ(mp.boundaries.size(), 10u);
  iga_check::ManufacturedOptions options;
  options.coarse_refine = 1;
  options.fine_refine = 2;
  // Issue 23, item 6: the study reports progress (each level's assembly,
  // then the levels solved) instead of running silently.
  std::map<std::string, std::pair<std::size_t, std::size_t>> last;
  int reports = 0;
  options.progress = [&](const std::string& task, std::size_t done, std::size_t total) {
    last[task] = {done, total};
    ++reports;
  };
  const auto st = iga_check::manufactured_study(mp, options);
  ASSERT_EQ(st.levels.size(), 2u);
  EXPECT_EQ(last["manufactured solution, levels solved"], std::make_pair(std::size_t{2}, std::size_t{2}));
  ASSERT_EQ(last.count("assembling stiffness"), 1u);
  EXPECT_EQ(last["assembling stiffness"].first, last["assembling stiffness"].second);
  EXPECT_GT(reports, 10);
  ASSERT_EQ(st.prescribed_labels, std::vector<std::string>{"T1"});
  EXPECT_NEAR(st.field.length, std::sqrt(4.0 + 4.0 + 1.0), 1e-9);  // control points span [0,2]^2 x [0,1]
  for (const auto& L : st.levels)
    std::printf("refine %d: %lld elements, h %.4f, %lld unknowns, %lld prescribed, L2 %.3e (rel %.3e), "
                "energy %.3e (rel %.3e), %.2f s\n",
                L.refine, L.elements, L.h, L.unknowns, L.prescribed_dofs, L.l2_error, L.l2_relative, L.energy_error,
                L.energy_relative, L.seconds);
  std::printf("L2 rate %.3f, energy rate %.3f, h ratio %.3f\n", st.l2_rate, st.energy_rate, st.h_ratio);
  EXPECT_EQ(st.levels[0].elements, 2 * 4 * 4 * 4);
  EXPECT_EQ(st.levels[1].elements, 2 * 8 * 8 * 8);
  EXPECT_DOUBLE_EQ(st.levels[0].h, 0.25);
  EXPECT_DOUBLE_EQ(st.h_ratio, 2.0);
  EXPECT_GT(st.levels[0].prescribed_dofs, 0);
  EXPECT_LT(st.levels[1].l2_error, st.levels[0].l2_error);
  EXPECT_LT(st.levels[1].l2_relative, 1e-4);
  EXPECT_GE(st.l2_rate, 3.5);
  EXPECT_GE(st.energy_rate, 2.5);
  EXPECT_NEAR(st.l2_rate,
              std::log(st.levels[0].l2_error / st.levels[1].l2_error) / std::log(st.levels[0].h / st.levels[1].h),
              1e-12);
}

TEST(SolveManufacturedStudy, BadInput) {
  MultiPatch mp = two_sector_cylinder(1);
  iga_check::ManufacturedOptions options;
  options.coarse_refine = 1;
  options.fine_refine = 1;
  expect_bad_input([&] { iga_check::manufactured_study(mp, options); }, {"coarse refine < fine refine"});
  // An outer side with no label would be traction free.
  mp.boundaries.pop_back();
  expect_bad_input([&] { iga_check::manufactured_study(mp); }, {"neither on an interface nor a labelled boundary"});
  mp.boundaries.clear();
  mp.interfaces.clear();
  expect_bad_input([&] { iga_check::manufactured_study(mp); }, {"patch 0 side 1"});
  expect_bad_input([&] { iga_check::manufactured_field({0, 0, 0}, {0, 0, 0}); }, {"bounding box"});
  expect_bad_input([&] { iga_check::manufactured_field({0, 0, 0}, {1, 1, 1}, -1.0); }, {"amplitude"});
}
