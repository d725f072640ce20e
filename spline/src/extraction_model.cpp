#include "igaprep/spline/extraction_model.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "igaprep/core/error.h"
#include "igaprep/spline/basis.h"
#include "igaprep/spline/bezier_extraction.h"
#include "igaprep/spline/multipatch_topology.h"

namespace igaprep::spline {

namespace {

double diagonal_of(const MultiPatch& mp) {
  Eigen::RowVector3d lo = Eigen::RowVector3d::Constant(INFINITY), hi = -lo;
  for (const Patch& p : mp.patches) {
    lo = lo.cwiseMin(p.control_points.colwise().minCoeff());
    hi = hi.cwiseMax(p.control_points.colwise().maxCoeff());
  }
  return (hi - lo).norm();
}

// Control point and weight of every global function, from its first copy;
// every other copy must agree (a conforming model).
void set_functions(const MultiPatch& mp, const GlobalNumbering& num, ExtractionModel& out) {
  out.control_points.resize(num.count, 3);
  out.weights.resize(num.count);
  std::vector<bool> set(static_cast<std::size_t>(num.count), false);
  const double tol = 1e-12 * std::max(diagonal_of(mp), 1e-300);
  for (std::size_t p = 0; p < mp.patches.size(); ++p) {
    const Patch& patch = mp.patches[p];
    for (Eigen::Index l = 0; l < patch.control_points.rows(); ++l) {
      const int g = num.global[p][static_cast<std::size_t>(l)];
      const double w = patch.rational() ? patch.weights[l] : 1.0;
      if (!set[static_cast<std::size_t>(g)]) {
        set[static_cast<std::size_t>(g)] = true;
        out.control_points.row(g) = patch.control_points.row(l);
        out.weights[g] = w;
      } else if ((out.control_points.row(g) - patch.control_points.row(l)).norm() > tol ||
                 std::abs(out.weights[g] - w) > 1e-12 * std::abs(w)) {
        throw bad_input("extraction model: patch " + std::to_string(p) + " control point " + std::to_string(l) +
                        " differs from another copy of the same function (the model is not conforming)");
      }
    }
  }
}

// Operators shared by elements: a 3-D operator is the Kronecker product of
// three 1-D ones, so it is keyed by the ids of its 1-D operators (equal to
// 1e-13) and built once.
class OperatorTable {
 public:
  explicit OperatorTable(std::vector<Eigen::MatrixXd>& operators) : operators_(operators) {}
  int id(const PatchExtraction& ex, int eu, int ev, int ew) {
    const int at[3] = {eu, ev, ew};
    std::array<int, 3> key{};
    for (int d = 0; d < 3; ++d) key[static_cast<std::size_t>(d)] = id_1d(ex.dirs[static_cast<std::size_t>(d)].C[static_cast<std::size_t>(at[d])]);
    const auto [it, added] = ids_.emplace(key, static_cast<int>(operators_.size()));
    if (added) operators_.push_back(element_extraction_operator(ex, eu, ev, ew));
    return it->second;
  }

