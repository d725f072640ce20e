#include <Eigen/Dense>
#include <unsupported/Eigen/KroneckerProduct>
#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <unordered_map>
#include <utility>

#include "igaprep/core/error.h"
#include "igaprep/spline/basis.h"
#include "igaprep/spline/bezier_extraction.h"
#include "igaprep/spline/evaluate.h"
#include "igaprep/spline/knot_vector.h"
#include "igaprep/spline/refine.h"
#include "igaprep/spline/tspline_functions.h"
#include "tspline_cells.h"
#include "tspline_common.h"

namespace igaprep::spline::detail {

namespace {

// The copies of the knots of `wanted` (a multiset) that `U` lacks.
std::vector<double> lacking_knots(const std::vector<double>& U, const std::vector<double>& wanted) {
  std::vector<double> out;
  for (const double x : unique_knots(wanted))
    for (long c = std::count(wanted.begin(), wanted.end(), x) - knot_multiplicity(U, x); c > 0; --c) out.push_back(x);
  return out;
}

// The Bernstein coefficients on [a, b] (inside one span) of the B-spline of
// degree knots.size() - 2 on its own knots: the function as one of a clamped
// spline, a and b inserted to multiplicity p (exact, so zeros stay zeros).
Eigen::VectorXd bspline_bernstein(const std::vector<double>& knots, double a, double b) {
  const int p = static_cast<int>(knots.size()) - 2;
  std::vector<double> U(static_cast<std::size_t>(p), knots.front());
  U.insert(U.end(), knots.begin(), knots.end());
  U.insert(U.end(), static_cast<std::size_t>(p), knots.back());
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(2 * p + 1, 1);
  c(p, 0) = 1.0;
  std::vector<double> K;
  Eigen::MatrixXd refined;
  std::vector<double> ends(static_cast<std::size_t>(p), a);  // a and b to multiplicity p
  ends.insert(ends.end(), static_cast<std::size_t>(p), b);
  insert_knots_1d(U, p, c, lacking_knots(U, ends), &K, &refined);
  // The last p copies of a are K[r + 1 .. r + p].
  const Eigen::Index r = (std::upper_bound(K.begin(), K.end(), a) - K.begin()) - 1 - p;
  return refined.col(0).segment(r, p + 1);
}

// Everything the elements of one patch need, per direction.
struct PatchContext {
  const Patch& patch;
  const TMesh& mesh;
  std::array<std::vector<double>, 3> breaks;
  PatchContext(const Patch& p, const TMesh& m) : patch(p), mesh(m) {
    for (std::size_t d = 0; d < 3; ++d) breaks[d] = unique_knots(p.knots[d]);
  }
  double parameter(int d, TCoord x) const { return detail::index_to_parameter(breaks[static_cast<std::size_t>(d)], x); }
};

struct SubBox {
  std::array<TCoord, 3> lo, hi;
  int element = 0;  // of the patch, u fastest
};

// A function's support within the patch (TFunction::support).
using Support = std::array<TCoord, 6>;

bool meets(const Support& s, const std::array<TCoord, 3>& lo, const std::array<TCoord, 3>& hi) {
  return s[0] < hi[0] && lo[0] < s[1] && s[2] < hi[1] && lo[1] < s[3] && s[4] < hi[2] && lo[2] < s[5];
}

// Per patch element the functions whose support meets it.
std::vector<std::vector<int>> functions_by_element(const TMesh& mesh, const std::vector<TFunction>& functions) {
  std::vector<std::vector<int>> out(static_cast<std::size_t>(mesh.elements()[0] * mesh.elements()[1] * mesh.elements()[2]));
  for (std::size_t f = 0; f < functions.size(); ++f) {
    std::array<int, 3> first{}, last{};
    for (int d = 0; d < 3; ++d) {
      first[static_cast<std::size_t>(d)] = static_cast<int>(functions[f].support_lo(d) / kTScale);
      last[static_cast<std::size_t>(d)] = static_cast<int>((functions[f].support_hi(d, mesh) - 1) / kTScale);
    }
    for (int k = first[2]; k <= last[2]; ++k)
      for (int j = first[1]; j <= last[1]; ++j)
        for (int i = first[0]; i <= last[0]; ++i)
          out[static_cast<std::size_t>(i + mesh.elements()[0] * (j + mesh.elements()[1] * k))].push_back(static_cast<int>(f));
  }
  return out;
}

// A box split where the knots of the functions on it run through it, into
// `out` (cleared); `cuts` is scratch space, kept from box to box.
void bezier_cells(const TBox& q, const std::vector<TFunction>& functions, const std::vector<int>& on_box,
                  std::array<std::vector<TCoord>, 3>& cuts, std::vector<SubBox>& out) {
  for (std::size_t d = 0; d < 3; ++d) {
    cuts[d].assign({q.lo[d], q.hi[d]});
    for (const int f : on_box)
      for (const TCoord k : functions[static_cast<std::size_t>(f)].knots[d])
        if (q.lo[d] < k && k < q.hi[d]) cuts[d].push_back(k);
    std::sort(cuts[d].begin(), cuts[d].end());
    cuts[d].erase(std::unique(cuts[d].begin(), cuts[d].end()), cuts[d].end());
  }
  out.clear();
  for (std::size_t k = 0; k + 1 < cuts[2].size(); ++k)
    for (std::size_t j = 0; j + 1 < cuts[1].size(); ++j)
      for (std::size_t i = 0; i + 1 < cuts[0].size(); ++i)
        out.push_back({{{cuts[0][i], cuts[1][j], cuts[2][k]}}, {{cuts[0][i + 1], cuts[1][j + 1], cuts[2][k + 1]}}, q.element});
}

// The 1-D Bernstein vectors of the patch's functions on its cells, each
// distinct one once. A vector depends on the direction, the function's knots
// in it and the cell's interval: knot vectors and intervals get ids once, so
// the per-cell look-up is an index into a table.
class Bernstein1dTable {
 public:
  Bernstein1dTable(const PatchContext& ctx, const std::vector<TFunction>& functions)
      : ctx_(ctx), knots_{{knot_vector_ids(functions, 0), knot_vector_ids(functions, 1), knot_vector_ids(functions, 2)}} {
    for (std::size_t d = 0; d < 3; ++d) table_[d].resize(knots_[d].vectors.size());
  }
  // The id of the interval [lo, hi] of direction d.
  int interval(int d, TCoord lo, TCoord hi) {
    const std::size_t dd = static_cast<std::size_t>(d);
    const auto [it, added] = interval_ids_[dd].emplace(std::make_pair(lo, hi), static_cast<int>(intervals_[dd].size()));
    if (added) intervals_[dd].push_back({lo, hi});
    return it->second;
  }
  int id(int function, int d, int interval) {
    const std::size_t dd = static_cast<std::size_t>(d);
    const int vector = knots_[dd].of_function[static_cast<std::size_t>(function)];
    std::vector<int>& row = table_[dd][static_cast<std::size_t>(vector)];
    if (row.size() <= static_cast<std::size_t>(interval)) row.resize(intervals_[dd].size(), -1);
    int& slot = row[static_cast<std::size_t>(interval)];
    if (slot < 0) {
      const auto [lo, hi] = intervals_[dd][static_cast<std::size_t>(interval)];
      std::vector<double> knots;
      for (const TCoord x : knots_[dd].vectors[static_cast<std::size_t>(vector)]) knots.push_back(ctx_.parameter(d, x));
      slot = static_cast<int>(vectors_.size());
      vectors_.push_back(bspline_bernstein(knots, ctx_.parameter(d, lo), ctx_.parameter(d, hi)));
    }
    return slot;
  }
  const std::vector<Eigen::VectorXd>& vectors() const { return vectors_; }

