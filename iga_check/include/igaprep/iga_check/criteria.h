#pragma once
// The criteria of the check's verdict, each judged on its own so that a report
// says which failed, by how much and where (docs/check-report.md):
//  - jacobian: every element certified positive (report.cpp judges it);
//  - conformity: interfaces match control point for control point;
//  - watertight: every patch side an interface, a labelled boundary or collapsed;
//  - fidelity: every input surface and the spline faces standing for it within
//    the limit of each other, both ways, relative to the input's diagonal (the
//    outermost surface's bounding box); a surface no face stands for fails;
//  - volume: every region between nested input surfaces (a material) within
//    the limit of the volume the input encloses there.
// Fidelity and volume need the input surfaces; without them they are not
// checked, and say so.
#include <string>
#include <vector>

#include "igaprep/iga_check/fidelity.h"
#include "igaprep/iga_check/topology_checks.h"
#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::iga_check {

struct Criterion {
  std::string name;      // "jacobian", "conformity", "watertight", "fidelity", "volume"
  bool checked = true;   // false: nothing to judge it on (no input surfaces); it then passes
  bool passed = true;
  double value = 0.0;    // the worst figure: relative for fidelity and volume (signed for volume)
  double limit = 0.0;    // what |value| is compared with, in the same unit
  std::string summary;   // one line: the figure against its limit
  std::vector<std::string> findings;  // where it fails: patches, sides, input regions
};

// Largest interface control-point gap, relative to the model's diagonal.
Criterion conformity_criterion(const TopologyReport& t, double tolerance);

Criterion watertight_criterion(const TopologyReport& t);

// Inputs: the fidelity entries, the surfaces they were measured on, their
// labels, the input's diagonal (relative distances divide by it), the limit.
Criterion fidelity_criterion(const std::vector<SurfaceFidelity>& fidelity, const std::vector<mesh::TriMesh>& surfaces,
                             const std::vector<std::string>& labels, double input_diagonal, double limit);

// Regions from `materials` on have no material (voids inside the innermost
// surfaces): their spline volume must stay within the limit of zero.
Criterion volume_criterion(const TopologyReport& t, const std::vector<std::string>& labels, int materials,
                           double limit);

// The names of the criteria that failed, comma separated ("" when none).
std::string failed_criterion_names(const std::vector<Criterion>& criteria);

// Most findings a criterion lists; the last line then says how many more.
inline constexpr int kMaxFindings = 12;

}  // namespace igaprep::iga_check
