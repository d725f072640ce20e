#pragma once
// Nesting of closed surfaces T1..Tn, outermost first: each T(i+1) must lie
// strictly inside T(i), and no two surfaces may intersect or touch. Decided
// with exact predicates (CGAL: face-pair intersection tests and
// Side_of_triangle_mesh on an exact-predicates kernel), so it never flips on
// round-off.
#include <string>
#include <vector>

#include "igaprep/core/error.h"  // the functions here throw igaprep::Error
#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::mesh {

struct NestingReport {
  bool nested = false;
  std::vector<std::string> errors;  // one per offending pair, naming both surfaces
};

// Inputs: surfaces, each closed, manifold and oriented (see check_surface);
// names, one per surface, for the messages.
// Output: nested == errors.empty(). Throws Error(BadInput) only when the two
// vectors differ in size.
NestingReport check_nesting(const std::vector<TriMesh>& surfaces, const std::vector<std::string>& names);

}  // namespace igaprep::mesh
