#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>

#include "igaprep/core/error.h"
#include "igaprep/core/parallel.h"
#include "igaprep/core/union_find.h"
#include "igaprep/spline/tspline_functions.h"
#include "igaprep/spline/tspline_model.h"
#include "tspline_cells.h"
#include "tspline_common.h"

namespace igaprep::spline {

namespace {

using detail::check_reproduces_geometry;
using detail::IntsHash;
using detail::patch_cells;
using detail::PatchCells;

using Anchor = std::array<TCoord, 3>;

Anchor anchor_of(const TFunction& f) { return {{f.anchor(0), f.anchor(1), f.anchor(2)}}; }

// Joins the functions that do not vanish on an interface (p + 1 repeated
// end knots across it) with their twins on the other side: the same anchor
// through the interface's direction map, the same knots along the face.
void join_interface(const TSplineModel& m, const Interface& itf, const std::vector<PatchCells>& cells,
                    const std::vector<int>& offset, UnionFind& classes) {
  const TMesh& A = m.meshes[static_cast<std::size_t>(itf.patch_a)];
  const TMesh& B = m.meshes[static_cast<std::size_t>(itf.patch_b)];
  const int na = itf.side_a.direction(), nb = itf.side_b.direction();
  const TCoord r_a = (A.degrees()[static_cast<std::size_t>(na)] - 1) / 2 * kTScale;
  const TCoord r_b = (B.degrees()[static_cast<std::size_t>(nb)] - 1) / 2 * kTScale;
  const TCoord on_a = itf.side_a.parameter() ? A.extent(na) + r_a : -r_a;
  const TCoord on_b = itf.side_b.parameter() ? B.extent(nb) + r_b : -r_b;
  std::map<Anchor, int> b_at;
  const std::vector<TFunction>& fb = cells[static_cast<std::size_t>(itf.patch_b)].functions;
  for (std::size_t f = 0; f < fb.size(); ++f)
    if (fb[f].anchor(nb) == on_b) b_at.emplace(anchor_of(fb[f]), static_cast<int>(f));
  const std::vector<TFunction>& fa = cells[static_cast<std::size_t>(itf.patch_a)].functions;
  for (std::size_t f = 0; f < fa.size(); ++f) {
    if (fa[f].anchor(na) != on_a) continue;
    Anchor at{};
    at[static_cast<std::size_t>(nb)] = on_b;
    for (const int d : itf.side_a.tangent_directions()) {
      const int db = itf.dirmap[static_cast<std::size_t>(d)];
      at[static_cast<std::size_t>(db)] = itf.orient[static_cast<std::size_t>(d)] ? fa[f].anchor(d) : B.extent(db) - fa[f].anchor(d);
    }
    const auto twin = b_at.find(at);
    if (twin == b_at.end())
      throw internal_error("T-spline: interface of patches " + std::to_string(itf.patch_a) + " and " + std::to_string(itf.patch_b) +
                           ": a function on the face has no twin");
    for (const int d : itf.side_a.tangent_directions()) {
      const int db = itf.dirmap[static_cast<std::size_t>(d)];
      std::vector<TCoord> mapped;
      for (const TCoord x : fa[f].knots[static_cast<std::size_t>(d)]) mapped.push_back(itf.orient[static_cast<std::size_t>(d)] ? x : B.extent(db) - x);
      std::sort(mapped.begin(), mapped.end());
      if (mapped != fb[static_cast<std::size_t>(twin->second)].knots[static_cast<std::size_t>(db)])
        throw internal_error("T-spline: interface of patches " + std::to_string(itf.patch_a) + " and " + std::to_string(itf.patch_b) +
                             ": twin functions with different knots along the face");
    }
    classes.unite(offset[static_cast<std::size_t>(itf.patch_a)] + static_cast<int>(f), offset[static_cast<std::size_t>(itf.patch_b)] + twin->second);
  }
}

double model_scale(const MultiPatch& mp) {
  double s = 1.0;
  for (const Patch& p : mp.patches) s = std::max(s, p.control_points.cwiseAbs().maxCoeff() * (p.rational() ? p.weights.maxCoeff() : 1.0));
  return s;
}

// C_e from its functions' 1-D vectors: row r = w (x) v (x) u (u fastest).
Eigen::MatrixXd operator_matrix(const PatchCells& cells, const std::vector<int>& key) {
  const Eigen::Index n = static_cast<Eigen::Index>(key.size() / 3);
  auto v = [&](Eigen::Index r, int d) -> const Eigen::VectorXd& { return cells.vectors_1d[static_cast<std::size_t>(key[static_cast<std::size_t>(3 * r + d)])]; };
  const Eigen::Index nu = v(0, 0).size(), nv = v(0, 1).size(), nw = v(0, 2).size();
  // Column by column (the matrix is column-major), the products in the order of w (x) (v (x) u).
  std::vector<const double*> a(static_cast<std::size_t>(n)), b(a), c(a);
  for (Eigen::Index r = 0; r < n; ++r) {
    a[static_cast<std::size_t>(r)] = v(r, 0).data(), b[static_cast<std::size_t>(r)] = v(r, 1).data();
    c[static_cast<std::size_t>(r)] = v(r, 2).data();
  }
  Eigen::MatrixXd C(n, nu * nv * nw);
  double* out = C.data();
  for (Eigen::Index k = 0; k < nw; ++k)
    for (Eigen::Index j = 0; j < nv; ++j)
      for (Eigen::Index i = 0; i < nu; ++i)
        for (std::size_t r = 0; r < a.size(); ++r) *out++ = c[r][k] * (b[r][j] * a[r][i]);
  return C;
}

// Operators shared across patches: each patch's 1-D vectors get global ids
// by their entries (rounded to 1e-13), and an operator is keyed by the
// global ids of its functions' vectors. The matrices of the distinct keys
// are made at the end, on all cores.
class GlobalOperators {
 public:
  // Global operator ids of a patch's operators (the patch's cells must
  // outlive build()).
  std::vector<int> add(const PatchCells& cells) {
    std::vector<int> global_1d;
    std::vector<long long> rounded;  // reused: a key is copied into the map only when new
    for (const Eigen::VectorXd& v : cells.vectors_1d) {
      rounded.clear();
      for (Eigen::Index i = 0; i < v.size(); ++i) rounded.push_back(std::llround(v[i] * 1e13));
      auto it = ids_1d_.find(rounded);
      if (it == ids_1d_.end()) it = ids_1d_.emplace(rounded, static_cast<int>(ids_1d_.size())).first;
      global_1d.push_back(it->second);
    }
    std::vector<int> out, key;
    for (const std::vector<int>& local : cells.operator_keys) {
      key.clear();
      for (const int id : local) key.push_back(global_1d[static_cast<std::size_t>(id)]);
      auto it = ids_.find(key);
      if (it == ids_.end()) {
        it = ids_.emplace(key, static_cast<int>(sources_.size())).first;
        sources_.push_back({&cells, &local});
      }
      out.push_back(it->second);
    }
    return out;
  }

