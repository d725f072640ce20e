#include "igaprep/iga_check/extraction_solve.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <string>

#include "elasticity_linear_solve.h"
#include "extraction_pattern.h"
#include "extraction_values.h"
#include "igaprep/core/error.h"
#include "igaprep/core/parallel.h"
#include "igaprep/iga_check/elasticity_material.h"
#include "igaprep/spline/gauss_legendre.h"

namespace igaprep::iga_check {

namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

int label_of(const spline::ExtractionModel& m, const std::string& label, const std::string& what) {
  for (std::size_t l = 0; l < m.labels.size(); ++l)
    if (m.labels[l] == label) return static_cast<int>(l);
  throw bad_input(what + ": the model has no side labelled '" + label + "'");
}

// Gauss points and weights on [0, 1] per direction of an element.
std::array<Eigen::VectorXd, 3> gauss_points(const spline::ExtractionElement& e, int extra, std::array<Eigen::VectorXd, 3>& weights) {
  std::array<Eigen::VectorXd, 3> t;
  for (std::size_t d = 0; d < 3; ++d) spline::gauss_legendre(e.degrees[d] + 1 + extra, t[d], weights[d]);
  return t;
}

// One labelled element face at its Gauss points: the basis there and the
// vector area n dA per point (Nanson: det J J^-T e_n, outward).
struct FaceValues {
  detail::ExtractionValues v;
  Eigen::MatrixXd area;  // 3 x nq
};

FaceValues face_values(const spline::ExtractionModel& m, const spline::ExtractionBoundaryFace& f, int extra) {
  const spline::ExtractionElement& e = m.elements[static_cast<std::size_t>(f.element)];
  std::array<Eigen::VectorXd, 3> w;
  std::array<Eigen::VectorXd, 3> t = gauss_points(e, extra, w);
  const int n = f.side.direction();
  const double end = f.side.parameter() ? 1.0 : 0.0;
  t[static_cast<std::size_t>(n)] = Eigen::VectorXd::Constant(1, end);
  w[static_cast<std::size_t>(n)] = Eigen::VectorXd::Constant(1, f.side.parameter() ? 1.0 : -1.0);
  FaceValues out{detail::extraction_values(m, f.element, t), Eigen::MatrixXd()};
  const Eigen::Index nq = out.v.R.cols();
  out.area.resize(3, nq);
  const Eigen::Index nu = t[0].size(), nv = t[1].size();
  for (Eigen::Index q = 0; q < nq; ++q) {
    const Eigen::Index a = q % nu, b = q / nu % nv, c = q / (nu * nv);
    const Eigen::Matrix3d& J = out.v.J[static_cast<std::size_t>(q)];
    // |det J| J^-T e_n points out of the element at either orientation.
    const Eigen::Vector3d cof = std::abs(J.determinant()) * J.inverse().transpose().col(n);
    out.area.col(q) = w[0][a] * w[1][b] * w[2][c] * cof;
  }
  return out;
}

// Functions whose trace on the face is not zero (a polynomial of degree p
// vanishing at all (p + 1)^2 Gauss points of the face is zero).
std::vector<int> face_functions(const spline::ExtractionModel& m, const spline::ExtractionBoundaryFace& f, const FaceValues& fv) {
  std::vector<int> out;
  const std::vector<int>& ids = m.elements[static_cast<std::size_t>(f.element)].functions;
  for (Eigen::Index r = 0; r < fv.v.R.rows(); ++r)
    if (fv.v.R.row(r).cwiseAbs().maxCoeff() > 1e-13) out.push_back(ids[static_cast<std::size_t>(r)]);
  return out;
}

// The element stiffness (3n x 3n, dof 3 f + i) and the body-force load.
void element_system(const spline::ExtractionModel& m, int element, const ElasticityProblem& problem, const LameParameters& lame,
                    int extra, Eigen::MatrixXd& K, Eigen::VectorXd& F) {
  const spline::ExtractionElement& e = m.elements[static_cast<std::size_t>(element)];
  std::array<Eigen::VectorXd, 3> w;
  const detail::ExtractionValues v = detail::extraction_values(m, element, gauss_points(e, extra, w));
  const Eigen::Index n = v.R.rows(), nu = w[0].size(), nv = w[1].size();
  F.setZero(3 * n);
  // Per gradient component i the n x nq gradients, plain and times dV:
  // then every block sum_q dV G_i G_j^T is one matrix product.
  std::array<Eigen::MatrixXd, 3> Gq, Gw;
  for (std::size_t i = 0; i < 3; ++i) Gq[i].resize(n, v.R.cols()), Gw[i].resize(n, v.R.cols());
  Eigen::MatrixXd dRt(n, 3);
  for (Eigen::Index q = 0; q < v.R.cols(); ++q) {
    const Eigen::Matrix3d& J = v.J[static_cast<std::size_t>(q)];
    // Either orientation, as long as it holds over the element.
    const double det = J.determinant(), first = v.J[0].determinant();
    if (!(det * first > 0.0))
      throw bad_input("elasticity: the Jacobian determinant vanishes or changes sign in element " + std::to_string(element));
    const double dV = std::abs(det) * w[0][q % nu] * w[1][q / nu % nv] * w[2][q / (nu * nv)];
    for (int d = 0; d < 3; ++d) dRt.col(d) = v.dR[static_cast<std::size_t>(d)].col(q);
    const Eigen::MatrixXd G = dRt * J.inverse();  // physical gradients, n x 3
    for (std::size_t i = 0; i < 3; ++i) {
      Gq[i].col(q) = G.col(static_cast<Eigen::Index>(i));
      Gw[i].col(q) = dV * G.col(static_cast<Eigen::Index>(i));
    }
    Eigen::Vector3d body = problem.body_force;
    const Eigen::Vector3d x = v.x.col(q);
    if (problem.body_force_function) body += problem.body_force_function(x);
    if (problem.rotation) body += problem.rotation->body_force(x);
    for (Eigen::Index a = 0; a < n; ++a) F.segment<3>(3 * a) += dV * v.R(a, q) * body;
  }
  // K_(3a+i)(3b+j) = lambda A_ij + mu A_ji + mu delta_ij sum_k A_kk, A_ij = sum_q dV G_i G_j^T
  // (A_ji = A_ij^T: six products).
  std::array<std::array<Eigen::MatrixXd, 3>, 3> A;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = i; j < 3; ++j) A[i][j].noalias() = Gw[i] * Gq[j].transpose();
  const Eigen::MatrixXd trace = A[0][0] + A[1][1] + A[2][2];
  K.resize(3 * n, 3 * n);
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) {
      const Eigen::Index ii = static_cast<Eigen::Index>(i), jj = static_cast<Eigen::Index>(j);
      for (Eigen::Index b = 0; b < n; ++b)
        for (Eigen::Index a = 0; a < n; ++a) {
          const double aij = i <= j ? A[i][j](a, b) : A[j][i](b, a), aji = j <= i ? A[j][i](a, b) : A[i][j](b, a);
          K(3 * a + ii, 3 * b + jj) = lame.lambda * aij + lame.mu * aji + (i == j ? lame.mu * trace(a, b) : 0.0);
        }
    }
}

