#pragma once
// What the sampled blocks leave out of the input, told by the stage that
// made them rather than only by the check at the end: per material, the
// blocks' signed volume (their sample grids' cells, folded ones counting
// negative) against the volume the input encloses there; on T1, the parts
// that no block side labelled T1 comes near. The sample grids are piecewise
// linear, so the limits here are coarser than the check's (block_coverage.cpp).
#include <string>
#include <vector>

#include "igaprep/iga_check/report.h"
#include "igaprep/param/volume_param.h"
#include "igaprep/pipeline/surfaces.h"

namespace igaprep::pipeline {

// The largest distance from a vertex of t1 to the block sides labelled T1
// (their sample grids cut into triangles), over t1's diagonal; infinity
// when no side lies on T1.
double t1_sample_gap(const param::VolumeParam& vp, const mesh::TriMesh& t1);

// Where the blocks' sides on T1 are too coarse: for each vertex of t1 that
// lies farther than `limit` (a share of t1's diagonal) from every block side
// on T1, the shell face whose side is nearest, and the direction of that
// face along which the nearest sample cell is the longer; sorted, each once.
std::vector<param::FaceDirection> faces_missing_t1(const param::VolumeParam& vp, const mesh::TriMesh& t1,
                                                   double limit);

// One line per finding (empty when the blocks cover the input).
std::vector<std::string> block_coverage_findings(const param::VolumeParam& vp, const Surfaces& surfaces,
                                                 const iga_check::CheckOptions& limits);

}  // namespace igaprep::pipeline
