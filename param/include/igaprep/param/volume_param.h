#pragma once
// The volumetric parameterization of strategy 2 (seed paper, section 6):
// hex-topology blocks, each a map [0,1]^3 -> R^3 sampled on a tensor grid.
//
// Core (inside T(n+1), around the base surface M; polycube-like): per
// rectangle R of M's layout a block above M and one below, each ruled from
// M(s, t) (r = 0) to the point where the ray from M along D+ (D-) reaches
// w = w0; per boundary segment of M a crest block whose cross-section is the
// quadrilateral P0 (on M's boundary), P3 = the top ray's end, P2 = the end of
// the ray along M's outward binormal, P1 = the bottom ray's end. D+- lean
// outwards near M's boundary so that S+ and S- leave it at the angle theta
// from M's plane: the three blocks meet at M's boundary at 180 - theta,
// 180 - theta and 2 theta degrees (interior extraordinary edges, valence 3).
//
// Strategy 1 (no core): the shell grows from M itself, its columns starting
// next to M along D+ and D-, and each crest is a fan of streamlines from M's
// boundary, from D+ through the binormal to D-: a block whose side on M is
// collapsed to M's boundary curve (degenerate, as the paper says).
//
// Shell (between T1 and T(n+1)): every outer face of the core (the top and
// bottom faces of the rectangle blocks, the two outer faces of each crest
// block) is carried out to T1 along streamlines of -grad w, one block per
// material layer: layer k spans w in [(k - 1)/n, k/n] (the innermost one up
// to the core), so layer faces lie on the Ti exactly. S+, S- and the corner
// surfaces are the streamline surfaces from the core's outer edges: sampled
// exactly, never a staircase of tets. The shells of the crest faces (and
// strategy 1's fans) trace only the columns of their long edges (and the
// fan's binormal row) and are linear across in between, their points on T1
// and the Ti put back onto those surfaces: their own streamlines bunch up on
// the ridge of w in M's plane. With strategy 2, M and the lids are smoothed
// per rectangle first (surface_degree).
#include <array>
#include <vector>

#include <Eigen/Core>

#include "igaprep/core/progress.h"

#include "igaprep/param/base_layout.h"
#include "igaprep/param/decomposition_mesh.h"
#include "igaprep/param/surface_grid_relax.h"
#include "igaprep/param/w_field.h"

