// Assembly of the P1 stiffness matrix (tets) and the cotangent Laplacian
// (triangles), lumped mass, gradients; linear functions are reproduced.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "igaprep/core/error.h"
#include "igaprep/param/gradient.h"
#include "igaprep/param/harmonic_field.h"
#include "igaprep/param/stiffness_matrix.h"
#include "param_meshes.h"

using namespace igaprep::param;

namespace {

// Symmetric, zero row sums, x^T K x >= 0 for random x.
void expect_laplacian_properties(const Eigen::SparseMatrix<double>& K) {
  const Eigen::SparseMatrix<double> Kt = K.transpose();
  EXPECT_LE((K - Kt).norm(), 1e-14 * K.norm());
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(K.cols());
  EXPECT_LE((K * ones).cwiseAbs().maxCoeff(), 1e-12 * K.diagonal().maxCoeff());
  std::mt19937 rng(7);
  std::normal_distribution<double> N;
  for (int trial = 0; trial < 5; ++trial) {
    Eigen::VectorXd x(K.cols());
    for (Eigen::Index i = 0; i < x.size(); ++i) x(i) = N(rng);
    EXPECT_GE(x.dot(K * x), 0.0);
  }
  EXPECT_GT(K.diagonal().minCoeff(), 0.0);
}

double linear(const Eigen::RowVector3d& p) { return 0.3 + 1.7 * p.x() - 0.8 * p.y() + 2.5 * p.z(); }

}  // namespace

TEST(Stiffness, SingleTetMatchesClosedForm) {
  // Unit corner tet: grad phi = (-1,-1,-1), e_x, e_y, e_z; volume 1/6.
  Eigen::MatrixXd V(4, 3);
  V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  Eigen::MatrixXi T(1, 4);
  T << 0, 1, 2, 3;
  const Eigen::MatrixXd K = Eigen::MatrixXd(tet_stiffness(V, T));
  Eigen::MatrixXd expected(4, 4);
  expected << 3, -1, -1, -1, -1, 1, 0, 0, -1, 0, 1, 0, -1, 0, 0, 1;
  expected /= 6.0;
  EXPECT_LE((K - expected).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(Stiffness, CotanMatchesCotangentFormula) {
  // Triangle with angles 90 (at 0), 60 (at 1), 30 (at 2): K(1,2) = -cot(90)/2 = 0,
  // K(0,2) = -cot(60)/2, K(0,1) = -cot(30)/2.
  Eigen::MatrixXd V(3, 3);
  V << 0, 0, 0, 1, 0, 0, 0, std::sqrt(3.0), 0;
  Eigen::MatrixXi F(1, 3);
  F << 0, 1, 2;
  const Eigen::MatrixXd K = Eigen::MatrixXd(tri_cotan_laplacian(V, F));
  EXPECT_NEAR(K(1, 2), 0.0, 1e-15);
  EXPECT_NEAR(K(0, 2), -0.5 / std::tan(M_PI / 3), 1e-15);
  EXPECT_NEAR(K(0, 1), -0.5 / std::tan(M_PI / 6), 1e-15);
}

TEST(Stiffness, TetMatrixProperties) {
  const auto m = param_test::box_tets(6, 5, 4, 0.15);
  for (Eigen::Index t = 0; t < m.T.rows(); ++t)
    ASSERT_GT(param_test::tet_volume(m.V, m.T(t, 0), m.T(t, 1), m.T(t, 2), m.T(t, 3)), 0.0);
  const auto K = tet_stiffness(m.V, m.T);
  EXPECT_EQ(K.rows(), m.V.rows());
  expect_laplacian_properties(K);
}

TEST(Stiffness, TriMatrixProperties) {
  const auto m = param_test::square_tris(9, 0.3);
  const auto K = tri_cotan_laplacian(m.V, m.F);
  expect_laplacian_properties(K);
  // A curved surface.
  const auto s = param_test::icosphere(4);
  expect_laplacian_properties(tri_cotan_laplacian(s.V, s.F));
}

TEST(Stiffness, DegenerateAndOutOfRangeCellsAreBadInput) {
  Eigen::MatrixXd V(4, 3);
  V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0;  // flat
  Eigen::MatrixXi T(1, 4);
  T << 0, 1, 2, 3;
  try {
    tet_stiffness(V, T);
    FAIL() << "no error for a flat tet";
  } catch (const igaprep::Error& e) {
    EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput);
    EXPECT_NE(std::string(e.what()).find("tet 0"), std::string::npos) << e.what();
  }
  T << 0, 1, 2, 4;
  EXPECT_THROW(tet_stiffness(V, T), igaprep::Error);
}

TEST(Harmonic, LinearFunctionReproducedOnTets) {
  const auto m = param_test::box_tets(7, 6, 5, 0.15, 3);
  const auto boundary = param_test::box_boundary(m.V);
  ASSERT_LT(boundary.size(), static_cast<size_t>(m.V.rows()));
  Eigen::VectorXd values(m.V.rows());
  for (Eigen::Index i = 0; i < m.V.rows(); ++i) values(i) = linear(m.V.row(i));
  for (LinearSolverKind kind : {LinearSolverKind::Cholesky, LinearSolverKind::ConjugateGradient}) {
    HarmonicSolverOptions opt;
    opt.solver = kind;
    opt.cg_tolerance = 1e-14;
    HarmonicSolver solver(tet_stiffness(m.V, m.T), {boundary}, opt);
    const Eigen::VectorXd u = solver.solve_with(values);
    EXPECT_LE((u - values).cwiseAbs().maxCoeff(), 1e-10) << "solver " << static_cast<int>(kind);
  }
  // The gradient of a linear field is exact per tet and per vertex.
  const Eigen::MatrixXd G = cell_gradients(m.V, m.T, values);
  const Eigen::MatrixXd Gv = vertex_gradients(m.V, m.T, values);
  const Eigen::RowVector3d g(1.7, -0.8, 2.5);
  EXPECT_LE((G.rowwise() - g).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LE((Gv.rowwise() - g).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(Harmonic, LinearFunctionReproducedOnPlanarTriangles) {
  const auto m = param_test::square_tris(12, 0.25, 5);
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {  // jitter keeps every triangle counter-clockwise
    const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    ASSERT_GT((b - a).cross(c - a).z(), 0.0);
  }
  std::vector<int> boundary;
  Eigen::VectorXd values(m.V.rows());
  for (Eigen::Index i = 0; i < m.V.rows(); ++i) {
    values(i) = 0.3 + 1.7 * m.V(i, 0) - 0.8 * m.V(i, 1);
    if (m.V(i, 0) == 0 || m.V(i, 0) == 1 || m.V(i, 1) == 0 || m.V(i, 1) == 1) boundary.push_back(static_cast<int>(i));
  }
  HarmonicSolver solver(tri_cotan_laplacian(m.V, m.F), {boundary});
  const Eigen::VectorXd u = solver.solve_with(values);
  EXPECT_LE((u - values).cwiseAbs().maxCoeff(), 1e-10);
  const Eigen::MatrixXd G = cell_gradients(m.V, m.F, values);
  EXPECT_LE((G.rowwise() - Eigen::RowVector3d(1.7, -0.8, 0.0)).cwiseAbs().maxCoeff(), 1e-11);
}