struct Constraints {
  std::vector<unsigned char> set;  // 3 f + i
  Eigen::VectorXd value;
};

// Prescribed values: the L2 projection of each PrescribedSide onto the
// traces of the functions on its faces, solved once over all of them.
void project_prescribed(const spline::ExtractionModel& m, const ElasticityProblem& problem, int extra, Constraints& c) {
  if (problem.prescribed.empty()) return;
  std::map<int, int> local;  // function -> row
  Triplets mass;
  std::vector<Eigen::Vector3d> rhs;
  for (const PrescribedSide& ps : problem.prescribed) {
    const int label = label_of(m, ps.label, "prescribed displacement");
    for (const spline::ExtractionBoundaryFace& f : m.boundary_faces) {
      if (f.label != label) continue;
      const FaceValues fv = face_values(m, f, extra);
      const std::vector<int>& ids = m.elements[static_cast<std::size_t>(f.element)].functions;
      const std::vector<int> on_face = face_functions(m, f, fv);
      std::vector<bool> traced(ids.size());
      for (std::size_t a = 0; a < ids.size(); ++a) traced[a] = std::find(on_face.begin(), on_face.end(), ids[a]) != on_face.end();
      for (Eigen::Index q = 0; q < fv.v.R.cols(); ++q) {
        const double dA = fv.area.col(q).norm();
        const Eigen::Vector3d u = ps.displacement(fv.v.x.col(q));
        for (Eigen::Index a = 0; a < fv.v.R.rows(); ++a) {
          if (!traced[static_cast<std::size_t>(a)]) continue;
          const int ra = local.emplace(ids[static_cast<std::size_t>(a)], static_cast<int>(local.size())).first->second;
          if (ra >= static_cast<int>(rhs.size())) rhs.resize(static_cast<std::size_t>(ra) + 1, Eigen::Vector3d::Zero());
          rhs[static_cast<std::size_t>(ra)] += dA * fv.v.R(a, q) * u;
          for (Eigen::Index b = 0; b < fv.v.R.rows(); ++b) {
            if (!traced[static_cast<std::size_t>(b)]) continue;
            const int rb = local.emplace(ids[static_cast<std::size_t>(b)], static_cast<int>(local.size())).first->second;
            mass.emplace_back(ra, rb, dA * fv.v.R(a, q) * fv.v.R(b, q));
          }
        }
      }
    }
  }
  const Eigen::Index n = static_cast<Eigen::Index>(local.size());
  rhs.resize(static_cast<std::size_t>(n), Eigen::Vector3d::Zero());
  Eigen::SparseMatrix<double> M(n, n);
  M.setFromTriplets(mass.begin(), mass.end());
  Eigen::MatrixXd b(n, 3);
  for (Eigen::Index r = 0; r < n; ++r) b.row(r) = rhs[static_cast<std::size_t>(r)].transpose();
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(M);
  if (solver.info() != Eigen::Success) throw internal_error("elasticity: the prescribed sides' mass matrix is singular");
  const Eigen::MatrixXd values = solver.solve(b);
  for (const auto& [f, r] : local)
    for (int i = 0; i < 3; ++i) {
      c.set[static_cast<std::size_t>(3 * f + i)] = 1;
      c.value[3 * f + i] = values(r, i);
    }
}

