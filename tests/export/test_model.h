#pragma once
// The multipatch model of the export tests: a curved slab over [0,2]x[0,2]x[0,1]
// (a smooth warp of it) in four patches, one per quadrant, with
//  - two materials (patches 0, 1: "steel"; patches 2, 3: "rubber"),
//  - mixed degrees (2,2,1) and (3,2,1), non-uniform and non-symmetric knot
//    vectors, one patch on the parameter domain [0,2] in u,
//  - patch 3 rational (weights != 1 away from its interface sides),
//  - interfaces in three different orientations (identity; u<->v swapped
//    with one direction reversed; one direction reversed),
//  - every free side labelled ("T1_outer", "base" for the bottom),
//  - a displacement field that is affine in space, u(x) = A x + b, so its
//    strain and von Mises stress are constant per material (exact checks).
#include <cmath>
#include <vector>

#include "igaprep/spline/knot_vector.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::test {

inline std::vector<double> reversed_knots(const std::vector<double>& U) {
  const double a = U.front(), b = U.back();
  std::vector<double> R(U.size());
  for (size_t i = 0; i < U.size(); ++i) R[i] = a + b - U[U.size() - 1 - i];
  return R;
}

// The warp of the slab: smooth, with positive Jacobian on [0,2]^2 x [0,1].
inline Eigen::Vector3d slab_warp(const Eigen::Vector3d& X) {
  const double pi = 3.14159265358979323846;
  return Eigen::Vector3d(X[0] + 0.08 * std::sin(pi * X[1] / 2.0),
                         X[1] + 0.06 * std::sin(pi * X[0] / 2.0) * (1.0 + X[2]),
                         0.7 * X[2] + 0.05 * X[0] * X[1]);
}

// The affine displacement of the test solution: u(x) = A x + b.
inline Eigen::Matrix3d test_displacement_gradient() {
  Eigen::Matrix3d A;
  A << 1.0e-3, 2.0e-4, -1.0e-4,
       -3.0e-4, 5.0e-4, 4.0e-4,
       2.0e-4, 1.0e-4, -2.0e-3;
  return A;
}
inline Eigen::Vector3d test_displacement_offset() { return Eigen::Vector3d(1.0e-3, -2.0e-3, 5.0e-4); }

// von Mises stress of the affine displacement for Young's modulus E, Poisson nu.
inline double test_von_mises(double E, double nu) {
  const Eigen::Matrix3d A = test_displacement_gradient();
  const Eigen::Matrix3d eps = 0.5 * (A + A.transpose());
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const Eigen::Matrix3d s = lambda * eps.trace() * Eigen::Matrix3d::Identity() + 2 * mu * eps;
  return std::sqrt(0.5 * ((s(0, 0) - s(1, 1)) * (s(0, 0) - s(1, 1)) + (s(1, 1) - s(2, 2)) * (s(1, 1) - s(2, 2)) +
                          (s(2, 2) - s(0, 0)) * (s(2, 2) - s(0, 0))) +
                   3.0 * (s(0, 1) * s(0, 1) + s(1, 2) * s(1, 2) + s(0, 2) * s(0, 2)));
}

// frame(s) maps normalised patch parameters s in [0,1]^3 to slab coordinates X.
template <class Frame>
spline::Patch make_slab_patch(const std::array<int, 3>& degrees, const std::array<std::vector<double>, 3>& knots,
                              Frame frame) {
  spline::Patch p;
  p.degrees = degrees;
  p.knots = knots;
  std::array<std::vector<double>, 3> g;
  for (int d = 0; d < 3; ++d) g[d] = spline::greville_abscissae(knots[d], degrees[d]);
  const int nu = p.count(0), nv = p.count(1), nw = p.count(2);
  p.control_points.resize(nu * nv * nw, 3);
  for (int k = 0; k < nw; ++k)
    for (int j = 0; j < nv; ++j)
      for (int i = 0; i < nu; ++i) {
        Eigen::Vector3d s;
        const int ijk[3] = {i, j, k};
        for (int d = 0; d < 3; ++d) s[d] = (g[d][ijk[d]] - knots[d].front()) / (knots[d].back() - knots[d].front());
        p.control_points.row(p.index(i, j, k)) = slab_warp(frame(s)).transpose();
      }
  return p;
}