 private:
  int id_1d(const Eigen::MatrixXd& C) {
    std::vector<long long> key{C.rows()};
    for (Eigen::Index i = 0; i < C.size(); ++i) key.push_back(std::llround(C.data()[i] * 1e13));
    return ids_1d_.emplace(key, static_cast<int>(ids_1d_.size())).first->second;
  }
  std::vector<Eigen::MatrixXd>& operators_;
  std::map<std::vector<long long>, int> ids_1d_;
  std::map<std::array<int, 3>, int> ids_;
};

void add_patch_elements(const MultiPatch& mp, const GlobalNumbering& num, int p, OperatorTable& operators,
                        ExtractionModel& out) {
  const Patch& patch = mp.patches[static_cast<std::size_t>(p)];
  const PatchExtraction ex = bezier_extraction(patch);
  const int first = static_cast<int>(out.elements.size());
  for (int ew = 0; ew < ex.element_count(2); ++ew)
    for (int ev = 0; ev < ex.element_count(1); ++ev)
      for (int eu = 0; eu < ex.element_count(0); ++eu) {
        ExtractionElement e;
        e.degrees = patch.degrees;
        for (const int l : element_control_points(patch, ex, eu, ev, ew))
          e.functions.push_back(num.global[static_cast<std::size_t>(p)][static_cast<std::size_t>(l)]);
        e.extraction = operators.id(ex, eu, ev, ew);
        e.material = patch.material;
        e.patch = p;
        e.index = {{eu, ev, ew}};
        e.box = eu + ex.element_count(0) * (ev + ex.element_count(1) * ew);
        const int at[3] = {eu, ev, ew};
        for (int d = 0; d < 3; ++d)
          e.domain[static_cast<std::size_t>(d)] = {{ex.dirs[static_cast<std::size_t>(d)].breaks[static_cast<std::size_t>(at[d])],
                                                    ex.dirs[static_cast<std::size_t>(d)].breaks[static_cast<std::size_t>(at[d]) + 1]}};
        out.elements.push_back(std::move(e));
      }
  // The element faces on the patch's labelled sides and on its interfaces with a surface.
  auto add_faces = [&](Side side, int label, std::vector<ExtractionBoundaryFace>& faces) {
    const int n = side.direction(), last = ex.element_count(n) - 1;
    for (int ew = 0; ew < ex.element_count(2); ++ew)
      for (int ev = 0; ev < ex.element_count(1); ++ev)
        for (int eu = 0; eu < ex.element_count(0); ++eu) {
          const int at[3] = {eu, ev, ew};
          if (at[n] != (side.parameter() ? last : 0)) continue;
          faces.push_back({first + eu + ex.element_count(0) * (ev + ex.element_count(1) * ew), side, label});
        }
  };
  for (const BoundarySide& b : mp.boundaries)
    if (b.patch == p) add_faces(b.side, b.label, out.boundary_faces);
  for (const Interface& itf : mp.interfaces)
    if (itf.patch_a == p && itf.surface >= 0) add_faces(itf.side_a, itf.surface, out.interface_faces);
}

}  // namespace

bool ExtractionModel::rational() const { return (weights.array() != 1.0).any(); }

ExtractionModel extraction_model(const MultiPatch& mp) {
  if (mp.patches.empty()) throw bad_input("extraction model: the model has no patches");
  validate_multipatch(mp);
  const GlobalNumbering num = global_numbering(mp);
  ExtractionModel out;
  set_functions(mp, num, out);
  OperatorTable operators(out.operators);
  for (int p = 0; p < static_cast<int>(mp.patches.size()); ++p) add_patch_elements(mp, num, p, operators, out);
  copy_model_descriptions(mp, out);
  return out;
}

void copy_model_descriptions(const MultiPatch& mp, ExtractionModel& out) {
  out.labels = mp.labels;
  out.materials = mp.materials;
  out.provenance_generator = mp.provenance_generator;
  out.provenance_case = mp.provenance_case;
  out.provenance_inputs = mp.provenance_inputs;
}

BezierElement bernstein_element(const ExtractionModel& m, int element) {
  const ExtractionElement& e = m.elements.at(static_cast<std::size_t>(element));
  const bool rational = m.rational();
  Eigen::MatrixXd H(static_cast<Eigen::Index>(e.functions.size()), rational ? 4 : 3);
  for (std::size_t r = 0; r < e.functions.size(); ++r) {
    const double w = m.weights[e.functions[r]];
    if (rational)
      H.row(static_cast<Eigen::Index>(r)) << w * m.control_points.row(e.functions[r]), w;
    else
      H.row(static_cast<Eigen::Index>(r)) = m.control_points.row(e.functions[r]);
  }
  BezierElement out = bezier_element_from(m.C(element), H);
  out.domain = e.domain;
  return out;
}

Eigen::VectorXd element_basis(const ExtractionModel& m, int element, const Eigen::Vector3d& t) {
  const ExtractionElement& e = m.elements.at(static_cast<std::size_t>(element));
  std::array<std::vector<double>, 3> B;
  for (int d = 0; d < 3; ++d) {
    B[static_cast<std::size_t>(d)].resize(static_cast<std::size_t>(e.degrees[static_cast<std::size_t>(d)] + 1));
    bernstein_basis(e.degrees[static_cast<std::size_t>(d)], t[d], B[static_cast<std::size_t>(d)].data());
  }
  const Eigen::MatrixXd& C = m.C(element);
  Eigen::VectorXd bernstein(C.cols());
  const int nu = e.degrees[0] + 1, nv = e.degrees[1] + 1;
  for (Eigen::Index b = 0; b < C.cols(); ++b)
    bernstein[b] = B[0][static_cast<std::size_t>(b % nu)] * B[1][static_cast<std::size_t>((b / nu) % nv)] *
                   B[2][static_cast<std::size_t>(b / (nu * nv))];
  Eigen::VectorXd R = C * bernstein;  // the element's functions at t
  double W = 0.0;
  for (std::size_t r = 0; r < e.functions.size(); ++r) {
    R[static_cast<Eigen::Index>(r)] *= m.weights[e.functions[r]];
    W += R[static_cast<Eigen::Index>(r)];
  }
  return R / W;
}

Eigen::Vector3d evaluate_element(const ExtractionModel& m, int element, const Eigen::Vector3d& t) {
  const ExtractionElement& e = m.elements.at(static_cast<std::size_t>(element));
  const Eigen::VectorXd R = element_basis(m, element, t);
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (std::size_t r = 0; r < e.functions.size(); ++r) x += R[static_cast<Eigen::Index>(r)] * m.control_points.row(e.functions[r]).transpose();
  return x;
}

std::vector<int> face_functions(const ExtractionModel& m, int element, Side side) {
  const ExtractionElement& e = m.elements[static_cast<std::size_t>(element)];
  const Eigen::MatrixXd& C = m.C(element);
  const int n = side.direction(), at = side.parameter() ? e.degrees[static_cast<std::size_t>(n)] : 0;
  const int nu = e.degrees[0] + 1, nv = e.degrees[1] + 1;
  std::vector<int> out;
  for (Eigen::Index r = 0; r < C.rows(); ++r)
    for (Eigen::Index b = 0; b < C.cols(); ++b) {
      const int index[3] = {static_cast<int>(b % nu), static_cast<int>((b / nu) % nv), static_cast<int>(b / (nu * nv))};
      if (index[n] == at && std::abs(C(r, b)) > 1e-14) {
        out.push_back(static_cast<int>(r));
        break;
      }
    }
  return out;
}

}  // namespace igaprep::spline