Constraints constraints(const spline::ExtractionModel& m, const ElasticityProblem& problem, int extra) {
  Constraints c{std::vector<unsigned char>(static_cast<std::size_t>(3 * m.function_count()), 0),
                Eigen::VectorXd::Zero(3 * m.function_count())};
  project_prescribed(m, problem, extra, c);
  for (const FixedSide& fs : problem.fixed) {
    const int label = label_of(m, fs.label, "fixed side");
    for (const spline::ExtractionBoundaryFace& f : m.boundary_faces) {
      if (f.label != label) continue;
      for (const int g : face_functions(m, f, face_values(m, f, extra)))
        for (int i = 0; i < 3; ++i)
          if (fs.components[static_cast<std::size_t>(i)]) {
            c.set[static_cast<std::size_t>(3 * g + i)] = 1;
            c.value[3 * g + i] = 0.0;
          }
    }
  }
  return c;
}

// The area of the element faces labelled `label`.
double labelled_area(const spline::ExtractionModel& m, int label, int extra) {
  double area = 0.0;
  for (const spline::ExtractionBoundaryFace& f : m.boundary_faces)
    if (f.label == label) area += face_values(m, f, extra).area.colwise().norm().sum();
  return area;
}

// Surface loads: tractions, pressures (-p n) and forces spread over their sides' area.
void add_surface_loads(const spline::ExtractionModel& m, const ElasticityProblem& problem, int extra, Eigen::VectorXd& F) {
  auto load = [&](int label, const std::function<Eigen::Vector3d(const Eigen::Vector3d& area)>& force_per) {
    for (const spline::ExtractionBoundaryFace& f : m.boundary_faces) {
      if (f.label != label) continue;
      const FaceValues fv = face_values(m, f, extra);
      const std::vector<int>& ids = m.elements[static_cast<std::size_t>(f.element)].functions;
      for (Eigen::Index q = 0; q < fv.v.R.cols(); ++q) {
        const Eigen::Vector3d t = force_per(fv.area.col(q));
        for (Eigen::Index a = 0; a < fv.v.R.rows(); ++a) F.segment<3>(3 * ids[static_cast<std::size_t>(a)]) += fv.v.R(a, q) * t;
      }
    }
  };
  for (const TractionLoad& t : problem.tractions)
    load(label_of(m, t.label, "traction"), [&](const Eigen::Vector3d& a) { return Eigen::Vector3d(a.norm() * t.traction); });
  for (const PressureLoad& p : problem.pressures)
    load(label_of(m, p.label, "pressure"), [&](const Eigen::Vector3d& a) { return Eigen::Vector3d(-p.pressure * a); });
  for (const ForceLoad& fl : problem.forces) {
    double area = 0.0;
    std::vector<int> labels;
    for (const std::string& l : fl.labels) labels.push_back(label_of(m, l, "force"));
    for (const int l : labels) area += labelled_area(m, l, extra);
    if (!(area > 0.0)) throw bad_input("force: its sides have no area");
    for (const int l : labels) load(l, [&](const Eigen::Vector3d& a) { return Eigen::Vector3d(a.norm() / area * fl.force); });
  }
}

}  // namespace

