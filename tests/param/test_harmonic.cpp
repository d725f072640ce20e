// Harmonic fields: convergence on a spherical shell, the singular-problem
// error, factorization reuse, and the maximum-principle check.
#include <gtest/gtest.h>

#include <cmath>

#include "igaprep/core/error.h"
#include "igaprep/param/harmonic_field.h"
#include "igaprep/param/maximum_principle.h"
#include "igaprep/param/stiffness_matrix.h"
#include "param_meshes.h"

using namespace igaprep::param;

namespace {

// L2 error of the P1 field u against shell_exact, by a degree-2 (4-point) rule per tet.
double shell_l2_error(const igaprep::mesh::TetMesh& m, const Eigen::VectorXd& u) {
  const double a = 0.5854101966249685, b = 0.1381966011250105;
  double err2 = 0.0;
  for (Eigen::Index t = 0; t < m.T.rows(); ++t) {
    const double vol = param_test::tet_volume(m.V, m.T(t, 0), m.T(t, 1), m.T(t, 2), m.T(t, 3));
    for (int q = 0; q < 4; ++q) {
      Eigen::Vector3d p = Eigen::Vector3d::Zero();
      double uh = 0.0;
      for (int k = 0; k < 4; ++k) {
        const double w = k == q ? a : b;
        p += w * m.V.row(m.T(t, k)).transpose();
        uh += w * u(m.T(t, k));
      }
      const double e = uh - param_test::shell_exact(p.norm());
      err2 += vol / 4.0 * e * e;
    }
  }
  return std::sqrt(err2);
}

Eigen::VectorXd shell_field(const param_test::Shell& s, const HarmonicSolverOptions& opt = {}) {
  return harmonic_field(tet_stiffness(s.mesh.V, s.mesh.T), {{s.inner, 1.0}, {s.outer, 0.0}}, opt);
}

int solver_free_vertex(const std::vector<char>& dir) {
  for (size_t i = dir.size() / 2; i < dir.size(); ++i)
    if (!dir[i]) return static_cast<int>(i);
  return -1;
}

}  // namespace

TEST(Harmonic, SphericalShellConvergesAtSecondOrder) {
  // Mesh size halves from one mesh to the next (icosphere level + 1, twice the layers).
  std::vector<double> err;
  for (int level = 2; level <= 4; ++level) {
    const auto s = param_test::spherical_shell(level, 1 << (level - 1));
    const Eigen::VectorXd u = shell_field(s);
    // Dirichlet nodes sit at the exact radius, so the nodal values there are exact.
    for (int v : s.inner) ASSERT_EQ(u(v), 1.0);
    err.push_back(shell_l2_error(s.mesh, u));
  }
  const double rate1 = std::log2(err[0] / err[1]), rate2 = std::log2(err[1] / err[2]);
  RecordProperty("l2_errors", std::to_string(err[0]) + " " + std::to_string(err[1]) + " " + std::to_string(err[2]));
  std::printf("shell L2 errors %.3e %.3e %.3e, rates %.2f %.2f\n", err[0], err[1], err[2], rate1, rate2);
  EXPECT_GE(rate1, 1.8);
  EXPECT_GE(rate2, 1.8);
  EXPECT_LT(err[2], 1e-2);  // over a volume of 28/3 pi: relative L2 error below 0.2 %
}

TEST(Harmonic, CholeskyAndConjugateGradientAgree) {
  const auto s = param_test::spherical_shell(3, 4);
  HarmonicSolverOptions cg;
  cg.solver = LinearSolverKind::ConjugateGradient;
  cg.cg_tolerance = 1e-13;
  HarmonicSolverOptions chol;
  chol.solver = LinearSolverKind::Cholesky;
  const Eigen::VectorXd u1 = shell_field(s, chol), u2 = shell_field(s, cg);
  EXPECT_LE((u1 - u2).cwiseAbs().maxCoeff(), 1e-9);
  HarmonicSolverOptions jacobi = cg;
  jacobi.cg_jacobi_only = true;
  EXPECT_LE((u1 - shell_field(s, jacobi)).cwiseAbs().maxCoeff(), 1e-9);
  // The default (CG at its default tolerance) is close too.
  EXPECT_LE((u1 - shell_field(s)).cwiseAbs().maxCoeff(), 1e-8);
}

