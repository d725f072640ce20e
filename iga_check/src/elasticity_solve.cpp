#include "igaprep/iga_check/elasticity_solve.h"

#include <Eigen/Eigenvalues>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <sstream>

#ifdef IGAPREP_HAVE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include "elasticity_basis.h"
#include "igaprep/core/error.h"
#include "igaprep/core/progress.h"
#include "igaprep/core/union_find.h"
#include "igaprep/iga_check/elasticity_element.h"
#include "igaprep/iga_check/elasticity_material.h"
#include "igaprep/iga_check/elasticity_refine.h"
#include "igaprep/spline/curve_surface.h"
#include "igaprep/spline/multipatch_topology.h"

namespace igaprep::iga_check {

namespace {

using SpMat = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::string label_list(const spline::MultiPatch& mp) {
  std::string s;
  for (size_t i = 0; i < mp.labels.size(); ++i) s += (i ? ", " : "") + mp.labels[i];
  return s.empty() ? "none" : s;
}

// Index of a label by name; bad_input naming the known labels otherwise.
int find_label(const spline::MultiPatch& mp, const std::string& name, const char* what) {
  for (size_t i = 0; i < mp.labels.size(); ++i)
    if (mp.labels[i] == name) return static_cast<int>(i);
  throw bad_input(std::string(what) + ": unknown label '" + name + "' (labels of the model: " + label_list(mp) + ")");
}

// Boundary sides carrying a label; bad_input when there are none (a label of
// an interface or an unused label cannot carry a boundary condition).
std::vector<spline::BoundarySide> sides_with_label(const spline::MultiPatch& mp, const std::string& name,
                                                   const char* what) {
  const int label = find_label(mp, name, what);
  std::vector<spline::BoundarySide> out;
  for (const auto& b : mp.boundaries)
    if (b.label == label) out.push_back(b);
  if (out.empty()) throw bad_input(std::string(what) + ": label '" + name + "' names no boundary side of the model");
  return out;
}

void check_jacobian(const detail::ElementValues& ev, int patch, double& sign) {
  for (Eigen::Index q = 0; q < ev.det.size(); ++q) {
    const double d = ev.det(q);
    if (sign == 0.0 && d != 0.0 && std::isfinite(d)) sign = d > 0 ? 1.0 : -1.0;
    if (!(d * sign > 0.0)) {
      std::ostringstream s;
      s << "patch " << patch << ": the Jacobian determinant vanishes or changes sign near x = ("
        << ev.x(q, 0) << ", " << ev.x(q, 1) << ", " << ev.x(q, 2)
        << "); the model is not valid for analysis (see igaprep check)";
      throw bad_input(s.str());
    }
  }
}

// Six rigid-body modes against the fixed coefficients, per connected part of
// the model: a combination of modes that vanishes on every fixed coefficient
// of a part is a free motion and makes the stiffness singular.
void check_rigid_modes(const spline::MultiPatch& mp, const spline::GlobalNumbering& num, const Eigen::MatrixXd& X,
                       const std::vector<unsigned char>& fixed) {
  const int np = static_cast<int>(mp.patches.size());
  UnionFind connected(np);  // patches that share a control point
  std::vector<int> owner(num.count, -1);
  for (int p = 0; p < np; ++p)
    for (int g : num.global[p]) {
      if (owner[g] < 0) owner[g] = p;
      else connected.unite(p, owner[g]);
    }
  std::map<int, std::vector<int>> parts;  // root (the part's first patch) -> patches
  for (int p = 0; p < np; ++p) parts[connected.find(p)].push_back(p);
  static const char* names[6] = {"translation in x", "translation in y", "translation in z",
                                 "rotation about x", "rotation about y", "rotation about z"};
  for (const auto& [root, patches] : parts) {
    std::vector<int> cps;
    for (int g = 0; g < num.count; ++g)
      if (connected.find(owner[g]) == root) cps.push_back(g);
    Eigen::Vector3d lo = X.row(cps[0]), hi = lo, c = Eigen::Vector3d::Zero();
    for (int g : cps) {
      lo = lo.cwiseMin(X.row(g).transpose());
      hi = hi.cwiseMax(X.row(g).transpose());
      c += X.row(g).transpose();
    }
    c /= static_cast<double>(cps.size());
    const double L = std::max((hi - lo).norm(), 1e-300);
    Eigen::Matrix<double, 6, 6> G = Eigen::Matrix<double, 6, 6>::Zero();
    for (int g : cps) {
      const Eigen::Vector3d r = (X.row(g).transpose() - c) / L;
      for (int i = 0; i < 3; ++i) {
        if (!fixed[3 * g + i]) continue;
        Eigen::Matrix<double, 6, 1> row = Eigen::Matrix<double, 6, 1>::Zero();
        row(i) = 1.0;
        for (int k = 0; k < 3; ++k) row(3 + k) = Eigen::Vector3d::Unit(k).cross(r)(i);
        G += row * row.transpose();
      }
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> es(G);
    const double tol = 1e-10 * std::max(1.0, es.eigenvalues().maxCoeff());
    int free_modes = 0;
    for (int k = 0; k < 6; ++k)
      if (es.eigenvalues()(k) <= tol) ++free_modes;
    if (free_modes == 0) continue;
    const Eigen::Matrix<double, 6, 1> v = es.eigenvectors().col(0);
    std::string motion;
    for (int k = 0; k < 6; ++k)
      if (std::abs(v(k)) > 0.3) motion += (motion.empty() ? "" : " + ") + std::string(names[k]);
    std::ostringstream s;
    s << "the constraints leave " << free_modes << " rigid-body motion" << (free_modes > 1 ? "s" : "")
      << " free (e.g. " << motion << ") in the part of the model made of patch" << (patches.size() > 1 ? "es" : "");
    for (size_t i = 0; i < patches.size() && i < 10; ++i) s << (i ? ", " : " ") << patches[i];
    if (patches.size() > 10) s << ", ...";
    s << "; the stiffness matrix is singular: fix more components (--fix LABEL[:xyz])";
    throw bad_input(s.str());
  }
}

// Lower-triangular scalar stiffness pattern built from the control-point
// adjacency, and the positions needed to scatter element matrices into it.
struct Pattern {
  int ncp = 0;
  std::vector<int> eq;            // 3*g + i -> equation, or -1 when fixed
  std::vector<int> free_before;   // 3*g + i -> free components of g before i
  std::vector<int> free_count;    // per g
  std::vector<long long> blk_start;  // per column block g: rows r >= g in blk_rows[blk_start[g]..]
  std::vector<int> blk_rows;
  std::vector<long long> blk_cum;    // free scalar rows of earlier off-diagonal blocks of the column
  SpMat K;
};

void build_pattern(const std::vector<std::vector<int>>& element_cps, int ncp, Pattern& P) {
  P.ncp = ncp;
  // control point -> elements
  std::vector<long long> inc_start(ncp + 1, 0);
  for (const auto& e : element_cps)
    for (int g : e) ++inc_start[g + 1];
  for (int g = 0; g < ncp; ++g) inc_start[g + 1] += inc_start[g];
  std::vector<int> inc(inc_start[ncp]);
  {
    std::vector<long long> fill(inc_start.begin(), inc_start.end() - 1);
    for (size_t e = 0; e < element_cps.size(); ++e)
      for (int g : element_cps[e]) inc[fill[g]++] = static_cast<int>(e);
  }
  std::vector<int> marker(ncp, -1);
  P.blk_start.assign(ncp + 1, 0);
  P.blk_rows.clear();
  std::vector<int> rows;
  for (int c = 0; c < ncp; ++c) {
    rows.clear();
    for (long long k = inc_start[c]; k < inc_start[c + 1]; ++k)
      for (int r : element_cps[inc[k]])
        if (r >= c && marker[r] != c) {
          marker[r] = c;
          rows.push_back(r);
        }
    std::sort(rows.begin(), rows.end());
    P.blk_rows.insert(P.blk_rows.end(), rows.begin(), rows.end());
    P.blk_start[c + 1] = static_cast<long long>(P.blk_rows.size());
  }
  // Scalar layout.
  P.free_before.assign(3 * ncp, 0);
  P.free_count.assign(ncp, 0);
  for (int g = 0; g < ncp; ++g)
    for (int i = 0; i < 3; ++i) {
      P.free_before[3 * g + i] = P.free_count[g];
      if (P.eq[3 * g + i] >= 0) ++P.free_count[g];
    }
  P.blk_cum.assign(P.blk_rows.size(), 0);
  const int n = *std::max_element(P.eq.begin(), P.eq.end()) + 1;
  std::vector<int> outer(n + 1, 0);
  for (int c = 0; c < ncp; ++c) {
    long long cum = 0;
    for (long long k = P.blk_start[c] + 1; k < P.blk_start[c + 1]; ++k) {
      P.blk_cum[k] = cum;
      cum += P.free_count[P.blk_rows[k]];
    }
    for (int j = 0; j < 3; ++j) {
      const int col = P.eq[3 * c + j];
      if (col < 0) continue;
      int diag = 0;
      for (int i = j; i < 3; ++i) diag += P.eq[3 * c + i] >= 0;
      outer[col + 1] = static_cast<int>(diag + cum);
    }
  }
  for (int j = 0; j < n; ++j) {
    if (static_cast<long long>(outer[j]) + outer[j + 1] > 2147483647LL)
      throw bad_input("the stiffness matrix has more than 2^31 non-zeros; refine less");
    outer[j + 1] += outer[j];
  }
  P.K = SpMat(n, n);
  P.K.resizeNonZeros(outer[n]);
  std::copy(outer.begin(), outer.end(), P.K.outerIndexPtr());
  int* inner = P.K.innerIndexPtr();
  std::fill(P.K.valuePtr(), P.K.valuePtr() + outer[n], 0.0);
  for (int c = 0; c < ncp; ++c)
    for (int j = 0; j < 3; ++j) {
      const int col = P.eq[3 * c + j];
      if (col < 0) continue;
      int pos = outer[col];
      for (long long k = P.blk_start[c]; k < P.blk_start[c + 1]; ++k) {
        const int r = P.blk_rows[k];
        for (int i = (r == c ? j : 0); i < 3; ++i)
          if (P.eq[3 * r + i] >= 0) inner[pos++] = P.eq[3 * r + i];
      }
    }
}

// Adds an element matrix (component-blocked, see element_stiffness) to K.
void scatter(Pattern& P, const std::vector<int>& gid, const Eigen::MatrixXd& Ke) {
  const int n = static_cast<int>(gid.size());
  double* val = P.K.valuePtr();
  const int* outer = P.K.outerIndexPtr();
  for (int b = 0; b < n; ++b) {
    const int gb = gid[b];
    const int* first = P.blk_rows.data() + P.blk_start[gb];
    const int* last = P.blk_rows.data() + P.blk_start[gb + 1];
    for (int a = 0; a < n; ++a) {
      const int ga = gid[a];
      if (ga < gb) continue;
      const long long k = std::lower_bound(first, last, ga) - P.blk_rows.data();
      for (int j = 0; j < 3; ++j) {
        const int col = P.eq[3 * gb + j];
        if (col < 0) continue;
        const long long base = outer[col];
        if (ga == gb) {
          int off = 0;
          for (int i = j; i < 3; ++i) {
            if (P.eq[3 * ga + i] < 0) continue;
            val[base + off++] += Ke(i * n + a, j * n + b);
          }
        } else {
          int diag = 0;
          for (int i = j; i < 3; ++i) diag += P.eq[3 * gb + i] >= 0;
          const long long row0 = base + diag + P.blk_cum[k];
          for (int i = 0; i < 3; ++i) {
            if (P.eq[3 * ga + i] < 0) continue;
            val[row0 + P.free_before[3 * ga + i]] += Ke(i * n + a, j * n + b);
          }
        }
      }
    }
  }
}

// Calls f(ev, q, normal, dA) at every Gauss point of boundary side b: the
// side's fixed direction is a one-point table at its end, the other two use
// the patch's volume tables. `normal` is the unit outward normal; points
// where the side collapses (zero area) are skipped. end_element() follows the
// points of each element of the side.
template <class F, class E>
void for_side_points(const spline::Patch& pa, int side, const std::array<std::vector<detail::DirElement>, 3>& tables,
                     F&& f, E&& end_element) {
  const int d = spline::side_direction(side);
  const bool at_max = spline::side_is_max(side);
  const auto t = spline::side_tangent_directions(side);
  const std::vector<double>& U = pa.knots[d];
  const int nd = pa.count(d);
  std::vector<detail::DirElement> fixed_dir{
      detail::direction_point(U, pa.degrees[d], at_max ? U[nd] : U[pa.degrees[d]])};
  std::array<const std::vector<detail::DirElement>*, 3> dirs;
  for (int k = 0; k < 3; ++k) dirs[k] = k == d ? &fixed_dir : &tables[k];
  detail::ElementValues ev;
  for (const auto& ew : *dirs[2])
    for (const auto& evv : *dirs[1])
      for (const auto& eu : *dirs[0]) {
        detail::element_values(pa, eu, evv, ew, false, ev);
        for (Eigen::Index q = 0; q < ev.w.size(); ++q) {
          Eigen::Matrix3d J;
          for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k) J(c, k) = ev.J(q, 3 * c + k);
          Eigen::Vector3d nv = J.col(t[0]).cross(J.col(t[1]));
          const double area = nv.norm();
          if (area == 0.0) continue;  // a collapsed point of the face carries no load
          nv /= area;
          // Outward: against the inward parameter direction at a min side.
          const double s = nv.dot(J.col(d));
          if (at_max ? s < 0 : s > 0) nv = -nv;
          f(ev, q, nv, area * ev.w(q));
        }
        end_element();
      }
}

// L2 projection of the prescribed displacements onto the spline space traced
// on the prescribed sides, all sides together: one boundary mass matrix over
// the global numbering, so a coefficient shared by sides or patches gets one
// value. Outputs: prescribed[g] (0/1) and values (ncp x 3, rows of
// non-prescribed points zero).
void project_prescribed(const spline::MultiPatch& mp, const spline::GlobalNumbering& num,
                        const std::vector<std::array<std::vector<detail::DirElement>, 3>>& tables,
                        const std::vector<PrescribedSide>& prescribed, std::vector<unsigned char>& is_prescribed,
                        Eigen::MatrixXd& values) {
  const int ncp = num.count;
  is_prescribed.assign(ncp, 0);
  values = Eigen::MatrixXd::Zero(ncp, 3);
  if (prescribed.empty()) return;
  struct SideJob {
    spline::BoundarySide side;
    const PrescribedSide* what;
  };
  std::vector<SideJob> jobs;
  std::vector<int> compact(ncp, -1);
  std::vector<std::pair<int, int>> first_seen;  // per compact index: (job, local control point)
  int nd = 0;
  for (const auto& pr : prescribed)
    for (const auto& b : sides_with_label(mp, pr.label, "prescribed displacement")) {
      jobs.push_back({b, &pr});
      for (int l : spline::side_control_points(mp.patches[b.patch], b.side)) {
        const int g = num.global[b.patch][l];
        if (compact[g] < 0) {
          compact[g] = nd++;
          first_seen.push_back({static_cast<int>(jobs.size()) - 1, l});
        }
      }
    }
  std::vector<Eigen::Triplet<double>> trip;
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(nd, 3);
  // Per side element: the side's functions (local index, compact index) and
  // their mass matrix, added to the triplets once per element.
  std::vector<int> act_local, act_c;
  Eigen::MatrixXd Me;
  Eigen::VectorXd r;
  bool fresh = true;
  for (const auto& job : jobs) {
    const int p = job.side.patch;
    const spline::Patch& pa = mp.patches[p];
    // Only functions of the side's own control points are non-zero on it.
    std::vector<unsigned char> on_side(pa.control_points.rows(), 0);
    for (int l : spline::side_control_points(pa, job.side.side)) on_side[l] = 1;
    const std::string& label = job.what->label;
    auto point = [&](const detail::ElementValues& ev, Eigen::Index q, const Eigen::Vector3d&, double dA) {
      if (fresh) {
        act_local.clear();
        act_c.clear();
        for (size_t a = 0; a < ev.local.size(); ++a)
          if (on_side[ev.local[a]]) {
            act_local.push_back(static_cast<int>(a));
            act_c.push_back(compact[num.global[p][ev.local[a]]]);
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
  // A function whose trace has no area (every side it lives on collapses to
  // a curve or point) has a zero row: it takes the value at its control
  // point, which is where that collapsed side lies. Its off-diagonal entries
  // are bounded by the zero diagonal and are dropped.
  {
    Eigen::VectorXd diag = Eigen::VectorXd::Zero(nd);
    for (const auto& t : trip)
      if (t.row() == t.col()) diag(t.row()) += t.value();
    const double tiny = 1e-12 * (nd > 0 ? diag.maxCoeff() : 0.0);
    std::vector<unsigned char> collapsed(nd, 0);
    bool any = false;
    for (int c = 0; c < nd; ++c)
      if (!(diag(c) > tiny)) collapsed[c] = 1, any = true;
    if (any) {
      trip.erase(std::remove_if(trip.begin(), trip.end(),
                                [&](const Eigen::Triplet<double>& t) { return collapsed[t.row()] || collapsed[t.col()]; }),
                 trip.end());
      for (int c = 0; c < nd; ++c) {
        if (!collapsed[c]) continue;
        const auto& [job, local] = first_seen[c];
        const Eigen::Vector3d x = mp.patches[jobs[job].side.patch].control_points.row(local).transpose();
        const Eigen::Vector3d u = jobs[job].what->displacement(x);
        if (!u.allFinite()) throw bad_input("prescribed displacement on '" + jobs[job].what->label + "': not finite");
        trip.emplace_back(c, c, 1.0);
        B.row(c) = u.transpose();
      }
    }
  }
  SpMat M(nd, nd);
  M.setFromTriplets(trip.begin(), trip.end());
  Eigen::SimplicialLDLT<SpMat, Eigen::Lower> ldlt(M);
  std::string labels;
  for (const auto& pr : prescribed) labels += (labels.empty() ? "'" : ", '") + pr.label + "'";
  if (ldlt.info() != Eigen::Success || ldlt.vectorD().size() != nd ||
      !(ldlt.vectorD().minCoeff() > 1e-13 * ldlt.vectorD().cwiseAbs().maxCoeff()))
    throw bad_input("prescribed displacement on " + labels +
                    ": the boundary mass matrix is singular (a side of zero area?)");
  const Eigen::MatrixXd C = ldlt.solve(B);
  if (ldlt.info() != Eigen::Success || !C.allFinite())
    throw internal_error("prescribed displacement on " + labels + ": the L2 projection failed");
  for (int g = 0; g < ncp; ++g)
    if (compact[g] >= 0) {
      is_prescribed[g] = 1;
      values.row(g) = C.row(compact[g]);
    }
}

}  // namespace

ElasticitySolution solve_elasticity(const spline::MultiPatch& input, const ElasticityProblem& problem,
                                    const ElasticityOptions& options) {
  spline::validate_multipatch(input);
  if (input.patches.empty()) throw bad_input("the model has no patches");
  if (options.extra_quadrature < 0 || options.extra_quadrature > 10)
    throw bad_input("extra quadrature points must lie in 0..10");
  // Materials and labels first: bad input fails before any work.
  std::vector<LameParameters> lame;
  for (size_t m = 0; m < input.materials.size(); ++m)
    lame.push_back(lame_parameters(input.materials[m].young_modulus, input.materials[m].poisson_ratio,
                                   "material " + std::to_string(m) + " ('" + input.materials[m].name + "')"));
  for (size_t p = 0; p < input.patches.size(); ++p)
    if (input.patches[p].material < 0 || input.patches[p].material >= static_cast<int>(lame.size()))
      throw bad_input("patch " + std::to_string(p) + ": material index " + std::to_string(input.patches[p].material) +
                      " has no entry in the model's materials");
  for (const auto& f : problem.fixed) sides_with_label(input, f.label, "--fix");
  for (const auto& pr : problem.prescribed) {
    sides_with_label(input, pr.label, "prescribed displacement");
    if (!pr.displacement) throw bad_input("prescribed displacement on '" + pr.label + "': no function given");
  }
  for (const auto& t : problem.tractions) sides_with_label(input, t.label, "--traction");
  for (const auto& t : problem.pressures) sides_with_label(input, t.label, "--pressure");
  if (!problem.body_force.allFinite()) throw bad_input("the body force is not finite");
  for (const auto& t : problem.tractions)
    if (!t.traction.allFinite()) throw bad_input("--traction " + t.label + ": not finite");
  for (const auto& t : problem.pressures)
    if (!std::isfinite(t.pressure)) throw bad_input("--pressure " + t.label + ": not finite");

  ElasticitySolution sol;
  ElasticityReport& rep = sol.report;
  const auto t_assembly = Clock::now();
  sol.model = refine_for_analysis(input, options.elevate, options.refine);
  spline::MultiPatch& mp = sol.model;
  const int np = static_cast<int>(mp.patches.size());
  const spline::GlobalNumbering num = spline::global_numbering(mp);
  const int ncp = num.count;
  Eigen::MatrixXd X(ncp, 3);
  for (int p = 0; p < np; ++p)
    for (size_t l = 0; l < num.global[p].size(); ++l) X.row(num.global[p][l]) = mp.patches[p].control_points.row(l);

  // 1-D element tables per patch and direction (volume and side quadrature).
  std::vector<std::array<std::vector<detail::DirElement>, 3>> tables(np);
  for (int p = 0; p < np; ++p) tables[p] = detail::patch_elements(mp.patches[p], options.extra_quadrature);

  // Constraints: the side's control points carry its trace (open knot vectors).
  // Prescribed values first; a FixedSide component then sets its value to zero.
  std::vector<unsigned char> fixed(3 * static_cast<size_t>(ncp), 0);
  Eigen::VectorXd ud = Eigen::VectorXd::Zero(3 * static_cast<Eigen::Index>(ncp));  // constrained values
  {
    const auto t_proj = Clock::now();
    std::vector<unsigned char> is_prescribed;
    Eigen::MatrixXd values;
    project_prescribed(mp, num, tables, problem.prescribed, is_prescribed, values);
    for (int g = 0; g < ncp; ++g)
      if (is_prescribed[g])
        for (int i = 0; i < 3; ++i) {
          fixed[3 * g + i] = 1;
          ud(3 * g + i) = values(g, i);
        }
    rep.projection_seconds = seconds_since(t_proj);
  }
  std::vector<unsigned char> zero_fixed(3 * static_cast<size_t>(ncp), 0);
  for (const auto& f : problem.fixed) {
    if (!f.components[0] && !f.components[1] && !f.components[2])
      throw bad_input("--fix " + f.label + ": no component chosen");
    for (const auto& b : sides_with_label(mp, f.label, "--fix"))
      for (int l : spline::side_control_points(mp.patches[b.patch], b.side))
        for (int i = 0; i < 3; ++i)
          if (f.components[i]) {
            fixed[3 * num.global[b.patch][l] + i] = 1;
            zero_fixed[3 * num.global[b.patch][l] + i] = 1;
            ud(3 * num.global[b.patch][l] + i) = 0.0;
          }
  }
  check_rigid_modes(mp, num, X, fixed);

  Pattern P;
  P.eq.assign(3 * static_cast<size_t>(ncp), -1);
  int neq = 0;
  for (size_t k = 0; k < fixed.size(); ++k)
    if (!fixed[k]) P.eq[k] = neq++;
  rep.unknowns = neq;
  rep.fixed_dofs = static_cast<long long>(fixed.size()) - neq;
  for (size_t k = 0; k < fixed.size(); ++k) rep.prescribed_dofs += fixed[k] && !zero_fixed[k];
  const bool has_prescribed = rep.prescribed_dofs > 0;

  // Elements and their global control points.
  std::vector<std::vector<int>> element_cps;
  for (int p = 0; p < np; ++p) {
    const spline::Patch& pa = mp.patches[p];
    for (const auto& ew : tables[p][2])
      for (const auto& ev : tables[p][1])
        for (const auto& eu : tables[p][0]) {
          std::vector<int> ids;
          ids.reserve((pa.degrees[0] + 1) * (pa.degrees[1] + 1) * (pa.degrees[2] + 1));
          for (int iw = 0; iw <= pa.degrees[2]; ++iw)
            for (int iv = 0; iv <= pa.degrees[1]; ++iv)
              for (int iu = 0; iu <= pa.degrees[0]; ++iu)
                ids.push_back(num.global[p][pa.index(eu.first + iu, ev.first + iv, ew.first + iw)]);
          element_cps.push_back(std::move(ids));
        }
  }
  rep.elements = static_cast<long long>(element_cps.size());
  build_pattern(element_cps, ncp, P);
  rep.nonzeros = P.K.nonZeros();

  Eigen::VectorXd F = Eigen::VectorXd::Zero(neq);
  // Prescribed values enter the right-hand side as -K_fd u_d; Kfd_ud and
  // ud_Kdd_ud complete the strain energy of the whole field.
  Eigen::VectorXd Kfd_ud = Eigen::VectorXd::Zero(neq);
  double ud_Kdd_ud = 0.0;
  const bool has_body = problem.body_force.squaredNorm() > 0.0 || static_cast<bool>(problem.body_force_function);
  {
    Progress progress("assembling stiffness", element_cps.size());
    detail::ElementValues ev;
    Eigen::MatrixXd Ke, work;
    Eigen::VectorXd ue, Ku_e;
    size_t e = 0;
    for (int p = 0; p < np; ++p) {
      const spline::Patch& pa = mp.patches[p];
      const LameParameters& lm = lame[pa.material];
      double sign = 0.0;
      for (const auto& ew : tables[p][2])
        for (const auto& evv : tables[p][1])
          for (const auto& eu : tables[p][0]) {
            detail::element_values(pa, eu, evv, ew, true, ev);
            check_jacobian(ev, p, sign);
            const Eigen::VectorXd wdet = ev.w.cwiseProduct(ev.det.cwiseAbs());
            rep.quadrature_points += wdet.size();
            element_stiffness(ev.grad, wdet, lm, Ke, work);
            const std::vector<int>& gid = element_cps[e];
            scatter(P, gid, Ke);
            if (has_prescribed) {
              const int n = static_cast<int>(gid.size());
              ue.setZero(3 * n);
              bool any = false;
              for (int a = 0; a < n; ++a)
                for (int i = 0; i < 3; ++i) {
                  const double v = ud(3 * gid[a] + i);
                  if (v != 0.0) {
                    ue(i * n + a) = v;
                    any = true;
                  }
                }
              if (any) {
                Ku_e.noalias() = Ke * ue;
                ud_Kdd_ud += ue.dot(Ku_e);
                for (int a = 0; a < n; ++a)
                  for (int i = 0; i < 3; ++i) {
                    const int r = P.eq[3 * gid[a] + i];
                    if (r >= 0) Kfd_ud(r) += Ku_e(i * n + a);
                  }
              }
            }
            if (has_body) {
              const int n = static_cast<int>(gid.size());
              for (Eigen::Index q = 0; q < wdet.size(); ++q) {
                Eigen::Vector3d b = problem.body_force;
                if (problem.body_force_function) b += problem.body_force_function(ev.x.row(q).transpose());
                for (int a = 0; a < n; ++a)
                  for (int i = 0; i < 3; ++i) {
                    const int r = P.eq[3 * gid[a] + i];
                    if (r >= 0) F(r) += ev.R(q, a) * b(i) * wdet(q);
                  }
              }
            }
            progress.update(++e);
          }
    }
    progress.finish();
  }

  // Surface loads: Gauss points of the side's elements.
  auto add_surface_load = [&](const spline::BoundarySide& b, const Eigen::Vector3d& traction, double pressure) {
    for_side_points(mp.patches[b.patch], b.side, tables[b.patch],
                    [&](const detail::ElementValues& ev, Eigen::Index q, const Eigen::Vector3d& nv, double dA) {
                      const Eigen::Vector3d tr = traction - pressure * nv;
                      const int n = static_cast<int>(ev.local.size());
                      for (int a = 0; a < n; ++a) {
                        const int g = num.global[b.patch][ev.local[a]];
                        for (int i = 0; i < 3; ++i) {
                          const int r = P.eq[3 * g + i];
                          if (r >= 0) F(r) += ev.R(q, a) * tr(i) * dA;
                        }
                      }
                    },
                    [] {});
  };
  for (const auto& tl : problem.tractions)
    for (const auto& b : sides_with_label(mp, tl.label, "--traction")) add_surface_load(b, tl.traction, 0.0);
  for (const auto& pl : problem.pressures)
    for (const auto& b : sides_with_label(mp, pl.label, "--pressure"))
      add_surface_load(b, Eigen::Vector3d::Zero(), pl.pressure);
  F -= Kfd_ud;
  rep.assembly_seconds = seconds_since(t_assembly);

  // Solve.
  const auto t_solve = Clock::now();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(neq);
  const char* singular =
      "the stiffness matrix is not positive definite: the constraints leave a mechanism free "
      "(e.g. patches that are not connected through interfaces and not fixed) ";
  if (neq > 0 && options.solver == LinearSolver::Cholesky) {
#ifdef IGAPREP_HAVE_CHOLMOD
    Eigen::CholmodDecomposition<SpMat, Eigen::Lower> chol;
    rep.solver = "cholmod";
#else
    Eigen::SimplicialLDLT<SpMat, Eigen::Lower> chol;
    rep.solver = "simplicial-ldlt";
#endif
    chol.compute(P.K);
    if (chol.info() != Eigen::Success) throw bad_input(std::string(singular) + "(Cholesky factorization failed)");
#ifndef IGAPREP_HAVE_CHOLMOD
    if (chol.vectorD().minCoeff() <= 1e-14 * chol.vectorD().cwiseAbs().maxCoeff())
      throw bad_input(std::string(singular) + "(zero or negative pivot)");
#endif
    u = chol.solve(F);
    if (chol.info() != Eigen::Success || !u.allFinite())
      throw bad_input(std::string(singular) + "(the solve failed)");
  } else if (neq > 0) {
    Eigen::ConjugateGradient<SpMat, Eigen::Lower, Eigen::IncompleteCholesky<double, Eigen::Lower>> cg;
    rep.solver = "cg-ichol";
    cg.setTolerance(options.cg_tolerance);
    cg.setMaxIterations(options.cg_max_iterations > 0 ? options.cg_max_iterations : 10 * neq);
    cg.compute(P.K);
    if (cg.info() != Eigen::Success) throw bad_input(std::string(singular) + "(incomplete Cholesky failed)");
    u = cg.solve(F);
    rep.cg_iterations = static_cast<int>(cg.iterations());
    rep.cg_residual = cg.error();
    if (cg.info() != Eigen::Success || !u.allFinite()) {
      std::ostringstream s;
      s << "conjugate gradients did not converge in " << cg.iterations() << " iterations (residual " << cg.error()
        << "); try --solver cholesky";
      throw internal_error(s.str());
    }
  }
  rep.solve_seconds = seconds_since(t_solve);
  const Eigen::VectorXd Ku = P.K.selfadjointView<Eigen::Lower>() * u;
  rep.strain_energy = 0.5 * u.dot(Ku) + u.dot(Kfd_ud) + 0.5 * ud_Kdd_ud;

  // Coefficients per patch; constrained components take their values (zero or prescribed).
  for (int p = 0; p < np; ++p) {
    spline::Patch& pa = mp.patches[p];
    pa.displacement = Eigen::MatrixXd::Zero(pa.control_points.rows(), 3);
    for (Eigen::Index l = 0; l < pa.displacement.rows(); ++l)
      for (int i = 0; i < 3; ++i) {
        const int g = num.global[p][l];
        const int r = P.eq[3 * g + i];
        pa.displacement(l, i) = r >= 0 ? u(r) : ud(3 * g + i);
      }
    if (pa.displacement.rows() > 0)
      rep.max_displacement = std::max(rep.max_displacement, pa.displacement.rowwise().norm().maxCoeff());
  }
  mp.has_solution = true;
  mp.strain_energy = rep.strain_energy;
  mp.max_displacement = rep.max_displacement;
  return sol;
}

}  // namespace igaprep::iga_check
