#include "igaprep/spline/tspline_fit.h"

#include <Eigen/Sparse>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <unordered_map>

#include "igaprep/core/error.h"
#include "igaprep/spline/bezier_extraction.h"

namespace igaprep::spline {

namespace {

Eigen::Vector3d face_coordinates(Side side, const Eigen::Vector2d& uv) {
  Eigen::Vector3d t;
  t[side.direction()] = side.parameter() ? 1.0 : 0.0;
  const std::array<int, 2> tan = side.tangent_directions();
  t[tan[0]] = uv[0];
  t[tan[1]] = uv[1];
  return t;
}

// The model's elements as Bezier elements, made when first asked: a fit
// step evaluates each face at many points, and a Bernstein sum is far
// cheaper than the element's basis (C_e times the Bernstein values).
class ElementPoints {
 public:
  explicit ElementPoints(const ExtractionModel& m) : m_(m), bezier_(m.elements.size()), made_(m.elements.size(), false) {}

  Eigen::Vector3d at(int element, const Eigen::Vector3d& t) {
    const std::size_t e = static_cast<std::size_t>(element);
    if (!made_[e]) bezier_[e] = bernstein_element(m_, element), made_[e] = true;
    return evaluate_bezier(bezier_[e], m_.elements[e].degrees, t);
  }
  Eigen::Vector3d on_face(int element, Side side, const Eigen::Vector2d& uv) { return at(element, face_coordinates(side, uv)); }

 private:
  const ExtractionModel& m_;
  std::vector<BezierElement> bezier_;
  std::vector<bool> made_;
};

// The face's unit normal at uv, pointing out of the element (zero where the
// face is degenerate).
Eigen::Vector3d outward_normal(ElementPoints& points, int element, Side side, const Eigen::Vector2d& uv) {
  constexpr double h = 1e-5;
  std::array<Eigen::Vector3d, 2> tangent;
  for (int k = 0; k < 2; ++k) {
    Eigen::Vector2d lo = uv, hi = uv;
    lo[k] = std::max(0.0, uv[k] - h);
    hi[k] = std::min(1.0, uv[k] + h);
    tangent[static_cast<std::size_t>(k)] = points.on_face(element, side, hi) - points.on_face(element, side, lo);
  }
  Eigen::Vector3d n = tangent[0].cross(tangent[1]);
  if (!(n.norm() > 1e-14 * (tangent[0].norm() * tangent[1].norm() + 1e-300))) return Eigen::Vector3d::Zero();
  Eigen::Vector3d inside = face_coordinates(side, uv);
  inside[side.direction()] = side.parameter() ? 1.0 - 1e-4 : 1e-4;
  if (n.dot(points.on_face(element, side, uv) - points.at(element, inside)) < 0.0) n = -n;
  return n.normalized();
}

// Per function: the surfaces whose faces it does not vanish on.
std::vector<std::set<int>> surfaces_of_functions(const ExtractionModel& m) {
  std::vector<std::set<int>> out(static_cast<std::size_t>(m.function_count()));
  for (const auto* list : {&m.boundary_faces, &m.interface_faces})
    for (const ExtractionBoundaryFace& f : *list)
      for (const int r : face_functions(m, f.element, f.side))
        out[static_cast<std::size_t>(m.elements[static_cast<std::size_t>(f.element)].functions[static_cast<std::size_t>(r)])].insert(f.label);
  return out;
}

double rms_distance(const ExtractionModel& m, const std::vector<ExtractionFitPair>& pairs) {
  double sum = 0.0;
  ElementPoints points(m);
  for (const ExtractionFitPair& p : pairs) sum += (points.on_face(p.element, p.side, p.uv) - p.target).squaredNorm();
  return pairs.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(pairs.size()));
}

// The free functions of one surface, numbered as unknowns, and the faces
// whose free functions the fairing ties together.
struct FreeFunctions {
  std::unordered_map<int, int> unknown;  // function -> unknown
  std::vector<int> function;             // unknown -> function
  std::vector<std::vector<int>> faces;   // per face of the surface: its free unknowns
};

FreeFunctions free_functions(const ExtractionModel& m, int surface) {
  const std::vector<std::set<int>> on = surfaces_of_functions(m);
  FreeFunctions out;
  for (const auto* list : {&m.boundary_faces, &m.interface_faces})
    for (const ExtractionBoundaryFace& f : *list) {
      if (f.label != surface) continue;
      std::vector<int> face;
      for (const int r : face_functions(m, f.element, f.side)) {
        const int g = m.elements[static_cast<std::size_t>(f.element)].functions[static_cast<std::size_t>(r)];
        if (on[static_cast<std::size_t>(g)].size() != 1) continue;  // on two surfaces: stays
        const auto [it, added] = out.unknown.emplace(g, static_cast<int>(out.function.size()));
        if (added) out.function.push_back(g);
        face.push_back(it->second);
      }
      out.faces.push_back(std::move(face));
    }
  return out;
}

// The normal equations' sums over one element's pairs: its free functions
// (positions in the element and unknowns), sum R R^T and sum R residual^T
// over those functions. Summed per element, not per pair: an element holds
// many pairs, and one set of triplets per element keeps the assembly small.
struct ElementSums {
  std::vector<int> rows, unknowns;
  Eigen::MatrixXd RR, Rres;
};

ElementSums element_sums(const ExtractionModel& m, const FreeFunctions& free, int element) {
  ElementSums s;
  const std::vector<int>& fns = m.elements[static_cast<std::size_t>(element)].functions;
  for (std::size_t r = 0; r < fns.size(); ++r)
    if (const auto it = free.unknown.find(fns[r]); it != free.unknown.end()) {
      s.rows.push_back(static_cast<int>(r));
      s.unknowns.push_back(it->second);
    }
  s.RR = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(s.rows.size()), static_cast<Eigen::Index>(s.rows.size()));
  s.Rres = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(s.rows.size()), 3);
  return s;
}