TEST(Harmonic, FreeComponentWithoutDirichletIsSingular) {
  // Two boxes in one vertex array: box A has two Dirichlet sets (x = 0 and x = 1),
  // box B (shifted, sharing no vertex) has none.
  const auto a = param_test::box_tets(3, 3, 3);
  const Eigen::Index nv = a.V.rows();
  Eigen::MatrixXd V(2 * nv, 3);
  V << a.V, a.V.rowwise() + Eigen::RowVector3d(5, 0, 0);
  Eigen::MatrixXi T(2 * a.T.rows(), 4);
  T << a.T, a.T.array() + static_cast<int>(nv);
  DirichletSet left, right;
  left.value = 0.0;
  right.value = 1.0;
  for (Eigen::Index i = 0; i < nv; ++i) {
    if (a.V(i, 0) == 0.0) left.vertices.push_back(static_cast<int>(i));
    if (a.V(i, 0) == 1.0) right.vertices.push_back(static_cast<int>(i));
  }
  try {
    harmonic_field(V, T, {left, right});
    FAIL() << "no error for a free component without Dirichlet vertices";
  } catch (const igaprep::Error& e) {
    EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput);
    const std::string msg = e.what();
    EXPECT_NE(msg.find("touches no Dirichlet vertex"), std::string::npos) << msg;
    EXPECT_NE(msg.find(std::to_string(nv) + " free vertices"), std::string::npos) << msg;  // all of box B
  }
  // With a value on box B as well, the same problem is fine.
  DirichletSet third;
  third.vertices = {static_cast<int>(nv)};
  third.value = 0.5;
  const Eigen::VectorXd u = harmonic_field(V, T, {left, right, third});
  EXPECT_LE((u.tail(nv).array() - 0.5).abs().maxCoeff(), 1e-9);  // B is constant (to the CG tolerance)
}

TEST(Harmonic, OverlappingSetsAndBadValuesAreBadInput) {
  const auto m = param_test::box_tets(2, 2, 2);
  const auto K = tet_stiffness(m.V, m.T);
  EXPECT_THROW(HarmonicSolver(K, {{0, 1}, {1, 2}}), igaprep::Error);
  EXPECT_THROW(HarmonicSolver(K, {{0, static_cast<int>(m.V.rows())}}), igaprep::Error);
  HarmonicSolver solver(K, {{0}, {1}});
  EXPECT_THROW(solver.solve({0.0}), igaprep::Error);  // one value for two sets
  EXPECT_THROW(solver.solve({0.0, std::nan("")}), igaprep::Error);
}

