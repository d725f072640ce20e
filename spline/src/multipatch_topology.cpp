// Validation, interface correspondences, conformity check and global numbering.
#include "igaprep/spline/multipatch_topology.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "igaprep/core/error.h"
#include "igaprep/core/union_find.h"
#include "igaprep/spline/curve_surface.h"
#include "igaprep/spline/knot_vector.h"

namespace igaprep::spline {

namespace {
const char* kDirName[3] = {"u", "v", "w"};

std::string itf_name(const MultiPatch& mp, const Interface& itf) {
  std::ostringstream s;
  const auto it = std::find_if(mp.interfaces.begin(), mp.interfaces.end(),
                               [&](const Interface& o) { return &o == &itf; });
  if (it != mp.interfaces.end()) s << "interface " << (it - mp.interfaces.begin()) << " ";
  s << "(patch " << itf.patch_a << " side " << itf.side_a << " / patch " << itf.patch_b << " side "
    << itf.side_b << ")";
  return s.str();
}

// Structural checks of one interface; throws bad_input.
void check_interface(const MultiPatch& mp, const Interface& itf) {
  const std::string name = itf_name(mp, itf);
  const int np = static_cast<int>(mp.patches.size());
  if (itf.patch_a < 0 || itf.patch_a >= np || itf.patch_b < 0 || itf.patch_b >= np)
    throw bad_input(name + ": patch index outside 0.." + std::to_string(np - 1));
  if (!itf.side_a.valid() || !itf.side_b.valid())
    throw bad_input(name + ": side outside 1..6");
  if (itf.patch_a == itf.patch_b && itf.side_a == itf.side_b) throw bad_input(name + ": glues a side to itself");
  std::array<int, 3> sorted = itf.dirmap;
  std::sort(sorted.begin(), sorted.end());
  if (sorted != std::array<int, 3>{{0, 1, 2}}) throw bad_input(name + ": dirmap is not a permutation of 0, 1, 2");
  for (int o : itf.orient)
    if (o != 0 && o != 1) throw bad_input(name + ": orient entries must be 0 or 1");
  const int da = itf.side_a.direction(), db = itf.side_b.direction();
  if (itf.dirmap[da] != db)
    throw bad_input(name + ": dirmap must map the normal direction of side_a (" + kDirName[da] +
                    ") to that of side_b (" + kDirName[db] + ")");
  const Patch &A = mp.patches[itf.patch_a], &B = mp.patches[itf.patch_b];
  for (int d = 0; d < 3; ++d) {
    if (d == da) continue;
    const int e = itf.dirmap[d];
    if (A.count(d) != B.count(e))
      throw bad_input(name + ": patch " + std::to_string(itf.patch_a) + " has " + std::to_string(A.count(d)) +
                      " control points in direction " + kDirName[d] + " but patch " + std::to_string(itf.patch_b) +
                      " has " + std::to_string(B.count(e)) + " in direction " + kDirName[e]);
  }
}
}  // namespace

void validate_patch(const Patch& p, const std::string& what) {
  for (int d = 0; d < 3; ++d) {
    const int n = static_cast<int>(p.knots[d].size()) - p.degrees[d] - 1;
    validate_knot_vector(p.knots[d], p.degrees[d], n, what + " direction " + kDirName[d]);
  }
  const long N = static_cast<long>(p.count(0)) * p.count(1) * p.count(2);
  if (p.control_points.rows() != N || p.control_points.cols() != 3)
    throw bad_input(what + ": " + std::to_string(p.control_points.rows()) + " x " +
                    std::to_string(p.control_points.cols()) + " control points, expected " + std::to_string(N) +
                    " x 3 from the knot vectors");
  if (!p.control_points.allFinite()) throw bad_input(what + ": control point coordinates are not all finite");
  if (p.rational()) {
    if (p.weights.size() != N)
      throw bad_input(what + ": " + std::to_string(p.weights.size()) + " weights for " + std::to_string(N) +
                      " control points");
    for (long i = 0; i < N; ++i)
      if (!(p.weights[i] > 0) || !std::isfinite(p.weights[i]))
        throw bad_input(what + ": weight " + std::to_string(i) + " is not positive and finite");
  }
  if (p.displacement.size() > 0 && (p.displacement.rows() != N || p.displacement.cols() != 3))
    throw bad_input(what + ": displacement must have one row of 3 per control point");
}

void validate_multipatch(const MultiPatch& mp) {
  for (size_t i = 0; i < mp.patches.size(); ++i) {
    validate_patch(mp.patches[i], "patch " + std::to_string(i));
    const int m = mp.patches[i].material;
    if (m < 0 || (!mp.materials.empty() && m >= static_cast<int>(mp.materials.size())))
      throw bad_input("patch " + std::to_string(i) + ": material " + std::to_string(m) + " does not exist");
  }
  for (const Interface& itf : mp.interfaces) {
    check_interface(mp, itf);
    if (itf.surface < -1 || itf.surface >= static_cast<int>(mp.labels.size()))
      throw bad_input(itf_name(mp, itf) + ": surface label " + std::to_string(itf.surface) + " does not exist");
  }
  for (size_t i = 0; i < mp.boundaries.size(); ++i) {
    const BoundarySide& b = mp.boundaries[i];
    const std::string name = "boundary " + std::to_string(i) + " (patch " + std::to_string(b.patch) + " side " +
                             std::to_string(b.side) + ")";
    if (b.patch < 0 || b.patch >= static_cast<int>(mp.patches.size())) throw bad_input(name + ": no such patch");
    if (!b.side.valid()) throw bad_input(name + ": side outside 1..6");
    if (b.label < 0 || b.label >= static_cast<int>(mp.labels.size()))
      throw bad_input(name + ": label " + std::to_string(b.label) + " does not exist");
  }
}

int map_to_neighbour(const MultiPatch& mp, const Interface& itf, int local_a) {
  check_interface(mp, itf);
  const Patch &A = mp.patches[itf.patch_a], &B = mp.patches[itf.patch_b];
  const int da = itf.side_a.direction(), db = itf.side_b.direction();
  int ia[3];
  ia[0] = local_a % A.count(0);
  ia[1] = (local_a / A.count(0)) % A.count(1);
  ia[2] = local_a / (A.count(0) * A.count(1));
  if (local_a < 0 || ia[2] >= A.count(2) || ia[da] != (itf.side_a.parameter() ? A.count(da) - 1 : 0))
    throw bad_input(itf_name(mp, itf) + ": control point " + std::to_string(local_a) + " of patch " +
                    std::to_string(itf.patch_a) + " is not on side " + std::to_string(itf.side_a));
  int ib[3];
  ib[db] = itf.side_b.parameter() ? B.count(db) - 1 : 0;
  for (int d = 0; d < 3; ++d) {
    if (d == da) continue;
    const int e = itf.dirmap[d];
    ib[e] = itf.orient[d] ? ia[d] : B.count(e) - 1 - ia[d];
  }
  return B.index(ib[0], ib[1], ib[2]);
}

std::vector<std::pair<int, int>> interface_point_pairs(const MultiPatch& mp, const Interface& itf) {
  check_interface(mp, itf);
  std::vector<std::pair<int, int>> out;
  for (int a : side_control_points(mp.patches[itf.patch_a], itf.side_a))
    out.emplace_back(a, map_to_neighbour(mp, itf, a));
  return out;
}

ConformityReport check_conformity(const MultiPatch& mp, double tol) {
  ConformityReport rep;
  auto problem = [&](const std::string& s) {
    rep.conforming = false;
    rep.problems.push_back(s);
  };
  for (size_t ii = 0; ii < mp.interfaces.size(); ++ii) {
    const Interface& itf = mp.interfaces[ii];
    const std::string name = itf_name(mp, itf);
    try {
      check_interface(mp, itf);
    } catch (const Error& e) {
      problem(e.what());
      continue;
    }
    const Patch &A = mp.patches[itf.patch_a], &B = mp.patches[itf.patch_b];
    const int da = itf.side_a.direction();
    bool knots_ok = true;
    for (int d = 0; d < 3; ++d) {
      if (d == da) continue;
      const int e = itf.dirmap[d];
      const auto &Ka = A.knots[d], &Kb = B.knots[e];
      std::ostringstream s;
      if (A.degrees[d] != B.degrees[e]) {
        s << name << ": degree " << A.degrees[d] << " in direction " << kDirName[d] << " of patch " << itf.patch_a
          << " but " << B.degrees[e] << " in direction " << kDirName[e] << " of patch " << itf.patch_b;
        problem(s.str());
        knots_ok = false;
        continue;
      }
      if (Ka.size() != Kb.size()) continue;  // counts were checked above; sizes then agree
      const double a0 = Ka.front(), a1 = Ka.back(), b0 = Kb.front(), b1 = Kb.back();
      double worst = 0;
      size_t at = 0;
      for (size_t k = 0; k < Ka.size(); ++k) {
        const double ta = (Ka[k] - a0) / (a1 - a0);
        const double tb = itf.orient[d] ? (Kb[k] - b0) / (b1 - b0) : (b1 - Kb[Kb.size() - 1 - k]) / (b1 - b0);
        if (std::abs(ta - tb) > worst) worst = std::abs(ta - tb), at = k;
      }
      if (worst > 1e-10) {
        s << name << ": knot vectors differ after orientation: direction " << kDirName[d] << " of patch "
          << itf.patch_a << " vs direction " << kDirName[e] << " of patch " << itf.patch_b << ", knot " << at
          << " off by " << worst << " (relative)";
        problem(s.str());
        knots_ok = false;
      }
    }
    (void)knots_ok;
    double worst = 0, worst_w = 0;
    std::pair<int, int> at{-1, -1}, at_w{-1, -1};
    for (const auto& pr : interface_point_pairs(mp, itf)) {
      const double dist = (A.control_points.row(pr.first) - B.control_points.row(pr.second)).norm();
      if (!(dist <= worst)) worst = dist, at = pr;
      const double wa = A.rational() ? A.weights[pr.first] : 1.0, wb = B.rational() ? B.weights[pr.second] : 1.0;
      const double dw = std::abs(wa - wb) / std::max(std::abs(wa), std::abs(wb));
      if (dw > worst_w) worst_w = dw, at_w = pr;
    }
    rep.max_deviation = std::max(rep.max_deviation, worst);
    if (!(worst <= tol)) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.1e", worst);
      problem(name + ": control point " + std::to_string(at.first) + " / " + std::to_string(at.second) +
              " off by " + buf);
    }
    if (worst_w > 1e-10) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.1e", worst_w);
      problem(name + ": weight of control point " + std::to_string(at_w.first) + " / " +
              std::to_string(at_w.second) + " differs by " + buf + " (relative)");
    }
  }
  return rep;
}