namespace igaprep::param {

struct VolumeParamOptions {
  int strategy = 2;  // section 6: 2 (default) or 1
  // Angle of S+ and S- from M's plane at its boundary: 1.1 rad (63 degrees); pi/4 leaves the crests'
  // shells so thin near T1 that the fit folds there, and repairing that costs fidelity (docs/decomposition.md).
  double theta = 1.1;
  double w0 = -1.0;     // iso-value of T(n+1) in ((n - 1)/n, 1); < 0: midway, at least 0.75
  double blend = 1.0;  // the rays lean out within this fraction of the narrowest band of M's domain from its boundary
  double crest_reach = 1.0;  // P2 at this fraction of the kite point (see build_volume_param)
  // Strategy 2: M and the lids, per rectangle, smoothed onto polynomials of
  // this degree per direction (grid_smoothing.h); 0 = as sampled.
  int surface_degree = 6;
  // Strategy 2: within this share of a rectangle's side from a corner on
  // M's boundary, the smoothed sides of M and the lids keep their samples
  // (grid_smoothing.h, KeptCorners); 0 (default): smoothed throughout.
  // ring2 and torus3 fitted with 12 elements per direction are certified
  // with 0.15, but torus_genus3 loses its pass at 9 (docs/decomposition.md).
  double corner_share = 0.0;
  // Strategy 2: a shell face's streamline ends are spread also where the
  // end from the middle of a gap lies farther than this fraction of the
  // diagonal from the cubic through the nearest ends (a part of T1 bulging
  // out between two samples, shell_spread.h); 0 (default): only where the
  // gaps are uneven. Not on everywhere: on the built-in models it lowers the
  // validation rate (docs/decomposition.md, "Bulges between samples"); the
  // pipeline sets it where the samples miss T1.
  double spread_deviation = 0.0;
  // Strategy 2: a spread face's side on T1 relaxed on T1 where its cells
  // fold there (surface_grid_relax.h); rounds = 0: off.
  SurfaceGridRelaxOptions t1_relax;
  // Strategy 2: the widest ring of cells around the core's folded ruled
  // cells whose lid points are re-aimed (lid_relax.h; docs/decomposition.md,
  // "Lids unfolded"); 0 (default): counted, not re-aimed.
  int lid_relax_rings = 0;
  double ray_step = 2e-3;     // ray march step, fraction of H's bounding-box diagonal
  double stream_step = 1e-3;  // streamline step (Runge-Kutta 4), fraction of the diagonal
  ProgressCallback progress;  // streamlines traced, per core face
};

enum class BlockKind { CoreTop, CoreBottom, Crest, Shell };
const char* to_string(BlockKind kind);

struct SampledBlock {
  BlockKind kind = BlockKind::Shell;
  int material = 0;  // 0 = between T1 and T2, ..., n - 1 = inside Tn
  int source = 0;    // rectangle (core top/bottom), crest segment (crest) or core face (shell)
  int layer = 0;     // shell: 1..n counted from T1; core: 0
  Eigen::MatrixXd samples;  // m^3 x 3 on params^3, first direction fastest
  // Per side (G+Smo order u0, u1, v0, v1, w0, w1): the surface label it lies
  // on when it is a boundary of the model (0 = T1), else -1 (an interface).
  std::array<int, 6> side_label{{-1, -1, -1, -1, -1, -1}};
  std::array<bool, 6> collapsed{};  // sides that are a curve (strategy 1: the crest fans at M's boundary)
  bool mirrored = false;  // the first direction was reversed for a positive orientation
  int folded = 0;         // sample-grid cells with a non-positive corner volume
};

// Reverses a block's first direction when more than half its sample cells
// are folded (a corner tet not positive): `mirrored`, the first two sides'
// labels and collapse flags swapped. Sets `folded` either way. m: samples
// per direction.
void orient_block(SampledBlock& block, int m);

// Where a face the shell grows from (a shell block's `source`) lies in M's
// layout: the rectangle it is over, and the crest segment when it is one of
// a crest's outer faces (strategy 2) or a crest's fan (strategy 1); -1: a lid
// (or, in strategy 1, M itself).
struct ShellFaceOrigin {
  int rectangle = -1;
  int crest = -1;
};

struct VolumeParam {
  std::vector<double> params;  // sample parameters in each direction (ascending, 0 and 1 included)
  std::vector<SampledBlock> blocks;
  std::vector<ShellFaceOrigin> face_origins;  // per shell face
  double w0 = 0.0;
  int rectangles = 0, crests = 0, core_faces = 0, layers = 0;
  int streamlines = 0;     // traced from the core's outer faces to T1
  int spread_faces = 0;    // core faces whose streamlines fanned out and were spread evenly on T1 (shell_spread.h)
  int folded_cells = 0;    // sample-grid cells with a non-positive corner volume (should be 0)
  // Spread faces' sides on T1: cells folded on T1 before and after the
  // side was relaxed on T1 (VolumeParamOptions::t1_relax).
  int t1_folded_before = 0;
  int t1_folded_after = 0;
  // The core's ruled cells folded between M and its lids, before and after
  // the lids' rays were re-aimed (VolumeParamOptions::lid_relax_rings).
  int lid_folded_before = 0;
  int lid_folded_after = 0;
};

// Inputs: H and its w-field, M's layout (whose sheet must be M as embedded in
// H), the sample parameters (>= 3, ascending, from 0 to 1), options. Output:
// the blocks. Throws bad_input for an option out of range and check_failed
// when a ray or streamline fails (with the point).
VolumeParam build_volume_param(const DecompositionMesh& H, const WField& w, const BaseLayout& layout,
                               const std::vector<double>& params, const VolumeParamOptions& options = {});

// A shell face (a shell block's `source`) and one of its two sample
// directions: 0, along u on a lid and along the segment on a crest's face;
// 1, along v on a lid and across the crest on a crest's face.
struct FaceDirection {
  int face = 0;
  int direction = 0;
  bool operator<(const FaceDirection& o) const { return face != o.face ? face < o.face : direction < o.direction; }
  bool operator==(const FaceDirection& o) const { return face == o.face && direction == o.direction; }
};

// Grid lines that halve the rectangles the given faces lie over, across the
// given directions (a crest's face across the crest has no line of the
// layout to add and is passed over). Where a face's shell reaches T1
// through too few samples, the halved rectangle gives it twice as many.
GridLines lines_halving_faces(const BaseLayout& layout, const VolumeParam& vp, const std::vector<FaceDirection>& faces);

}  // namespace igaprep::param