  std::vector<Eigen::MatrixXd> build() const {
    std::vector<Eigen::MatrixXd> operators(sources_.size());
    parallel_for(sources_.size(), [&](std::size_t k) { operators[k] = operator_matrix(*sources_[k].first, *sources_[k].second); });
    return operators;
  }

 private:
  std::unordered_map<std::vector<long long>, int, IntsHash> ids_1d_;
  std::unordered_map<std::vector<int>, int, IntsHash> ids_;
  std::vector<std::pair<const PatchCells*, const std::vector<int>*>> sources_;  // per global operator: a patch's key
};

// The element faces on the patch's labelled sides and on its interfaces with a surface.
void add_boundary_faces(const TSplineModel& m, int patch, int first_element, const PatchCells& cells, ExtractionModel& out) {
  const Patch& P = m.base.patches[static_cast<std::size_t>(patch)];
  auto add_faces = [&](Side side, int label, std::vector<ExtractionBoundaryFace>& faces) {
    const std::size_t n = static_cast<std::size_t>(side.direction()), end = side.parameter() ? 1 : 0;
    const double at = end ? P.knots[n].back() : P.knots[n].front();
    for (std::size_t e = 0; e < cells.elements.size(); ++e)
      if (cells.elements[e].domain[n][end] == at) faces.push_back({first_element + static_cast<int>(e), side, label});
  };
  for (const BoundarySide& b : m.base.boundaries)
    if (b.patch == patch) add_faces(b.side, b.label, out.boundary_faces);
  for (const Interface& itf : m.base.interfaces)
    if (itf.patch_a == patch && itf.surface >= 0) add_faces(itf.side_a, itf.surface, out.interface_faces);
}

// The patches' functions joined across interfaces into the model's
// functions: ids in order of first appearance, and one control point each
// (every copy must agree).
struct SharedFunctions {
  const std::vector<PatchCells>& cells;
  std::vector<int> offset;    // per patch: its first function in the concatenation
  std::vector<int> class_of;  // per function of the concatenation: its class (a representative)
  double scale;

