#pragma once
// The blending functions of a T-mesh of odd degree (issue 18): one per
// anchor, the anchors being the vertices of the mesh, each with a local
// knot vector of p_d + 2 knots per direction read by casting rays from the
// anchor through the faces of the boxes (Sederberg et al. 2003; Morgenstern
// 2016). The patch's repeated end knots are numbered on in index space
// beyond the domain: the low end's p copies at -kTScale, ..., -p kTScale,
// the high end's past extent(d). So every knot vector is strictly
// increasing, the anchors at the ends (one per repeated knot) are distinct,
// and dual compatibility is a plain comparison of windows.
#include <algorithm>
#include <array>
#include <optional>
#include <utility>
#include <vector>

#include "igaprep/spline/tmesh.h"

namespace igaprep::spline {

struct TFunction {
  std::array<std::vector<TCoord>, 3> knots;  // p_d + 2 per direction, index space, strictly increasing
  TCoord anchor(int d) const { return knots[static_cast<std::size_t>(d)][knots[static_cast<std::size_t>(d)].size() / 2]; }
  // The support within the patch's domain (ends clamped to [0, extent]).
  TCoord support_lo(int d) const { return std::max<TCoord>(0, knots[static_cast<std::size_t>(d)].front()); }
  TCoord support_hi(int d, const TMesh& mesh) const {
    return std::min(mesh.extent(d), knots[static_cast<std::size_t>(d)].back());
  }
  // The support as one box (lo u, hi u, lo v, hi v, lo w, hi w).
  std::array<TCoord, 6> support(const TMesh& mesh) const {
    std::array<TCoord, 6> s{};
    for (int d = 0; d < 3; ++d) s[static_cast<std::size_t>(2 * d)] = support_lo(d), s[static_cast<std::size_t>(2 * d + 1)] = support_hi(d, mesh);
    return s;
  }
};

// The distinct knot vectors of the functions in direction d, and per
// function the index of its own among them (in order of first appearance).
struct KnotVectorIds {
  std::vector<std::vector<TCoord>> vectors;
  std::vector<int> of_function;
};
KnotVectorIds knot_vector_ids(const std::vector<TFunction>& functions, int d);

// Every function of the mesh, ordered by anchor (w slowest, u fastest).
// On the initial tensor grid they are the patch's B-splines in its own
// order (n_d = elements_d + p_d per direction).
std::vector<TFunction> tspline_functions(const TMesh& mesh);

// Two knot vectors overlap when both are runs of consecutive knots of one
// increasing sequence: inside the range they share they hold the same knots.
bool knot_vectors_overlap(const std::vector<TCoord>& a, const std::vector<TCoord>& b);

// Dual compatibility (Beirao da Veiga, Buffa, Sangalli, Vazquez 2013): every
// two functions whose supports overlap have, in some direction, knot
// vectors that overlap and differ. It implies linear independence. Returns
// the first pair that fails, or nothing.
std::optional<std::pair<int, int>> dual_compatibility_violation(const TMesh& mesh,
                                                                const std::vector<TFunction>& functions);

// Throws bad_input naming two functions (anchors and knots) when the mesh's
// functions are not dual compatible: such a T-spline is not
// analysis-suitable and its functions may be linearly dependent.
void check_analysis_suitable(const TMesh& mesh);

}  // namespace igaprep::spline