 private:
  const PatchContext& ctx_;
  std::array<KnotVectorIds, 3> knots_;  // per direction
  std::array<std::map<std::pair<TCoord, TCoord>, int>, 3> interval_ids_;
  std::array<std::vector<std::pair<TCoord, TCoord>>, 3> intervals_;
  std::array<std::vector<std::vector<int>>, 3> table_;  // [knot vector][interval] -> vector id, -1 until made
  std::vector<Eigen::VectorXd> vectors_;
};

// The coefficients, over the patch's own B-splines in direction d, of the
// B-spline on the local knots `xi` (parameters): the row of the knot
// insertion that makes xi consecutive knots of the patch's knot vector
// (every knot of the patch inside xi's range is one of xi's: the mesh holds
// every element boundary). Knot insertion: convex weights, exact to
// round-off. Returns (first index, coefficients).
std::pair<int, std::vector<double>> insertion_row(const std::vector<double>& U, int p, const std::vector<double>& xi) {
  const int n = static_cast<int>(U.size()) - p - 1;
  std::vector<double> K;
  Eigen::MatrixXd rows;  // the refined basis over the patch's: knot insertion of the identity
  insert_knots_1d(U, p, Eigen::MatrixXd::Identity(n, n), lacking_knots(U, xi), &K, &rows);
  const auto at = std::search(K.begin(), K.end(), xi.begin(), xi.end());
  if (at == K.end()) throw internal_error("T-spline: a function's knots are not consecutive in its patch's refined knots");
  const Eigen::Index row = at - K.begin();
  int first = -1;
  std::vector<double> alpha;
  for (int j = 0; j < n; ++j) {
    if (rows(row, j) == 0.0) continue;
    if (first < 0) first = j;
    alpha.resize(static_cast<std::size_t>(j - first) + 1, 0.0);
    alpha.back() = rows(row, j);
  }
  return {first, alpha};
}

// Each function's control point (homogeneous) from the patch's: the tensor
// product of the three insertion rows applied to the patch's control net.
// The geometry is unchanged: the T-spline space holds the patch's.
void set_control_points(const PatchContext& ctx, PatchCells& cells) {
  const Patch& P = ctx.patch;
  std::array<std::map<std::vector<TCoord>, std::pair<int, std::vector<double>>>, 3> rows;
  cells.homogeneous.setZero(static_cast<Eigen::Index>(cells.functions.size()), 4);
  for (std::size_t f = 0; f < cells.functions.size(); ++f) {
    std::array<const std::pair<int, std::vector<double>>*, 3> r{};
    for (std::size_t d = 0; d < 3; ++d) {
      const std::vector<TCoord>& k = cells.functions[f].knots[d];
      auto it = rows[d].find(k);
      if (it == rows[d].end()) {
        std::vector<double> xi;
        for (const TCoord x : k) xi.push_back(ctx.parameter(static_cast<int>(d), x));
        it = rows[d].emplace(k, insertion_row(P.knots[d], P.degrees[d], xi)).first;
      }
      r[d] = &it->second;
    }
    for (std::size_t c = 0; c < r[2]->second.size(); ++c)
      for (std::size_t b = 0; b < r[1]->second.size(); ++b)
        for (std::size_t a = 0; a < r[0]->second.size(); ++a) {
          const int l = P.index(r[0]->first + static_cast<int>(a), r[1]->first + static_cast<int>(b), r[2]->first + static_cast<int>(c));
          const double alpha = r[0]->second[a] * r[1]->second[b] * r[2]->second[c];
          const double w = P.rational() ? P.weights[l] : 1.0;
          cells.homogeneous.row(static_cast<Eigen::Index>(f)).head<3>() += alpha * w * P.control_points.row(l);
          cells.homogeneous(static_cast<Eigen::Index>(f), 3) += alpha * w;
        }
  }
}

// The cells (Bezier elements) of a refined patch with their functions and
// C_e, and the functions' control points (set_control_points).
PatchCells refined_patch_cells(const Patch& patch, const TMesh& mesh, int patch_index) {
  PatchCells out;
  out.functions = tspline_functions(mesh);
  if (const auto bad = dual_compatibility_violation(mesh, out.functions))
    throw internal_error("T-spline: the mesh of patch " + std::to_string(patch_index) + " is not dual compatible (functions " +
                         std::to_string(bad->first) + " and " + std::to_string(bad->second) + ")");
  const PatchContext ctx(patch, mesh);
  const std::vector<std::vector<int>> by_element = functions_by_element(mesh, out.functions);
  Bernstein1dTable table(ctx, out.functions);
  std::unordered_map<std::vector<int>, int, IntsHash> operator_ids;
  out.elements.reserve(mesh.boxes().size());
  std::vector<Support> support;
  support.reserve(out.functions.size());
  for (const TFunction& f : out.functions) support.push_back(f.support(mesh));
  std::vector<int> on_box, key;  // reused from box to box
  std::array<std::vector<TCoord>, 3> cuts;
  std::vector<SubBox> box_cells;
  for (std::size_t box = 0; box < mesh.boxes().size(); ++box) {
    const TBox& q = mesh.boxes()[box];
    on_box.clear();
    for (const int f : by_element[static_cast<std::size_t>(q.element)])
      if (meets(support[static_cast<std::size_t>(f)], q.lo, q.hi)) on_box.push_back(f);
    bezier_cells(q, out.functions, on_box, cuts, box_cells);
    for (const SubBox& cell : box_cells) {
      ExtractionElement e;
      e.degrees = patch.degrees;
      e.material = patch.material;
      e.patch = patch_index;
      e.box = static_cast<int>(box);
      for (int d = 0; d < 3; ++d) {
        e.index[static_cast<std::size_t>(d)] = static_cast<int>(cell.lo[static_cast<std::size_t>(d)] / kTScale);
        e.domain[static_cast<std::size_t>(d)] = {{ctx.parameter(d, cell.lo[static_cast<std::size_t>(d)]), ctx.parameter(d, cell.hi[static_cast<std::size_t>(d)])}};
      }
      std::array<int, 3> interval{};
      for (int d = 0; d < 3; ++d)
        interval[static_cast<std::size_t>(d)] = table.interval(d, cell.lo[static_cast<std::size_t>(d)], cell.hi[static_cast<std::size_t>(d)]);
      key.clear();
      e.functions.reserve(on_box.size());
      for (const int f : on_box) {
        if (!meets(support[static_cast<std::size_t>(f)], cell.lo, cell.hi)) continue;
        for (int d = 0; d < 3; ++d) key.push_back(table.id(f, d, interval[static_cast<std::size_t>(d)]));
        e.functions.push_back(f);
      }
      auto it = operator_ids.find(key);
      if (it == operator_ids.end()) {
        it = operator_ids.emplace(key, static_cast<int>(out.operator_keys.size())).first;
        out.operator_keys.push_back(key);
      }
      e.extraction = it->second;
      out.elements.push_back(std::move(e));
    }
  }
  out.vectors_1d = table.vectors();
  set_control_points(ctx, out);
  return out;
}

// An unrefined patch: its own elements, B-splines (the functions in the
// same order: tspline_functions) and control points; the rows of its 1-D
// extraction operators are the 1-D vectors.
PatchCells tensor_patch_cells(const Patch& patch, const TMesh& mesh, int patch_index) {
  PatchCells out;
  out.functions = tspline_functions(mesh);
  if (static_cast<Eigen::Index>(out.functions.size()) != patch.control_points.rows())
    throw internal_error("T-spline: the tensor mesh of patch " + std::to_string(patch_index) + " has another function count");
  const PatchExtraction ex = bezier_extraction(patch);
  std::array<std::vector<int>, 3> first_row;  // per direction and element: the id of its first row
  for (std::size_t d = 0; d < 3; ++d)
    for (const Eigen::MatrixXd& C : ex.dirs[d].C) {
      first_row[d].push_back(static_cast<int>(out.vectors_1d.size()));
      for (Eigen::Index r = 0; r < C.rows(); ++r) out.vectors_1d.push_back(C.row(r).transpose());
    }
  std::map<std::array<int, 3>, int> operator_ids;
  for (int ew = 0; ew < ex.element_count(2); ++ew)
    for (int ev = 0; ev < ex.element_count(1); ++ev)
      for (int eu = 0; eu < ex.element_count(0); ++eu) {
        ExtractionElement e;
        e.degrees = patch.degrees;
        e.material = patch.material;
        e.patch = patch_index;
        e.index = {{eu, ev, ew}};
        e.box = eu + ex.element_count(0) * (ev + ex.element_count(1) * ew);
        const int at[3] = {eu, ev, ew};
        for (std::size_t d = 0; d < 3; ++d)
          e.domain[d] = {{ex.dirs[d].breaks[static_cast<std::size_t>(at[d])], ex.dirs[d].breaks[static_cast<std::size_t>(at[d]) + 1]}};
        e.functions = element_control_points(patch, ex, eu, ev, ew);
        const std::array<int, 3> key{{first_row[0][static_cast<std::size_t>(eu)], first_row[1][static_cast<std::size_t>(ev)],
                                      first_row[2][static_cast<std::size_t>(ew)]}};
        const auto [it, added] = operator_ids.emplace(key, static_cast<int>(out.operator_keys.size()));
        if (added) {
          std::vector<int> rows;
          for (int k = 0; k <= patch.degrees[2]; ++k)
            for (int j = 0; j <= patch.degrees[1]; ++j)
              for (int i = 0; i <= patch.degrees[0]; ++i) rows.insert(rows.end(), {key[0] + i, key[1] + j, key[2] + k});
          out.operator_keys.push_back(std::move(rows));
        }
        e.extraction = it->second;
        out.elements.push_back(std::move(e));
      }
  out.homogeneous.resize(patch.control_points.rows(), 4);
  for (Eigen::Index l = 0; l < patch.control_points.rows(); ++l) {
    const double w = patch.rational() ? patch.weights[l] : 1.0;
    out.homogeneous.row(l) << w * patch.control_points.row(l), w;
  }
  return out;
}

}  // namespace

PatchCells patch_cells(const Patch& patch, const TMesh& mesh, int patch_index) {
  return mesh.refined() ? refined_patch_cells(patch, mesh, patch_index) : tensor_patch_cells(patch, mesh, patch_index);
}

// Nestedness, checked at every cell's centre: the patch's old geometry
// comes back (the tests check it at random points).
void check_reproduces_geometry(const Patch& patch, const PatchCells& cells, int patch_index, double tolerance) {
  for (const ExtractionElement& e : cells.elements) {
    std::array<Eigen::VectorXd, 3> B;
    for (std::size_t d = 0; d < 3; ++d) {
      B[d].resize(e.degrees[d] + 1);
      bernstein_basis(e.degrees[d], 0.5, B[d].data());
    }
    const std::vector<int>& key = cells.operator_keys[static_cast<std::size_t>(e.extraction)];
    Eigen::RowVector4d h = Eigen::RowVector4d::Zero();
    for (std::size_t r = 0; r < e.functions.size(); ++r) {
      double N = 1.0;
      for (std::size_t d = 0; d < 3; ++d) N *= B[d].dot(cells.vectors_1d[static_cast<std::size_t>(key[3 * r + d])]);
      h += N * cells.homogeneous.row(e.functions[r]);
    }
    Eigen::Vector3d u;
    for (int d = 0; d < 3; ++d) u[d] = 0.5 * (e.domain[static_cast<std::size_t>(d)][0] + e.domain[static_cast<std::size_t>(d)][1]);
    const double off = (h.head<3>().transpose() / h[3] - evaluate_point(patch, u)).cwiseAbs().maxCoeff();
    if (!(off <= tolerance)) {
      char text[160];
      std::snprintf(text, sizeof text, "T-spline: patch %d does not reproduce its geometry (off by %.3g, tolerance %.3g)", patch_index, off,
                    tolerance);
      throw internal_error(text);
    }
  }
}

}  // namespace igaprep::spline::detail