  SharedFunctions(const TSplineModel& m, const std::vector<PatchCells>& c, double s) : cells(c), scale(s) {
    int total = 0;
    for (const PatchCells& pc : cells) {
      offset.push_back(total);
      total += static_cast<int>(pc.functions.size());
    }
    UnionFind classes(total);
    for (const Interface& itf : m.base.interfaces) join_interface(m, itf, cells, offset, classes);
    class_of.resize(static_cast<std::size_t>(total));
    for (int x = 0; x < total; ++x) class_of[static_cast<std::size_t>(x)] = classes.find(x);
  }

  // Per patch function (concatenated) its model function.
  std::vector<int> global_ids() const {
    std::vector<int> global(class_of.size(), -1), id_of_class(class_of.size(), -1);
    int next = 0;
    for (std::size_t p = 0; p < cells.size(); ++p)
      for (Eigen::Index f = 0; f < cells[p].homogeneous.rows(); ++f) {
        const std::size_t x = static_cast<std::size_t>(offset[p] + f), c = static_cast<std::size_t>(class_of[x]);
        if (id_of_class[c] < 0) id_of_class[c] = next++;
        global[x] = id_of_class[c];
      }
    return global;
  }

  // The model's control points and weights: each function's first copy;
  // throws internal_error where a twin across an interface differs.
  void set_control_points(const MultiPatch& mp, ExtractionModel& out) const {
    std::vector<int> id_of_class(class_of.size(), -1);
    std::vector<Eigen::RowVector4d> homogeneous;
    for (std::size_t p = 0; p < cells.size(); ++p)
      for (Eigen::Index f = 0; f < cells[p].homogeneous.rows(); ++f) {
        const std::size_t c = static_cast<std::size_t>(class_of[static_cast<std::size_t>(offset[p] + f)]);
        if (id_of_class[c] < 0) {
          id_of_class[c] = static_cast<int>(homogeneous.size());
          homogeneous.push_back(cells[p].homogeneous.row(f));
        } else if ((homogeneous[static_cast<std::size_t>(id_of_class[c])] - cells[p].homogeneous.row(f)).cwiseAbs().maxCoeff() > 1e-9 * scale) {
          throw internal_error("T-spline: patch " + std::to_string(p) + " function " + std::to_string(f) +
                               " differs from its twin across an interface");
        }
      }
    out.control_points.resize(static_cast<Eigen::Index>(homogeneous.size()), 3);
    out.weights.resize(static_cast<Eigen::Index>(homogeneous.size()));
    for (std::size_t g = 0; g < homogeneous.size(); ++g) {
      out.weights[static_cast<Eigen::Index>(g)] = homogeneous[g][3];
      out.control_points.row(static_cast<Eigen::Index>(g)) = homogeneous[g].head<3>() / homogeneous[g][3];
    }
    // A polynomial model keeps weights of exactly 1.
    bool rational = false;
    for (const Patch& p : mp.patches) rational = rational || p.rational();
    if (!rational) out.weights.setOnes();
  }
};

}  // namespace

ExtractionModel extraction_model(const TSplineModel& model) {
  const MultiPatch& mp = model.base;
  const double scale = model_scale(mp);
  // Patches on all cores: each writes only its own cells (the same result on any thread count).
  std::vector<PatchCells> cells(mp.patches.size());
  parallel_for(mp.patches.size(), [&](std::size_t p) {
    cells[p] = patch_cells(mp.patches[p], model.meshes[p], static_cast<int>(p));
    if (model.meshes[p].refined()) check_reproduces_geometry(mp.patches[p], cells[p], static_cast<int>(p), 1e-10 * scale);
  });
  // Which operators are the same does not depend on the functions' classes: the two run side by side.
  std::optional<SharedFunctions> functions;
  std::vector<std::vector<int>> global_operator(cells.size());
  GlobalOperators operators;
  std::vector<int> global;
  parallel_for(2, [&](std::size_t task) {
    if (task == 0) {
      functions.emplace(model, cells, scale);
      global = functions->global_ids();
    } else {
      for (std::size_t p = 0; p < cells.size(); ++p) global_operator[p] = operators.add(cells[p]);
    }
  });
  ExtractionModel out;
  functions->set_control_points(mp, out);
  std::size_t element_count = 0;
  for (const PatchCells& c : cells) element_count += c.elements.size();
  out.elements.reserve(element_count);
  for (std::size_t p = 0; p < cells.size(); ++p) {
    add_boundary_faces(model, static_cast<int>(p), static_cast<int>(out.elements.size()), cells[p], out);
    for (ExtractionElement& e : cells[p].elements) {
      for (int& f : e.functions) f = global[static_cast<std::size_t>(functions->offset[p] + f)];
      e.extraction = global_operator[p][static_cast<std::size_t>(e.extraction)];
      out.elements.push_back(std::move(e));
    }
  }
  out.operators = operators.build();
  copy_model_descriptions(mp, out);
  return out;
}

}  // namespace igaprep::spline