// One linearized step: the offsets along the functions' normals.
double fit_step(ExtractionModel& m, const FreeFunctions& free, const std::vector<ExtractionFitPair>& pairs, double smoothing) {
  const Eigen::Index k = static_cast<Eigen::Index>(free.function.size());
  std::unordered_map<int, ElementSums> sums;
  Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(k, 3);
  ElementPoints points(m);
  for (const ExtractionFitPair& p : pairs) {
    auto it = sums.find(p.element);
    if (it == sums.end()) it = sums.emplace(p.element, element_sums(m, free, p.element)).first;
    ElementSums& e = it->second;
    const Eigen::VectorXd R = element_basis(m, p.element, face_coordinates(p.side, p.uv));
    const Eigen::Vector3d n = outward_normal(points, p.element, p.side, p.uv);
    const Eigen::Vector3d residual = p.target - points.on_face(p.element, p.side, p.uv);
    Eigen::VectorXd Rf(static_cast<Eigen::Index>(e.rows.size()));
    for (std::size_t i = 0; i < e.rows.size(); ++i) {
      Rf[static_cast<Eigen::Index>(i)] = R[e.rows[i]];
      if (std::abs(Rf[static_cast<Eigen::Index>(i)]) >= 1e-14) normal.row(e.unknowns[i]) += Rf[static_cast<Eigen::Index>(i)] * n.transpose();
    }
    e.RR.noalias() += Rf * Rf.transpose();
    e.Rres.noalias() += Rf * residual.transpose();
  }
  for (Eigen::Index i = 0; i < k; ++i)
    if (normal.row(i).norm() > 0.0) normal.row(i).normalize();
  std::vector<Eigen::Triplet<double>> a;
  Eigen::VectorXd b = Eigen::VectorXd::Zero(k), diagonal = Eigen::VectorXd::Zero(k);
  for (const auto& [element, e] : sums)
    for (std::size_t x = 0; x < e.unknowns.size(); ++x) {
      const int i = e.unknowns[x];
      b[i] += normal.row(i).dot(e.Rres.row(static_cast<Eigen::Index>(x)));
      for (std::size_t y = 0; y < e.unknowns.size(); ++y) {
        const double rr = e.RR(static_cast<Eigen::Index>(x), static_cast<Eigen::Index>(y));
        if (std::abs(rr) < 1e-28) continue;  // a function that vanishes on the element's faces with pairs
        const int j = e.unknowns[y];
        const double v = rr * normal.row(i).dot(normal.row(j));
        a.emplace_back(i, j, v);
        if (i == j) diagonal[i] += v;
      }
    }
  const double mean = k > 0 ? diagonal.sum() / static_cast<double>(k) : 0.0;
  if (!(mean > 0.0)) return 0.0;
  for (const std::vector<int>& face : free.faces)  // fairing: a graph Laplacian over each face's unknowns
    for (std::size_t x = 0; x < face.size(); ++x)
      for (std::size_t y = x + 1; y < face.size(); ++y) {
        const double w = smoothing * mean / static_cast<double>(face.size());
        a.insert(a.end(), {{face[x], face[x], w}, {face[y], face[y], w}, {face[x], face[y], -w}, {face[y], face[x], -w}});
      }
  for (Eigen::Index i = 0; i < k; ++i) a.emplace_back(i, i, 1e-6 * mean + (normal.row(i).norm() > 0.0 ? 0.0 : mean));
  Eigen::SparseMatrix<double> A(k, k);
  A.setFromTriplets(a.begin(), a.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
  if (solver.info() != Eigen::Success) throw internal_error("T-spline fit: the normal equations are singular");
  const Eigen::VectorXd delta = solver.solve(b);
  double max_move = 0.0;
  for (Eigen::Index i = 0; i < k; ++i) {
    m.control_points.row(free.function[static_cast<std::size_t>(i)]) += delta[i] * normal.row(i);
    max_move = std::max(max_move, std::abs(delta[i]));
  }
  return max_move;
}

// Per element: the largest distance of its pairs on the surfaces.
std::vector<double> element_distances(const ExtractionModel& m, const std::vector<int>& surfaces, const ExtractionFitPairsFn& pairs) {
  std::vector<double> out(m.elements.size(), 0.0);
  ElementPoints points(m);
  for (const int s : surfaces)
    for (const ExtractionFitPair& p : pairs(m, s)) {
      double& d = out[static_cast<std::size_t>(p.element)];
      d = std::max(d, (points.on_face(p.element, p.side, p.uv) - p.target).norm());
    }
  return out;
}

}  // namespace

