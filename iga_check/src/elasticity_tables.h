#pragma once
// Internal to the elasticity solver: the 1-D element tables of every patch
// and direction with their Gauss rules, built once per solve and read by
// every assembly step (the tensor structure: a volume element is a triple of
// 1-D elements).
#include <array>
#include <vector>

#include "elasticity_basis.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::iga_check::detail {

using PatchTables = std::array<std::vector<DirElement>, 3>;

// Inputs: the model; Gauss points per direction = degree + 1 + extra_quadrature.
// Output: per patch, the elements of each direction with their quadrature.
// The tables belong to the caller: concurrent solves share no mutable state.
std::vector<PatchTables> quadrature_tables(const spline::MultiPatch& mp, int extra_quadrature);

}  // namespace igaprep::iga_check::detail