long control_point_count(const MultiPatch& mp) {
  long n = 0;
  for (const Patch& p : mp.patches) n += static_cast<long>(p.control_points.rows());
  return n;
}

GlobalNumbering global_numbering(const MultiPatch& mp) {
  GlobalNumbering g;
  std::vector<long> offset(mp.patches.size() + 1, 0);
  for (size_t p = 0; p < mp.patches.size(); ++p) offset[p + 1] = offset[p] + mp.patches[p].control_points.rows();
  UnionFind copies(static_cast<int>(offset.back()));  // the copies of one control point
  for (const Interface& itf : mp.interfaces)
    for (const auto& pr : interface_point_pairs(mp, itf))
      copies.unite(static_cast<int>(offset[itf.patch_a] + pr.first), static_cast<int>(offset[itf.patch_b] + pr.second));
  std::vector<int> number(static_cast<std::size_t>(copies.size()), -1);
  g.global.resize(mp.patches.size());
  g.patch_offset.resize(mp.patches.size());
  for (size_t p = 0; p < mp.patches.size(); ++p) {
    g.patch_offset[p] = g.count;
    g.global[p].resize(mp.patches[p].control_points.rows());
    for (long i = 0; i < mp.patches[p].control_points.rows(); ++i) {
      const int r = copies.find(static_cast<int>(offset[p] + i));
      if (number[r] < 0) number[r] = g.count++;
      g.global[p][i] = number[r];
    }
  }
  return g;
}

Eigen::MatrixXd global_points(const MultiPatch& mp, const GlobalNumbering& gn) {
  Eigen::MatrixXd X(gn.count, 3);
  for (std::size_t p = 0; p < mp.patches.size(); ++p)
    for (Eigen::Index i = 0; i < mp.patches[p].control_points.rows(); ++i)
      X.row(gn.global[p][static_cast<std::size_t>(i)]) = mp.patches[p].control_points.row(i);
  return X;
}

}  // namespace igaprep::spline