void carry_extraction_moves_inside(ExtractionModel& m, const Eigen::MatrixXd& before) {
  const std::vector<std::set<int>> on = surfaces_of_functions(m);
  std::vector<int> unknown(static_cast<std::size_t>(m.function_count()), -1);
  int k = 0;
  for (std::size_t f = 0; f < on.size(); ++f)
    if (on[f].empty()) unknown[f] = k++;
  if (k == 0) return;
  // The umbrella Laplacian over "shares an element": each free function's
  // move the mean of its neighbours'.
  std::vector<std::vector<int>> neighbours(static_cast<std::size_t>(k));
  for (const ExtractionElement& e : m.elements)
    for (const int f : e.functions)
      if (unknown[static_cast<std::size_t>(f)] >= 0)
        for (const int g : e.functions)
          if (g != f) neighbours[static_cast<std::size_t>(unknown[static_cast<std::size_t>(f)])].push_back(g);
  for (std::vector<int>& n : neighbours) {
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
  }
  const Eigen::MatrixXd move = m.control_points - before;
  std::vector<Eigen::Triplet<double>> a;
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(k, 3);
  for (int i = 0; i < k; ++i) {
    const double w = 1.0 / static_cast<double>(std::max<std::size_t>(1, neighbours[static_cast<std::size_t>(i)].size()));
    a.emplace_back(i, i, 1.0);
    for (const int g : neighbours[static_cast<std::size_t>(i)]) {
      if (unknown[static_cast<std::size_t>(g)] >= 0)
        a.emplace_back(i, unknown[static_cast<std::size_t>(g)], -w);
      else
        b.row(i) += w * move.row(g);
    }
  }
  Eigen::SparseMatrix<double> A(k, k);
  A.setFromTriplets(a.begin(), a.end());
  Eigen::BiCGSTAB<Eigen::SparseMatrix<double>, Eigen::DiagonalPreconditioner<double>> solver(A);
  solver.setTolerance(1e-8);
  const Eigen::MatrixXd x = solver.solve(b);
  if (solver.info() != Eigen::Success) throw internal_error("T-spline fit: the harmonic carry of the moves did not converge");
  for (std::size_t f = 0; f < unknown.size(); ++f)
    if (unknown[f] >= 0) m.control_points.row(static_cast<Eigen::Index>(f)) = before.row(static_cast<Eigen::Index>(f)) + x.row(unknown[f]);
}