inline spline::MultiPatch make_test_model() {
  using V = std::vector<double>;
  const V kx0 = {0, 0, 0, 0.3, 1, 1, 1};              // x in [0,1], degree 2
  const V kx1 = {0, 0, 0, 0, 1.2, 2, 2, 2, 2};        // x in [1,2], degree 3, domain [0,2]
  const V ky0 = {0, 0, 0, 0.5, 1, 1, 1};              // y in [0,1], degree 2
  const V ky1 = {0, 0, 0, 0.4, 0.7, 1, 1, 1};         // y in [1,2], degree 2
  const V kz = {0, 0, 0.35, 1, 1};                    // z in [0,1], degree 1

  spline::MultiPatch mp;
  // Patch 0: X = (u, v, w).
  mp.patches.push_back(make_slab_patch({2, 2, 1}, {kx0, ky0, kz},
                                       [](const Eigen::Vector3d& s) { return Eigen::Vector3d(s[0], s[1], s[2]); }));
  // Patch 1: X = (1 + u, v, w).
  mp.patches.push_back(make_slab_patch({3, 2, 1}, {kx1, ky0, kz},
                                       [](const Eigen::Vector3d& s) { return Eigen::Vector3d(1 + s[0], s[1], s[2]); }));
  // Patch 2: u along +y, v along -x: X = (1 - v, 1 + u, w).
  mp.patches.push_back(make_slab_patch({2, 2, 1}, {ky1, reversed_knots(kx0), kz},
                                       [](const Eigen::Vector3d& s) { return Eigen::Vector3d(1 - s[1], 1 + s[0], s[2]); }));
  // Patch 3: turned half round: X = (2 - u, 2 - v, w); rational.
  mp.patches.push_back(make_slab_patch({3, 2, 1}, {reversed_knots(kx1), reversed_knots(ky1), kz},
                                       [](const Eigen::Vector3d& s) { return Eigen::Vector3d(2 - s[0], 2 - s[1], s[2]); }));
  {
    spline::Patch& p = mp.patches[3];
    p.weights = Eigen::VectorXd::Ones(p.control_points.rows());
    for (int k = 0; k < p.count(2); ++k)
      for (int j = 0; j < p.count(1); ++j)
        for (int i = 0; i < p.count(0); ++i)
          // weights 1 on the interface sides u1 and v1 keep the interfaces conforming
          if (i < p.count(0) - 1 && j < p.count(1) - 1) p.weights[p.index(i, j, k)] = 0.6 + 0.3 * ((i + 2 * j + k) % 3);
  }
  mp.patches[0].material = 0;
  mp.patches[1].material = 0;
  mp.patches[2].material = 1;
  mp.patches[3].material = 1;

  mp.labels = {"T1_outer", "T2_inclusion", "base"};
  mp.materials = {{"steel", 210e9, 0.3}, {"rubber", 0.01e9, 0.45}};

  // Interfaces; orient of the normal direction as G+Smo sets it (1 when both
  // sides are at the same end of their directions).
  auto add = [&](int pa, int sa, int pb, int sb, std::array<int, 3> dm, std::array<int, 3> o, int surface) {
    spline::Interface f;
    f.patch_a = pa;
    f.side_a = sa;
    f.patch_b = pb;
    f.side_b = sb;
    f.dirmap = dm;
    f.orient = o;
    f.surface = surface;
    mp.interfaces.push_back(f);
  };
  add(0, spline::kU1, 1, spline::kU0, {0, 1, 2}, {0, 1, 1}, -1);  // identity
  add(0, spline::kV1, 2, spline::kU0, {1, 0, 2}, {0, 0, 1}, 1);   // u<->v, u reversed
  add(1, spline::kV1, 3, spline::kV1, {0, 1, 2}, {0, 1, 1}, 1);   // u reversed
  add(2, spline::kV0, 3, spline::kU1, {1, 0, 2}, {0, 0, 1}, -1);  // u<->v, u reversed

  // Free sides: the bottom (w0) is "base", the rest "T1_outer".
  const std::vector<std::vector<int>> free_sides = {{1, 3, 5, 6}, {2, 3, 5, 6}, {2, 4, 5, 6}, {1, 3, 5, 6}};
  for (int p = 0; p < 4; ++p)
    for (int s : free_sides[p]) mp.boundaries.push_back({p, s, s == spline::kW0 ? 2 : 0});

  // Solve result: the affine displacement's coefficients are A x_i + b.
  const Eigen::Matrix3d A = test_displacement_gradient();
  const Eigen::Vector3d b = test_displacement_offset();
  double umax = 0.0;
  for (spline::Patch& p : mp.patches) {
    p.displacement.resize(p.control_points.rows(), 3);
    for (Eigen::Index r = 0; r < p.control_points.rows(); ++r) {
      const Eigen::Vector3d u = A * p.control_points.row(r).transpose() + b;
      p.displacement.row(r) = u.transpose();
      umax = std::max(umax, u.norm());
    }
  }
  mp.has_solution = true;
  mp.strain_energy = 1234.5678901234567;
  mp.max_displacement = umax;
  mp.provenance_generator = "igaprep export tests";
  mp.provenance_case = R"({"name": "slab", "units": "m"})";
  mp.provenance_inputs = R"({"T1.obj": "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855"})";
  return mp;
}

}  // namespace igaprep::test
