#pragma once
// Lobes of a sheet: parts joined to the rest across a narrow neck (a
// figure's ears, a hand's fingers, an animal's legs). Mapped onto one
// rectangle, a lobe is squeezed exponentially in its length over its neck's
// width and the volume above it is lost; each lobe gets an arm of the (u, v)
// domain instead (polycube_2d.h, RectilinearDomain::arms).
#include <vector>

#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::param {

struct SheetLobe {
  int start = 0, end = 0;  // positions in the loop: the lobe's boundary runs forward from start to end
  double neck = 0.0;       // straight distance between the two ends
  double area = 0.0;       // area of the part the neck cuts off
  double modulus = 0.0;    // area / neck^2: the lobe's length over its width
};

struct LobeOptions {
  double min_modulus = 1.5;     // a lobe longer than wide (a square bump is none)
  double max_area_share = 0.45;  // a lobe is the smaller part of the sheet
  // The lobes together leave the body at least a quarter of the sheet: two
  // blades on a small hub (the propeller, 88 % in its blades) are one long
  // sheet with a bulge, mapped better onto one rectangle along it than as a
  // hub with two arms; a hand keeps its fingers (37 %), an elephant its legs
  // and trunk (66 %).
  double max_total_share = 0.75;
  int samples = 200;             // candidate neck ends along the loop
  // A neck's path across the sheet at most this times its straight length
  // (the edge graph zigzags; a fold of the sheet back onto itself is no neck).
  double max_detour = 3.0;
  // A lobe found at its narrowest is moved out to enclosing necks, each at
  // most `taper` times as wide as the last, while it keeps `keep_share` of
  // its modulus (a tapering finger is cut at its base, where the palm widens).
  double taper = 1.15;
  double keep_share = 0.6;
  // The sheet widens beyond a neck: the boundary points one neck width
  // outside its two ends are at least this times the neck apart (the end of
  // a long strip is no lobe: nothing narrows there).
  double min_widening = 1.5;
};

// Inputs: the sheet, one of its boundary loops (vertex indices in order),
// the other loops (a lobe holding one of their vertices is no lobe: an arm
// has no holes). Output: lobes whose boundaries do not overlap (nor touch),
// ordered by start; none when together they exceed max_total_share of the
// sheet. Deterministic.
std::vector<SheetLobe> find_lobes(const mesh::TriMesh& sheet, const std::vector<int>& loop,
                                  const std::vector<std::vector<int>>& other_loops, const LobeOptions& options = {});

}  // namespace igaprep::param