Eigen::Vector3d face_point(const ExtractionModel& m, int element, Side side, const Eigen::Vector2d& uv) {
  return evaluate_element(m, element, face_coordinates(side, uv));
}

ExtractionSurfaceFitResult fit_extraction_surface(ExtractionModel& m, int surface, const ExtractionFitPairsFn& pairs,
                                                  const ExtractionSurfaceFitOptions& options) {
  const FreeFunctions free = free_functions(m, surface);
  ExtractionSurfaceFitResult out;
  out.moved_points = static_cast<int>(free.function.size());
  if (free.function.empty()) return out;
  const Eigen::MatrixXd start = m.control_points;
  std::vector<ExtractionFitPair> current = pairs(m, surface);
  out.rms.push_back(rms_distance(m, current));
  for (int it = 0; it < options.iterations; ++it) {
    fit_step(m, free, current, options.smoothing);
    current = pairs(m, surface);
    out.rms.push_back(rms_distance(m, current));
    const double before = out.rms[out.rms.size() - 2], after = out.rms.back();
    if (!(std::abs(before - after) > options.stop_improvement * before)) break;
  }
  out.max_move = (m.control_points - start).rowwise().norm().maxCoeff();
  return out;
}

TSplineFitResult fit_tspline(TSplineModel& model, const std::vector<int>& surfaces, const ExtractionFitPairsFn& pairs,
                             const TSplineFitOptions& options) {
  if (!(options.tolerance > 0.0)) throw bad_input("T-spline fit: the tolerance must be positive");
  if (options.max_rounds < 0) throw bad_input("T-spline fit: max_rounds must be >= 0");
  TSplineFitResult out;
  for (int round = 0;; ++round) {
    out.model = extraction_model(model);
    const Eigen::MatrixXd before = out.model.control_points;
    for (const int s : surfaces) fit_extraction_surface(out.model, s, pairs, options.fit);
    if (options.carry_inside) carry_extraction_moves_inside(out.model, before);
    const std::vector<double> distance = element_distances(out.model, surfaces, pairs);
    TSplineFitRound r;
    r.functions = out.model.function_count();
    r.elements = static_cast<int>(out.model.elements.size());
    std::set<std::pair<int, int>> boxes;
    for (std::size_t e = 0; e < distance.size(); ++e) {
      r.max_distance = std::max(r.max_distance, distance[e]);
      if (!(distance[e] > options.tolerance)) continue;
      ++r.elements_over;
      boxes.emplace(out.model.elements[e].patch, out.model.elements[e].box);
    }
    out.reached = r.elements_over == 0;
    if (out.reached || round == options.max_rounds) {
      out.rounds.push_back(r);
      return out;
    }
    r.boxes_refined = static_cast<int>(boxes.size());
    out.rounds.push_back(r);
    refine_boxes(model, std::vector<std::pair<int, int>>(boxes.begin(), boxes.end()));
  }
}

}  // namespace igaprep::spline
