#include "elasticity_prescribed.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <sstream>
#include <string>

#include "elasticity_input.h"
#include "elasticity_side_points.h"
#include "igaprep/core/error.h"
#include "igaprep/spline/curve_surface.h"

namespace igaprep::iga_check::detail {

namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

// The prescribed sides and their control points, numbered compactly in order
// of first appearance.
struct ProjectionSides {
  struct Entry {
    spline::BoundarySide side;
    const PrescribedSide* what;
  };
  std::vector<Entry> sides;
  std::vector<int> compact;                     // global control point -> compact index, or -1
  std::vector<std::pair<int, int>> first_seen;  // per compact index: (side, local control point)
  int size = 0;
};

ProjectionSides projection_sides(const spline::MultiPatch& mp, const spline::GlobalNumbering& num,
                                 const std::vector<PrescribedSide>& prescribed) {
  ProjectionSides ps;
  ps.compact.assign(num.count, -1);
  for (const auto& pr : prescribed)
    for (const auto& b : sides_with_label(mp, pr.label, "prescribed displacement")) {
      ps.sides.push_back({b, &pr});
      for (int l : spline::side_control_points(mp.patches[b.patch], b.side)) {
        const int g = num.global[b.patch][l];
        if (ps.compact[g] < 0) {
          ps.compact[g] = ps.size++;
          ps.first_seen.push_back({static_cast<int>(ps.sides.size()) - 1, l});
        }
      }
    }
  return ps;
}

// The boundary mass matrix (lower triangle, as triplets) and the right-hand
// side B (size x 3) of the projection.
void assemble_boundary_mass(const spline::MultiPatch& mp, const spline::GlobalNumbering& num,
                            const std::vector<PatchTables>& tables, const ProjectionSides& ps, Triplets& trip,
                            Eigen::MatrixXd& B) {
  B = Eigen::MatrixXd::Zero(ps.size, 3);
  // Per side element: the side's functions (local index, compact index) and
  // their mass matrix, added to the triplets once per element.
  std::vector<int> act_local, act_c;
  Eigen::MatrixXd Me;
  Eigen::VectorXd r;
  bool fresh = true;
  for (const auto& job : ps.sides) {
    const int p = job.side.patch;
    const spline::Patch& pa = mp.patches[p];
    // Only functions of the side's own control points are non-zero on it.
    std::vector<unsigned char> on_side(pa.control_points.rows(), 0);
    for (int l : spline::side_control_points(pa, job.side.side)) on_side[l] = 1;
    const std::string& label = job.what->label;
    auto point = [&](const ElementValues& ev, Eigen::Index q, const Eigen::Vector3d&, double dA) {
      if (fresh) {
        act_local.clear();
        act_c.clear();
        for (size_t a = 0; a < ev.local.size(); ++a)
          if (on_side[ev.local[a]]) {
            act_local.push_back(static_cast<int>(a));
            act_c.push_back(ps.compact[num.global[p][ev.local[a]]]);
          }
        Me.setZero(act_c.size(), act_c.size());
        r.resize(act_c.size());
        fresh = false;
      }
      const Eigen::Vector3d x = ev.x.row(q).transpose();
      const Eigen::Vector3d u = job.what->displacement(x);
      if (!u.allFinite()) {
        std::ostringstream s;
        s << "prescribed displacement on '" << label << "': not finite at x = (" << x(0) << ", " << x(1) << ", "
          << x(2) << ")";
        throw bad_input(s.str());
      }
      for (size_t i = 0; i < act_local.size(); ++i) r(i) = ev.R(q, act_local[i]);
      Me.noalias() += (dA * r) * r.transpose();
      for (size_t i = 0; i < act_c.size(); ++i) B.row(act_c[i]) += (r(i) * dA) * u.transpose();
    };
    auto end_element = [&] {
      if (fresh) return;  // no point (a collapsed element)
      for (size_t i = 0; i < act_c.size(); ++i)
        for (size_t j = 0; j < act_c.size(); ++j)
          if (act_c[j] <= act_c[i] && Me(i, j) != 0.0) trip.emplace_back(act_c[i], act_c[j], Me(i, j));
      fresh = true;
    };
    for_side_points(pa, job.side.side, tables[p], point, end_element);
  }
}

// A function whose trace has no area (every side it lives on collapses to
// a curve or point) has a zero row: it takes the value at its control
// point, which is where that collapsed side lies. Its off-diagonal entries
// are bounded by the zero diagonal and are dropped.
void pin_collapsed_functions(const spline::MultiPatch& mp, const ProjectionSides& ps, Triplets& trip,
                             Eigen::MatrixXd& B) {
  const int nd = ps.size;
  Eigen::VectorXd diag = Eigen::VectorXd::Zero(nd);
  for (const auto& t : trip)
    if (t.row() == t.col()) diag(t.row()) += t.value();
  const double tiny = 1e-12 * (nd > 0 ? diag.maxCoeff() : 0.0);
  std::vector<unsigned char> collapsed(nd, 0);
  bool any = false;
  for (int c = 0; c < nd; ++c)
    if (!(diag(c) > tiny)) collapsed[c] = 1, any = true;
  if (!any) return;
  trip.erase(std::remove_if(trip.begin(), trip.end(),
                            [&](const Eigen::Triplet<double>& t) { return collapsed[t.row()] || collapsed[t.col()]; }),
             trip.end());
  for (int c = 0; c < nd; ++c) {
    if (!collapsed[c]) continue;
    const auto& [side, local] = ps.first_seen[c];
    const ProjectionSides::Entry& job = ps.sides[side];
    const Eigen::Vector3d x = mp.patches[job.side.patch].control_points.row(local).transpose();
    const Eigen::Vector3d u = job.what->displacement(x);
    if (!u.allFinite()) throw bad_input("prescribed displacement on '" + job.what->label + "': not finite");
    trip.emplace_back(c, c, 1.0);
    B.row(c) = u.transpose();
  }
}

// Solves M C = B (M from its lower triangle); `labels` names the prescribed
// boundaries in errors.
Eigen::MatrixXd solve_projection(int nd, const Triplets& trip, const Eigen::MatrixXd& B, const std::string& labels) {
  Eigen::SparseMatrix<double, Eigen::ColMajor, int> M(nd, nd);
  M.setFromTriplets(trip.begin(), trip.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double, Eigen::ColMajor, int>, Eigen::Lower> ldlt(M);
  if (ldlt.info() != Eigen::Success || ldlt.vectorD().size() != nd ||
      !(ldlt.vectorD().minCoeff() > 1e-13 * ldlt.vectorD().cwiseAbs().maxCoeff()))
    throw bad_input("prescribed displacement on " + labels +
                    ": the boundary mass matrix is singular (a side of zero area?)");
  Eigen::MatrixXd C = ldlt.solve(B);
  if (ldlt.info() != Eigen::Success || !C.allFinite())
    throw internal_error("prescribed displacement on " + labels + ": the L2 projection failed");
  return C;
}

}  // namespace

PrescribedValues project_prescribed(const spline::MultiPatch& mp, const spline::GlobalNumbering& num,
                                    const std::vector<PatchTables>& tables,
                                    const std::vector<PrescribedSide>& prescribed) {
  PrescribedValues out;
  out.is_prescribed.assign(num.count, 0);
  out.values = Eigen::MatrixXd::Zero(num.count, 3);
  if (prescribed.empty()) return out;
  const ProjectionSides ps = projection_sides(mp, num, prescribed);
  Triplets trip;
  Eigen::MatrixXd B;
  assemble_boundary_mass(mp, num, tables, ps, trip, B);
  pin_collapsed_functions(mp, ps, trip, B);
  std::string labels;
  for (const auto& pr : prescribed) labels += (labels.empty() ? "'" : ", '") + pr.label + "'";
  const Eigen::MatrixXd C = solve_projection(ps.size, trip, B, labels);
  for (int g = 0; g < num.count; ++g)
    if (ps.compact[g] >= 0) {
      out.is_prescribed[g] = 1;
      out.values.row(g) = C.row(ps.compact[g]);
    }
  return out;
}

}  // namespace igaprep::iga_check::detail