TEST(Harmonic, FactorizationReuseMatchesFreshSolve) {
  const auto s = param_test::spherical_shell(3, 4);
  const auto K = tet_stiffness(s.mesh.V, s.mesh.T);
  // A third set: the vertices of the middle layer with z > 1.2 (a cap).
  std::vector<int> cap;
  for (Eigen::Index i = 0; i < s.mesh.V.rows(); ++i)
    if (s.mesh.V(i, 2) > 1.2 && s.mesh.V.row(i).norm() < 1.99) cap.push_back(static_cast<int>(i));
  ASSERT_FALSE(cap.empty());
  HarmonicSolverOptions chol;
  chol.solver = LinearSolverKind::Cholesky;
  HarmonicSolver solver(K, {s.inner, s.outer, cap}, chol);
  EXPECT_EQ(solver.kind(), LinearSolverKind::Cholesky);
  EXPECT_EQ(solver.num_free() + s.inner.size() + s.outer.size() + cap.size(), static_cast<size_t>(s.mesh.V.rows()));
  const Eigen::VectorXd first = solver.solve({1.0, 0.0, 0.3});
  const Eigen::VectorXd second = solver.solve({-2.0, 5.0, 1.5});
  const Eigen::VectorXd fresh = harmonic_field(K, {{s.inner, -2.0}, {s.outer, 5.0}, {cap, 1.5}}, chol);
  EXPECT_LE((second - fresh).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_GT((second - first).cwiseAbs().maxCoeff(), 1.0);  // really a different field
  // Linearity: the field for a combination of values is that combination.
  const Eigen::VectorXd combo = solver.solve({1.0 - 2.0 * 2, 0.0 + 5.0 * 2, 0.3 + 1.5 * 2});
  EXPECT_LE((combo - (first + 2 * second)).cwiseAbs().maxCoeff(), 1e-11);
  // A right-hand side: K u = f on free rows with u = 0 on Dirichlet vertices.
  Eigen::VectorXd f = Eigen::VectorXd::Ones(s.mesh.V.rows());
  const Eigen::VectorXd p = solver.solve_with(Eigen::VectorXd::Zero(s.mesh.V.rows()), f);
  const Eigen::VectorXd r = K * p;
  for (int v : solver.free_vertices()) ASSERT_NEAR(r(v), 1.0, 1e-9);
  // The CG solver keeps its preconditioner: same answers to its tolerance.
  HarmonicSolverOptions cg;
  cg.solver = LinearSolverKind::ConjugateGradient;
  cg.cg_tolerance = 1e-13;
  HarmonicSolver iterative(K, {s.inner, s.outer, cap}, cg);
  EXPECT_LE((iterative.solve({-2.0, 5.0, 1.5}) - fresh).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_GT(iterative.last_cg_iterations(), 0);
}

TEST(MaximumPrinciple, ShellFieldHasNoInteriorExtrema) {
  const auto s = param_test::spherical_shell(3, 4);
  const auto K = tet_stiffness(s.mesh.V, s.mesh.T);
  const Eigen::VectorXd u = harmonic_field(K, {{s.inner, 1.0}, {s.outer, 0.0}});
  std::vector<char> dir(s.mesh.V.rows(), 0);
  for (int v : s.inner) dir[v] = 1;
  for (int v : s.outer) dir[v] = 1;
  EXPECT_EQ(find_interior_extrema(K, u, dir).size(), 0u);
  // The detector on the same mesh: a raised free vertex is found, and only it.
  Eigen::VectorXd bumped = u;
  const int v = solver_free_vertex(dir);
  bumped(v) = 1.5;  // above every value of the field
  const auto ext = find_interior_extrema(K, bumped, dir);
  ASSERT_EQ(ext.size(), 1u);
  EXPECT_EQ(ext[0].vertex, v);
  EXPECT_TRUE(ext[0].maximum);
}

TEST(MaximumPrinciple, FindsExtremumPlantedByObtuseTets) {
  // A flattened octahedron (square of radius 1 in z = 0, apexes at z = +-0.2)
  // around one free vertex. At the centre the P1 weights are all positive; moved
  // to (0.5, 0, 0) the flat tets get obtuse dihedral angles and the weight of
  // the far corner (-1, 0, 0) turns negative. With u = 0 there and u = 1 on the
  // other five neighbours, the discrete harmonic value exceeds 1: a planted maximum.
  auto build = [](double x) {
    Eigen::MatrixXd V(7, 3);
    V << x, 0, 0, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0, 0, 0, 0.2, 0, 0, -0.2;
    Eigen::MatrixXi T(8, 4);
    for (int i = 0; i < 4; ++i) {
      const int a = 1 + i, b = 1 + (i + 1) % 4;
      T.row(2 * i) << 0, a, b, 5;
      T.row(2 * i + 1) << 0, b, a, 6;
    }
    param_test::orient_positive(V, T);
    return std::make_pair(V, T);
  };
  std::vector<char> dir = {0, 1, 1, 1, 1, 1, 1};
  for (double x : {0.0, 0.5}) {
    const auto [V, T] = build(x);
    const auto K = tet_stiffness(V, T);
    const Eigen::VectorXd u = harmonic_field(K, {{{1, 2, 4, 5, 6}, 1.0}, {{3}, 0.0}});
    const auto ext = find_interior_extrema(K, u, dir);
    if (x == 0.0) {
      EXPECT_GT(K.coeff(0, 3), -1e300);
      EXPECT_LT(K.coeff(0, 3), 0.0);  // Delaunay-like: all couplings negative
      EXPECT_TRUE(ext.empty());
      EXPECT_LT(u(0), 1.0);
    } else {
      EXPECT_GT(K.coeff(0, 3), 0.0);  // the obtuse tets flip the sign of this coupling
      ASSERT_EQ(ext.size(), 1u);
      EXPECT_EQ(ext[0].vertex, 0);
      EXPECT_TRUE(ext[0].maximum);
      EXPECT_GT(u(0), 1.05);
      EXPECT_NEAR(ext[0].margin, u(0) - 1.0, 1e-14);
    }
  }
}