ExtractionSolution solve_elasticity(const spline::ExtractionModel& model, const ElasticityProblem& problem,
                                    const ElasticityOptions& options) {
  if (options.refine != 0 || options.elevate != 0)
    throw bad_input("elasticity on an extraction model: refine the T-spline instead of --refine / --elevate");
  const auto start = std::chrono::steady_clock::now();
  const int extra = options.extra_quadrature;
  const Eigen::Index dofs = 3 * model.function_count();
  const Constraints c = constraints(model, problem, extra);
  ExtractionSolution out;
  for (Eigen::Index i = 0; i < dofs; ++i)
    if (!c.set[static_cast<std::size_t>(i)]) ++out.report.unknowns;
  out.report.fixed_dofs = dofs - out.report.unknowns;
  detail::BlockLowerMatrix assembled(model);
  Eigen::VectorXd F = Eigen::VectorXd::Zero(dofs);
  // Element matrices on all cores, a batch at a time; added in element order
  // on one (the same sums whatever the thread count).
  const std::size_t batch = 128;
  std::vector<Eigen::MatrixXd> Ke(batch);
  std::vector<Eigen::VectorXd> Fe(batch);
  for (std::size_t first = 0; first < model.elements.size(); first += batch) {
    const std::size_t count = std::min(batch, model.elements.size() - first);
    parallel_for(count, [&](std::size_t i) {
      const spline::ExtractionElement& el = model.elements[first + i];
      const spline::Material& mat = model.materials.at(static_cast<std::size_t>(el.material));
      element_system(model, static_cast<int>(first + i), problem, lame_parameters(mat.young_modulus, mat.poisson_ratio, mat.name), extra,
                     Ke[i], Fe[i]);
    });
    for (std::size_t i = 0; i < count; ++i) {
      const spline::ExtractionElement& el = model.elements[first + i];
      assembled.add(el.functions, Ke[i]);
      for (Eigen::Index a = 0; a < Fe[i].size(); ++a) F[3 * el.functions[static_cast<std::size_t>(a / 3)] + a % 3] += Fe[i][a];
      out.report.quadrature_points += (el.degrees[0] + 1 + extra) * (el.degrees[1] + 1 + extra) * (el.degrees[2] + 1 + extra);
    }
  }
  out.report.elements = static_cast<long long>(model.elements.size());
  add_surface_loads(model, problem, extra, F);
  // Constraints in place: F_f -= K_fc u_c, then a constrained dof's row and
  // column become the identity and its load its value (K keeps its pattern).
  detail::SparseMatrix& K = assembled.matrix();
  const std::vector<double> original(K.valuePtr(), K.valuePtr() + K.nonZeros());
  for (int col = 0; col < K.outerSize(); ++col)
    for (detail::SparseMatrix::InnerIterator it(K, col); it; ++it) {
      const int i = static_cast<int>(it.row()), j = col;
      const bool ci = c.set[static_cast<std::size_t>(i)], cj = c.set[static_cast<std::size_t>(j)];
      if (!ci && cj) F[i] -= it.value() * c.value[j];
      if (ci && !cj) F[j] -= it.value() * c.value[i];
    }
  for (int col = 0; col < K.outerSize(); ++col)
    for (detail::SparseMatrix::InnerIterator it(K, col); it; ++it) {
      const int i = static_cast<int>(it.row());
      if (c.set[static_cast<std::size_t>(i)] || c.set[static_cast<std::size_t>(col)]) it.valueRef() = i == col ? 1.0 : 0.0;
    }
  for (Eigen::Index i = 0; i < dofs; ++i)
    if (c.set[static_cast<std::size_t>(i)]) F[i] = c.value[i];
  out.report.nonzeros = K.nonZeros();
  out.report.assembly_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto solve_start = std::chrono::steady_clock::now();
  detail::NodalLayout layout{std::vector<int>(static_cast<std::size_t>(dofs)), model.control_points};
  std::iota(layout.row_of.begin(), layout.row_of.end(), 0);  // constraints are rows of K already
  Eigen::VectorXd u = detail::solve_linear_system(K, F, layout, options, out.report);
  for (Eigen::Index i = 0; i < dofs; ++i)
    if (c.set[static_cast<std::size_t>(i)]) u[i] = c.value[i];  // exactly, whatever the solver's tolerance
  out.report.solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - solve_start).count();
  // 1/2 u^T K u with the matrix as assembled (the lower triangle).
  double energy = 0.0;
  for (int col = 0, at = 0; col < K.outerSize(); ++col)
    for (detail::SparseMatrix::InnerIterator it(K, col); it; ++it, ++at)
      energy += original[static_cast<std::size_t>(at)] * u[it.row()] * u[col] * (it.row() == col ? 1.0 : 2.0);
  out.report.strain_energy = 0.5 * energy;
  out.displacement = Eigen::Map<const Eigen::MatrixXd>(u.data(), 3, model.function_count()).transpose();
  out.report.max_displacement = out.displacement.rowwise().norm().maxCoeff();
  return out;
}

ExtractionPointValue evaluate_solution(const spline::ExtractionModel& model, const Eigen::MatrixXd& displacement, int element,
                                       const Eigen::Vector3d& t) {
  const std::array<Eigen::VectorXd, 3> at{{Eigen::VectorXd::Constant(1, t[0]), Eigen::VectorXd::Constant(1, t[1]),
                                           Eigen::VectorXd::Constant(1, t[2])}};
  const detail::ExtractionValues v = detail::extraction_values(model, element, at);
  const std::vector<int>& ids = model.elements[static_cast<std::size_t>(element)].functions;
  ExtractionPointValue out{v.x.col(0), Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero()};
  Eigen::Matrix3d du_dt = Eigen::Matrix3d::Zero();
  for (Eigen::Index a = 0; a < v.R.rows(); ++a) {
    const Eigen::Vector3d c = displacement.row(ids[static_cast<std::size_t>(a)]).transpose();
    out.displacement += v.R(a, 0) * c;
    for (int d = 0; d < 3; ++d) du_dt.col(d) += v.dR[static_cast<std::size_t>(d)](a, 0) * c;
  }
  out.gradient = du_dt * v.J[0].inverse();
  return out;
}

}  // namespace igaprep::iga_check
