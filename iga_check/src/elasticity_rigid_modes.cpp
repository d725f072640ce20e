#include "elasticity_rigid_modes.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <map>
#include <sstream>
#include <string>

#include "igaprep/core/error.h"
#include "igaprep/core/union_find.h"

namespace igaprep::iga_check::detail {

namespace {

using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Vector6 = Eigen::Matrix<double, 6, 1>;

// Patches coupled through shared control points, as lists of patches in
// increasing order, and the first patch of each control point.
struct Parts {
  std::map<int, std::vector<int>> patches;  // root -> patches
  std::vector<int> owner;                   // global control point -> first patch holding it
  std::vector<int> root;                    // patch -> root of its part
};

Parts connected_parts(const spline::MultiPatch& mp, const spline::GlobalNumbering& num) {
  const int np = static_cast<int>(mp.patches.size());
  UnionFind connected(np);  // patches that share a control point
  Parts parts;
  parts.owner.assign(num.count, -1);
  for (int p = 0; p < np; ++p)
    for (int g : num.global[p]) {
      if (parts.owner[g] < 0) parts.owner[g] = p;
      else connected.unite(p, parts.owner[g]);
    }
  parts.root.resize(np);
  for (int p = 0; p < np; ++p) {
    parts.root[p] = connected.find(p);
    parts.patches[parts.root[p]].push_back(p);
  }
  return parts;
}

// Gram matrix of the six modes (translations, rotations about the centroid,
// lengths scaled by the part's size) restricted to the constrained components
// of the control points cps.
Matrix6 constrained_mode_gram(const Eigen::MatrixXd& X, const std::vector<int>& cps,
                              const std::vector<unsigned char>& constrained) {
  Eigen::Vector3d lo = X.row(cps[0]), hi = lo, c = Eigen::Vector3d::Zero();
  for (int g : cps) {
    lo = lo.cwiseMin(X.row(g).transpose());
    hi = hi.cwiseMax(X.row(g).transpose());
    c += X.row(g).transpose();
  }
  c /= static_cast<double>(cps.size());
  const double L = std::max((hi - lo).norm(), 1e-300);
  Matrix6 G = Matrix6::Zero();
  for (int g : cps) {
    const Eigen::Vector3d r = (X.row(g).transpose() - c) / L;
    for (int i = 0; i < 3; ++i) {
      if (!constrained[3 * g + i]) continue;
      Vector6 row = Vector6::Zero();
      row(i) = 1.0;
      for (int k = 0; k < 3; ++k) row(3 + k) = Eigen::Vector3d::Unit(k).cross(r)(i);
      G += row * row.transpose();
    }
  }
  return G;
}

// The labels of the boundary sides of the given patches (sorted), quoted; "none" if none.
std::string boundary_labels_of(const spline::MultiPatch& mp, const std::vector<int>& patches) {
  std::vector<int> labels;
  for (const auto& b : mp.boundaries)
    if (std::binary_search(patches.begin(), patches.end(), b.patch)) labels.push_back(b.label);
  std::sort(labels.begin(), labels.end());
  labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
  std::string s;
  for (int l : labels) s += (s.empty() ? "'" : ", '") + mp.labels[l] + "'";
  return s.empty() ? "none" : s;
}

std::string rigid_modes_message(const spline::MultiPatch& mp, const std::vector<int>& patches, int free_modes,
                                const Vector6& mode) {
  static const char* const names[6] = {"translation in x", "translation in y", "translation in z",
                                       "rotation about x", "rotation about y", "rotation about z"};
  std::string motion;
  for (int k = 0; k < 6; ++k)
    if (std::abs(mode(k)) > 0.3) motion += (motion.empty() ? "" : " + ") + std::string(names[k]);
  std::ostringstream part;
  part << "the part of the model made of patch" << (patches.size() > 1 ? "es" : "");
  for (size_t i = 0; i < patches.size() && i < 10; ++i) part << (i ? ", " : " ") << patches[i];
  if (patches.size() > 10) part << ", ...";
  const std::string labels = boundary_labels_of(mp, patches);
  std::ostringstream s;
  if (free_modes == 6)
    s << "no boundary of " << part.str() << " is fixed or prescribed: its 6 rigid-body motions are free and the "
      << "stiffness matrix is singular; fix at least one of its labelled boundaries (" << labels << ")";
  else
    s << "the constraints leave " << free_modes << " rigid-body motion" << (free_modes > 1 ? "s" : "") << " free (e.g. "
      << motion << ") in " << part.str() << "; the stiffness matrix is singular: fix more displacement components "
      << "on the labelled boundaries of that part (" << labels << ")";
  return s.str();
}

}  // namespace

void check_rigid_modes(const spline::MultiPatch& mp, const spline::GlobalNumbering& num,
                       const std::vector<unsigned char>& constrained) {
  const Parts parts = connected_parts(mp, num);
  const Eigen::MatrixXd X = spline::global_points(mp, num);
  for (const auto& [root, patches] : parts.patches) {
    std::vector<int> cps;
    for (int g = 0; g < num.count; ++g)
      if (parts.root[parts.owner[g]] == root) cps.push_back(g);
    Eigen::SelfAdjointEigenSolver<Matrix6> es(constrained_mode_gram(X, cps, constrained));
    const double tol = 1e-10 * std::max(1.0, es.eigenvalues().maxCoeff());
    int free_modes = 0;
    for (int k = 0; k < 6; ++k)
      if (es.eigenvalues()(k) <= tol) ++free_modes;
    if (free_modes > 0) throw bad_input(rigid_modes_message(mp, patches, free_modes, es.eigenvectors().col(0)));
  }
}

}  // namespace igaprep::iga_check::detail
