#include "igaprep/param/volume_param.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>

#include "igaprep/core/error.h"
#include "igaprep/core/progress.h"
#include "igaprep/param/field_probe.h"
#include "igaprep/param/gradient.h"
#include "igaprep/param/grid_smoothing.h"
#include "igaprep/param/inset_base.h"
#include "igaprep/param/lid_relax.h"
#include "igaprep/param/sheet_sampler.h"
#include "igaprep/param/streamline_column.h"
#include "igaprep/param/surface_grid_relax.h"
#include "igaprep/param/surface_projector.h"
#include "igaprep/param/tet_topology.h"
#include "cell_geometry.h"
#include "shell_columns.h"

namespace igaprep::param {

const char* to_string(BlockKind kind) {
  switch (kind) {
    case BlockKind::CoreTop: return "core top";
    case BlockKind::CoreBottom: return "core bottom";
    case BlockKind::Crest: return "crest";
    case BlockKind::Shell: return "shell";
  }
  return "?";
}

namespace {

// A ray of the core that fails (it leaves the solid, or does not reach its
// level within the length allowed) says that the solid is thinner along it
// than the core reaches: a property of the shape and of case keys the user
// can change (exit 1), not a failed check of a built model.
Eigen::Vector3d core_ray(const FieldProbe& probe, const char* what, const Eigen::Vector3d& from, const Eigen::Vector3d& dir,
                         double level, double step, double max_length, int* hint) {
  try {
    return probe.ray_to_level(from, dir, level, step, max_length, hint);
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::CheckFailed) throw;
    throw bad_input(std::string("param: ") + what + ": " + e.what() +
                    "; the solid is thinner along this ray than the core reaches: steeper rays ('decomposition.theta'), "
                    "a thinner core ('decomposition.w0' nearer 1), another 'decomposition.inset', or a finer tet mesh "
                    "('tetmesh.max_volume') can change that");
  }
}

using Grid2 = std::vector<Eigen::Vector3d>;  // m x m, first index fastest

// (1 - t) p + t q: exact at t = 0 and t = 1, so blocks that share a face
// compute its points bit for bit alike.
Eigen::Vector3d lerp(const Eigen::Vector3d& p, const Eigen::Vector3d& q, double t) { return (1.0 - t) * p + t * q; }

// The sample cells whose corner tet at (i, j, k) is not positive.
int count_folded(const SampledBlock& b, int m) {
  auto at = [&](int i, int j, int k) -> Eigen::Vector3d { return b.samples.row(i + m * (j + m * k)).transpose(); };
  int folded = 0;
  for (int k = 0; k + 1 < m; ++k)
    for (int j = 0; j + 1 < m; ++j)
      for (int i = 0; i + 1 < m; ++i) {
        const Eigen::Vector3d o = at(i, j, k);
        Eigen::Matrix3d E;
        E.col(0) = at(i + 1, j, k) - o;
        E.col(1) = at(i, j + 1, k) - o;
        E.col(2) = at(i, j, k + 1) - o;
        if (!(E.determinant() > 0.0)) ++folded;
      }
  return folded;
}

// Fills the rows j of a shell block (samples i + m j + m^2 k) that were not
// traced by linear interpolation across j between the traced rows 0, mid
// (if mid >= 0) and m - 1, at every i and k.
void rule_rows(Eigen::MatrixXd& s, int m, const std::vector<double>& params, int mid) {
  auto row = [&](int i, int j, int k) { return static_cast<Eigen::Index>(i + m * j + m * m * k); };
  for (int k = 0; k < m; ++k)
    for (int j = 1; j + 1 < m; ++j) {
      if (j == mid) continue;
      const int a = mid > 0 && j > mid ? mid : 0, b = mid > 0 && j < mid ? mid : m - 1;
      const double t = (params[static_cast<std::size_t>(j)] - params[static_cast<std::size_t>(a)]) /
                       (params[static_cast<std::size_t>(b)] - params[static_cast<std::size_t>(a)]);
      for (int i = 0; i < m; ++i) s.row(row(i, j, k)) = lerp(s.row(row(i, a, k)).transpose(), s.row(row(i, b, k)).transpose(), t).transpose();
    }
}

// The ruled rows' points on the block's outer face (k = 0) go back onto the
// outer level surface, those on the inner face (k = m - 1) onto the inner one
// (none: the core face, kept), and the points between move by the blend of
// the two corrections (near the crest a layer can be thinner than they are).
void put_back_on_levels(Eigen::MatrixXd& s, int m, const std::vector<double>& params, int mid,
                        const SurfaceProjector& outer_surface, const SurfaceProjector* inner_surface) {
  for (int j = 1; j + 1 < m; ++j) {
    if (j == mid) continue;
    for (int i = 0; i < m; ++i) {
      const Eigen::Index outer = i + m * j, inner = outer + static_cast<Eigen::Index>(m) * m * (m - 1);
      const Eigen::RowVector3d d_outer = outer_surface.closest(s.row(outer).transpose()).transpose() - s.row(outer);
      const Eigen::RowVector3d d_inner =
          inner_surface ? Eigen::RowVector3d(inner_surface->closest(s.row(inner).transpose()).transpose() - s.row(inner))
                        : Eigen::RowVector3d::Zero();
      for (int k = 0; k < m; ++k)
        s.row(outer + static_cast<Eigen::Index>(m) * m * k) +=
            (1.0 - params[static_cast<std::size_t>(k)]) * d_outer + params[static_cast<std::size_t>(k)] * d_inner;
    }
  }
}

// The checks of the inputs and options; returns w0, the level of T(n+1).
double checked_w0(const DecompositionMesh& H, const WField& w, const std::vector<double>& params,
                  const VolumeParamOptions& options) {
  const int n = H.num_surfaces;
  const int m = static_cast<int>(params.size());
  if (n < 1) throw bad_input("volume parameterization: H has no surface");
  if (options.strategy != 1 && options.strategy != 2)
    throw bad_input("volume parameterization: strategy must be 1 or 2, got " + std::to_string(options.strategy));
  if (m < 3 || params.front() != 0.0 || params.back() != 1.0)
    throw bad_input("volume parameterization: need at least 3 sample parameters from 0 to 1");
  if (!(options.theta >= 0.05 && options.theta <= 1.5))
    throw bad_input("volume parameterization: theta = " + std::to_string(options.theta) +
                    " is outside [0.05, 1.5] radians");
  const double inner = static_cast<double>(n - 1) / n;
  // Default: midway between Tn and M, and no lower than 0.75 (nearer to T1
  // the streamlines from the core spread more unevenly; measured on torus3).
  const double w0 = options.w0 < 0.0 ? std::max(0.75, 0.5 * (inner + 1.0)) : options.w0;
  if (!(w0 > inner && w0 < 1.0))
    throw bad_input("volume parameterization: w0 = " + std::to_string(w0) + " must lie in (" +
                    std::to_string(inner) + ", 1): T(n+1) between Tn and M");
  if (w.w.size() != H.tets.V.rows()) throw bad_input("volume parameterization: the w-field belongs to another mesh");
  return w0;
}

// M at (u, v) with its outward lean.
struct Frame {
  Eigen::Vector3d position, normal, lean;
  int triangle;
  Eigen::Vector3d bary;
};

// What every step reads: H's w-field and its probe, M's sheet and layout,
// the sample parameters and the options; and the tet hint threaded through
// every ray and streamline query in turn (consecutive queries are close).
struct VolumeContext {
  VolumeContext(const DecompositionMesh& H, const WField& w, const BaseLayout& layout,
                const std::vector<double>& params, const VolumeParamOptions& options, double w0)
      : layout(layout),
        params(params),
        options(options),
        n(H.num_surfaces),
        m(static_cast<int>(params.size())),
        inner(static_cast<double>(n - 1) / n),
        w0(w0),
        topo(build_tet_topology(H.tets.T, H.tets.V.rows())),
        grad(vertex_gradients(H.tets.V, H.tets.T, w.w)),
        probe(H.tets.V, H.tets.T, topo, w.w, grad),
        diag((H.tets.V.colwise().maxCoeff() - H.tets.V.colwise().minCoeff()).norm()),
        step(options.ray_step * diag),
        kappa(options.blend * narrowest_band(layout.domain)),
        cot_theta(1.0 / std::tan(options.theta)),
        sheet(layout.sheet, layout.uv),
        strategy1(options.strategy == 1),
        offset(2.0 * step) {
    if (strategy1) probe.set_ridge(1.0 - 1e-12);  // its streamlines start next to M
  }

  // The outward lean at (u, v): M's outward binormals of the domain sides
  // within kappa, weighted by (1 - d/kappa)^2 (1 on the boundary).
  Frame frame(const Eigen::Vector2d& uv) const {
    const SheetPoint sp = sheet.at(uv);
    Frame f{sp.position, sp.normal, Eigen::Vector3d::Zero(), sp.triangle, sp.bary};
    for (const DomainEdge& e : layout.domain_edges) {
      const double d = detail::distance_to_segment<2>(uv, e.a, e.b);
      if (d >= kappa) continue;
      Eigen::Vector3d b = e.outward.x() * sp.du + e.outward.y() * sp.dv;
      b -= b.dot(f.normal) * f.normal;
      if (b.norm() == 0.0) continue;
      const double beta = (1.0 - d / kappa) * (1.0 - d / kappa);
      f.lean += beta * b.normalized();
    }
    // At most unit length: at a convex corner the two sides add up, and the
    // rays would leave M at less than theta (too flat, the lid folds).
    if (f.lean.norm() > 1.0) f.lean.normalize();
    return f;
  }

  // The lid above (side = 1) or below (-1) M: straight along the leaning
  // direction to w = w0 (of the smooth w, FieldProbe::smooth_value).
  // Streamlines of -grad w from M would not cross, but near M's boundary
  // they all bend to the crest.
  Eigen::Vector3d ray(const Frame& f, double side) {
    const Eigen::Vector3d dir = (side * f.normal + cot_theta * f.lean).normalized();
    return core_ray(probe, "the lid's ray from M", f.position, dir, w0, step, 0.5 * diag, &hint);
  }

  // Strategy 1 starts its streamlines this far from M along D+ and D-
  // (w = 1 on M: the gradient there is two-sided).
  Eigen::Vector3d start_point(const Frame& f, double side) const {
    return Eigen::Vector3d(f.position + offset * (side * f.normal + cot_theta * f.lean).normalized());
  }

  const BaseLayout& layout;
  const std::vector<double>& params;
  const VolumeParamOptions& options;
  const int n, m;
  const double inner, w0;
  // Smoothed lids and crests must keep w above this: a tenth of the way
  // from Tn to T(n+1), so that they stay clear of Tn.
  double outer_band() const { return inner + 0.1 * (w0 - inner); }
  const TetTopology topo;
  const Eigen::MatrixXd grad;
  FieldProbe probe;
  const double diag, step, kappa, cot_theta;
  const SheetSampler sheet;
  const bool strategy1;
  const double offset;
  int hint = -1;
};

// Per rectangle: M, the top and the bottom of the core on an m x m grid.
struct RectGrid {
  Grid2 base, top, bottom;  // top, bottom: the lids (strategy 2) or the streamline starts (strategy 1)
  Grid2 lean;               // the frame's lean at each sample (the crest's binormal on M's boundary)
};

// Every point inside H with w at least `level` (w = 1 on M, 0 on T1).
bool within_band(VolumeContext& ctx, const Grid2& points, double level) {
  for (const Eigen::Vector3d& p : points) {
    double w = ctx.probe.value(p, &ctx.hint);
    if (std::isnan(w)) ctx.hint = -1, w = ctx.probe.value(p, &ctx.hint);  // the walk from the hint left H
    if (std::isnan(w) || w < level) return false;
  }
  return true;
}

// Which corners of rectangle R (grid corners (0, 0), (m - 1, 0), (0, m - 1),
// (m - 1, m - 1)) lie on the domain's boundary, kept within `share`
// (VolumeParamOptions::corner_share).
KeptCorners boundary_corners_of(const BaseLayout& layout, const Eigen::Vector4d& R, double share) {
  const double eps = 1e-9 * (layout.domain.width + layout.domain.height);
  const std::array<Eigen::Vector2d, 4> corners{{{R(0), R(1)}, {R(2), R(1)}, {R(0), R(3)}, {R(2), R(3)}}};
  KeptCorners kept;
  kept.end_share = share;
  for (std::size_t c = 0; c < 4; ++c)
    for (const DomainEdge& e : layout.domain_edges)
      if (detail::distance_to_segment<2>(corners[c], e.a, e.b) < eps) kept.corners[c] = true;
  return kept;
}

// M and the lids of every rectangle smoothed onto polynomials, unless a
// smoothed surface leaves its band of w: M the core (w >= w0), the lids the
// layer between T(n+1) and Tn (ctx.outer_band()). On a solid a few tets
// thick (a blade) the polynomials' bumps are thicker than the solid, and the
// rectangles are then kept as sampled (all of them: neighbours must match).
void smooth_rectangles(VolumeContext& ctx, std::vector<RectGrid>& rect) {
  const int degree = ctx.options.surface_degree;
  std::vector<RectGrid> smooth = rect;
  for (std::size_t r = 0; r < smooth.size(); ++r) {
    RectGrid& g = smooth[r];
    const KeptCorners kept = boundary_corners_of(ctx.layout, ctx.layout.rectangles[r], ctx.options.corner_share);
    for (Grid2* s : {&g.base, &g.top, &g.bottom}) *s = smooth_grid(*s, ctx.params, degree, kept);
    if (!within_band(ctx, g.base, ctx.w0) || !within_band(ctx, g.top, ctx.outer_band()) ||
        !within_band(ctx, g.bottom, ctx.outer_band()))
      return;
  }
  rect = std::move(smooth);
}

// A rectangle's side in the domain: which lid, along u (0) or v (1), the
// fixed coordinate, and the range. Rectangles meet side to side, so two
// that share a side give it the same key.
using SideKey = std::tuple<int, int, double, double, double>;

SideKey side_key(const Eigen::Vector4d& R, int lid, int side) {
  switch (side) {
    case 0: return {lid, 0, R(1), R(0), R(2)};
    case 1: return {lid, 0, R(3), R(0), R(2)};
    case 2: return {lid, 1, R(0), R(1), R(3)};
    default: return {lid, 1, R(2), R(1), R(3)};
  }
}

// The core's cells folded under the lids counted, and with
// lid_relax_rings > 0 each lid re-aimed where they fold (lid_relax.h):
// every side once, copied into the rectangles that share it, then each
// rectangle's inside.
void relax_lids(VolumeContext& ctx, std::vector<RectGrid>& rect, VolumeParam& out) {
  const int m = ctx.m;
  if (ctx.options.lid_relax_rings == 0) {
    for (const RectGrid& g : rect)
      for (const Grid2* lid : {&g.top, &g.bottom}) out.lid_folded_before += count_folded_lid_cells(g.base, *lid, m);
    out.lid_folded_after = out.lid_folded_before;
    return;
  }
  const LidRay ray = [&](const Eigen::Vector3d& from, const Eigen::Vector3d& dir) -> std::optional<Eigen::Vector3d> {
    try {
      return ctx.probe.ray_to_level(from, dir, ctx.w0, ctx.step, 0.5 * ctx.diag, &ctx.hint);
    } catch (const Error& e) {
      if (e.kind() != ErrorKind::CheckFailed) throw;
      return std::nullopt;
    }
  };
  std::map<SideKey, Grid2> sides;
  for (std::size_t r = 0; r < rect.size(); ++r)
    for (int l = 0; l < 2; ++l) {
      const Grid2& base = rect[r].base;
      Grid2& lid = l == 0 ? rect[r].top : rect[r].bottom;
      out.lid_folded_before += count_folded_lid_cells(base, lid, m);
      for (int s = 0; s < 4; ++s) {
        const std::vector<std::size_t> at = lid_side_indices(m, s);
        const SideKey key = side_key(ctx.layout.rectangles[r], l, s);
        auto it = sides.find(key);
        if (it == sides.end()) {
          relax_lid_side(base, lid, at, ray);
          Grid2 row;
          for (std::size_t q : at) row.push_back(lid[q]);
          sides.emplace(key, std::move(row));
        } else {
          for (std::size_t k = 0; k < at.size(); ++k) lid[at[k]] = it->second[k];
        }
      }
      out.lid_folded_after += relax_lid_inside(base, lid, m, ray, ctx.options.lid_relax_rings);
    }
}

std::vector<RectGrid> sample_rectangles(VolumeContext& ctx) {
  const std::vector<double>& params = ctx.params;
  const int m = ctx.m;
  std::vector<RectGrid> rect(ctx.layout.rectangles.size());
  for (std::size_t r = 0; r < ctx.layout.rectangles.size(); ++r) {
    const Eigen::Vector4d& R = ctx.layout.rectangles[r];
    RectGrid& g = rect[r];
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        const Eigen::Vector2d uv((1.0 - params[i]) * R(0) + params[i] * R(2), (1.0 - params[j]) * R(1) + params[j] * R(3));
        const Frame f = ctx.frame(uv);
        g.lean.push_back(f.lean);
        g.base.push_back(f.position);
        g.top.push_back(ctx.strategy1 ? ctx.start_point(f, 1.0) : ctx.ray(f, 1.0));
        g.bottom.push_back(ctx.strategy1 ? ctx.start_point(f, -1.0) : ctx.ray(f, -1.0));
      }
  }
  // The sampled M and lids are piecewise linear with bumps a few samples
  // wide, which the shell's streamlines carry out to T1 and the fit cannot
  // follow. T(n+1) need not be exactly w = w0: only between Tn and M.
  if (!ctx.strategy1 && ctx.options.surface_degree > 0) smooth_rectangles(ctx, rect);
  return rect;
}

// Grid index of position k along side s of a rectangle (box_sides order).
int side_index(int m, int s, int k) {
  switch (s) {
    case 0: return k;                // bottom: j = 0
    case 1: return (m - 1) + m * k;  // right: i = m - 1
    case 2: return k + m * (m - 1);  // top: j = m - 1
    default: return m * k;           // left: i = 0
  }
}

// The faces the shell grows from, each m x m: the outer faces of the core
// (strategy 2), or M's two sides and the collapsed crest fans (strategy 1)
// with the points the streamlines start from.
struct ShellBase {
  Grid2 face, start;
  bool collapsed = false;  // the face is a curve (strategy 1 crest)
  // Strategy 2 crest faces: the shell is ruled across the face's second
  // direction (j), between the exact streamline surfaces from its two long
  // edges (S+ or S-, and the one from P2), its rows on T1 and the Ti put
  // back onto them. The face is thin, and its own streamlines near P2 run
  // along the ridge of w in M's plane, where the discrete gradient barely
  // pulls them apart: they bunch up (a sample spacing drops to a tenth of
  // its neighbours') and the fit folds.
  bool ruled = false;
  // Strategy 1 crest fans: ruled in two halves, through the streamline
  // from this row (along M's binormal) as well; -1: no middle row.
  int ruled_mid = -1;
  // Sides of a lid face (DomainSide order) on M's boundary: shared with a
  // ruled crest face, whose two long edges cannot be spread alike (the P2
  // edge is shared with the other crest face), so they are not spread.
  std::array<bool, 4> fixed_sides{};
  ShellFaceOrigin origin;
};

void add_block(VolumeParam& out, int m, BlockKind kind, int source, int layer, int material, Eigen::MatrixXd samples,
               int t1_side) {
  SampledBlock b;
  b.kind = kind;
  b.source = source;
  b.layer = layer;
  b.material = material;
  b.samples = std::move(samples);
  if (t1_side >= 0) b.side_label[static_cast<std::size_t>(t1_side)] = 0;
  orient_block(b, m);
  out.folded_cells += b.folded;
  out.blocks.push_back(std::move(b));
}

// Strategy 1: the shell grows from both sides of M and from a fan per crest
// segment, from D+ through the binormal (the middle row) to D-: only those
// three rows are traced, the others are ruled between them.
void add_strategy1_bases(const VolumeContext& ctx, const std::vector<RectGrid>& rect, std::vector<ShellBase>& faces) {
  const int m = ctx.m;
  const int mid = (m - 1) / 2;
  for (std::size_t r = 0; r < rect.size(); ++r) {
    const ShellFaceOrigin over{static_cast<int>(r), -1};
    faces.push_back({rect[r].base, rect[r].top, false, false, -1, {}, over});
    faces.push_back({rect[r].base, rect[r].bottom, false, false, -1, {}, over});
  }
  for (std::size_t c = 0; c < ctx.layout.crests.size(); ++c) {
    const CrestSegment& seg = ctx.layout.crests[c];
    const RectGrid& g = rect[static_cast<std::size_t>(seg.rectangle)];
    ShellBase fan;
    fan.collapsed = true;
    fan.ruled = true;
    fan.ruled_mid = mid;
    fan.origin = {seg.rectangle, static_cast<int>(c)};
    for (int j = 0; j < m; ++j)
      for (int k = 0; k < m; ++k) {
        const int q = side_index(m, seg.side, k);
        fan.face.push_back(g.base[q]);
        fan.start.push_back(j == mid ? Eigen::Vector3d(g.base[q] + ctx.offset * g.lean[q].normalized())
                                     : lerp(g.top[q], g.bottom[q], ctx.params[j]));
      }
    faces.push_back(std::move(fan));
  }
}

// Strategy 2: per rectangle a block ruled from M to its top lid and one to
// its bottom lid; the lids are faces the shell grows from.
void add_core_blocks(const VolumeContext& ctx, const std::vector<RectGrid>& rect, VolumeParam& out,
                     std::vector<ShellBase>& faces) {
  const int m = ctx.m;
  for (std::size_t r = 0; r < rect.size(); ++r) {
    for (const bool top : {true, false}) {
      Eigen::MatrixXd s(m * m * m, 3);
      const Grid2& lid = top ? rect[r].top : rect[r].bottom;
      for (int k = 0; k < m; ++k)
        for (int q = 0; q < m * m; ++q) s.row(q + m * m * k) = lerp(rect[r].base[q], lid[q], ctx.params[k]).transpose();
      add_block(out, m, top ? BlockKind::CoreTop : BlockKind::CoreBottom, static_cast<int>(r), 0, ctx.n - 1,
                std::move(s), -1);
      ShellBase face{lid, lid, false, false, -1, {}, {static_cast<int>(r), -1}};
      for (const CrestSegment& seg : ctx.layout.crests)
        if (seg.rectangle == static_cast<int>(r)) face.fixed_sides[static_cast<std::size_t>(seg.side)] = true;
      faces.push_back(std::move(face));
    }
  }
}

// The corners of a crest's cross-section along its segment: P0 on M's
// boundary, P3 and P1 the top and bottom lids' edges, P2 out along M's binormal.
struct CrestProfile {
  Grid2 P0, P1, P2, P3;
};

CrestProfile crest_profile(VolumeContext& ctx, const CrestSegment& seg, const RectGrid& g) {
  const int m = ctx.m;
  CrestProfile c{Grid2(m), Grid2(m), Grid2(m), Grid2(m)};
  for (int k = 0; k < m; ++k) {
    const int q = side_index(m, seg.side, k);
    c.P0[k] = g.base[q];
    c.P3[k] = g.top[q];
    c.P1[k] = g.bottom[q];
    if (g.lean[q].norm() == 0.0) throw internal_error("volume parameterization: no binormal on M's boundary");
    // P2 out along the binormal, so that the crest's cross-section is
    // close to a kite with right angles at P3 and P1 (crest_reach = 1),
    // but no farther than the level halfway between Tn and T(n+1).
    const Eigen::Vector3d b = g.lean[q].normalized();
    const double r3 = 0.5 * ((c.P3[k] - c.P0[k]).norm() + (c.P1[k] - c.P0[k]).norm());
    const double kite = ctx.options.crest_reach * r3 / std::cos(ctx.options.theta);
    const Eigen::Vector3d limit =
        core_ray(ctx.probe, "the crest's ray along M's binormal", c.P0[k], b, 0.5 * (ctx.inner + ctx.w0), ctx.step, 0.5 * ctx.diag, &ctx.hint);
    c.P2[k] = c.P0[k] + std::min(kite, (limit - c.P0[k]).norm()) * b;
  }
  // The lids' edges P3 and P1 are smooth; P2 follows the ray limits, which
  // are not (the crest is thin: a bump folds it).
  // Kept as sampled where the smoothed curve would leave the layer beyond
  // T(n+1) (a thin solid's crest is thinner than the polynomial's bumps).
  if (ctx.options.surface_degree > 0) {
    const Grid2 smooth = smooth_polyline(c.P2, ctx.params, ctx.options.surface_degree);
    if (within_band(ctx, smooth, ctx.outer_band())) c.P2 = smooth;
  }
  return c;
}

// Strategy 2: per crest segment a block bilinear in its cross-section
// (P0, P3, P2, P1); its two outer faces (P3-P2 and P1-P2) are faces the
// shell grows from, ruled across.
void add_crest_blocks(VolumeContext& ctx, const std::vector<RectGrid>& rect, VolumeParam& out,
                      std::vector<ShellBase>& faces) {
  const int m = ctx.m;
  const std::vector<double>& params = ctx.params;
  for (std::size_t c = 0; c < ctx.layout.crests.size(); ++c) {
    const CrestSegment& seg = ctx.layout.crests[c];
    const CrestProfile P = crest_profile(ctx, seg, rect[static_cast<std::size_t>(seg.rectangle)]);
    Eigen::MatrixXd s(m * m * m, 3);
    Grid2 upper(m * m), lower(m * m);
    for (int b = 0; b < m; ++b)
      for (int a = 0; a < m; ++a)
        for (int k = 0; k < m; ++k)
          s.row(k + m * (a + m * b)) = ((1.0 - params[b]) * lerp(P.P0[k], P.P3[k], params[a]) +
                                        params[b] * lerp(P.P1[k], P.P2[k], params[a]))
                                           .transpose();
    for (int j = 0; j < m; ++j)
      for (int k = 0; k < m; ++k) {
        upper[k + m * j] = lerp(P.P3[k], P.P2[k], params[j]);  // the a = 1 face, (tau, b)
        lower[k + m * j] = lerp(P.P1[k], P.P2[k], params[j]);  // the b = 1 face, (tau, a)
      }
    add_block(out, m, BlockKind::Crest, static_cast<int>(c), 0, ctx.n - 1, std::move(s), -1);
    const ShellFaceOrigin over{seg.rectangle, static_cast<int>(c)};
    faces.push_back({upper, upper, false, true, -1, {}, over});  // ruled
    faces.push_back({lower, lower, false, true, -1, {}, over});
  }
}

// A ruled face needs the columns of its rows j = 0, m - 1 (and the middle one) only.
bool traced(const ShellBase& face, int m, int q) {
  const int j = q / m;
  return !face.ruled || j == 0 || j == m - 1 || j == face.ruled_mid;
}

// Depth in the shell (0 on the core face, 1 on T1) of sample k of a layer's
// block (layer 1 outermost): the same number for the samples two layers share.
double shell_depth(const VolumeContext& ctx, int layer, int k) {
  return 1.0 - (static_cast<double>(layer - 1) + ctx.params[static_cast<std::size_t>(k)]) / ctx.n;
}

// The streamlines of -grad w from the face's traced samples; with strategy 2
// spread where they fan out (shell_columns.h).
ShellColumns face_columns(VolumeContext& ctx, const ShellBase& face) {
  std::vector<double> depths;
  for (int layer = 1; layer <= ctx.n; ++layer)
    for (int k = 0; k < ctx.m; ++k) depths.push_back(shell_depth(ctx, layer, k));
  std::sort(depths.begin(), depths.end());
  depths.erase(std::unique(depths.begin(), depths.end()), depths.end());
  const int m = ctx.m;
  SpreadOptions spread;
  spread.chord_deviation = ctx.options.spread_deviation * ctx.diag;
  return ShellColumns(ctx.probe, ctx.options.stream_step * ctx.diag, ctx.params, face.start,
                      [&](int q) { return traced(face, m, q); }, face.fixed_sides,
                      !ctx.strategy1 && !face.collapsed && !face.ruled, depths, spread);
}

// The samples of a face's shell block in layer (1..n): the columns cut at
// the layer's w-levels, w in [(layer - 1)/n, layer/n] (the innermost one up
// to the face itself); the untraced rows of a ruled face are left for rule_rows.
Eigen::MatrixXd layer_samples(const VolumeContext& ctx, const ShellBase& face, const ShellColumns& cols, int layer) {
  const int m = ctx.m, n = ctx.n;
  const double lo = static_cast<double>(layer - 1) / n;
  Eigen::MatrixXd s(m * m * m, 3);
  for (int q = 0; q < m * m; ++q) {
    if (!traced(face, m, q)) continue;
    for (int k = 0; k < m; ++k) {
      const StreamlineColumn& col = cols.at(q, shell_depth(ctx, layer, k));
      // Arc lengths of the layer's outer (w = lo) and inner ends; the inner
      // end of the innermost layer is the core face itself (arc 0).
      const double s_lo = col.arc_at_level(lo);
      const double s_hi = layer == n ? 0.0 : col.arc_at_level(static_cast<double>(layer) / n);
      Eigen::Vector3d x;
      if (k == 0) x = col.at_arc(s_lo);
      else if (k == m - 1) x = layer == n ? face.face[static_cast<std::size_t>(q)] : col.at_arc(s_hi);
      else x = col.at_arc(s_lo + ctx.params[static_cast<std::size_t>(k)] * (s_hi - s_lo));
      s.row(q + m * m * k) = x.transpose();
    }
  }
  return s;
}

// A spread face's layer-1 block: its side on T1 (k = 0) relaxed on T1
// (surface_grid_relax.h), the move carried into the block along each
// column, whole on T1 and fading to none at the layer's inner side (a
// smoothstep in the depth parameter), so that every other side keeps its
// samples. Counts the side's folded cells on T1 before and after in out.
void relax_t1_side(const VolumeContext& ctx, Eigen::MatrixXd& s, const SurfaceProjector& t1, VolumeParam& out) {
  const int m = ctx.m;
  std::vector<Eigen::Vector3d> side(static_cast<std::size_t>(m * m));
  for (int q = 0; q < m * m; ++q) side[static_cast<std::size_t>(q)] = s.row(q).transpose();
  const SurfaceGridRelaxResult r = relax_grid_on_surface(side, m, t1, ctx.options.t1_relax);
  for (int q = 0; q < m * m; ++q) {
    const Eigen::Vector3d move = r.grid[static_cast<std::size_t>(q)] - side[static_cast<std::size_t>(q)];
    if (move.squaredNorm() == 0.0) continue;
    for (int k = 0; k + 1 < m; ++k) {
      const double fade = 1.0 - smoothstep(ctx.params[static_cast<std::size_t>(k)]);
      s.row(q + m * m * k) += fade * move.transpose();
    }
  }
  out.t1_folded_before += r.folded_before;
  out.t1_folded_after += r.folded_after;
}

// Shell: streamlines from every sample of every face, one block per face and
// material layer; the layer-1 block's side w0 (side 4) lies on T1.
void add_shell_blocks(VolumeContext& ctx, const DecompositionMesh& H, const std::vector<ShellBase>& faces,
                      VolumeParam& out) {
  const int m = ctx.m, n = ctx.n;
  const std::vector<SurfaceProjector> surface = surface_projectors(H);  // T1..Tn
  Progress progress("streamlines", faces.size(), ctx.options.progress);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const ShellBase& face = faces[f];
    const ShellColumns cols = face_columns(ctx, face);
    out.streamlines += cols.streamlines();
    if (cols.spread()) ++out.spread_faces;
    for (int layer = 1; layer <= n; ++layer) {
      Eigen::MatrixXd s = layer_samples(ctx, face, cols, layer);
      if (layer == 1 && cols.spread() && ctx.options.t1_relax.rounds > 0) relax_t1_side(ctx, s, surface[0], out);
      if (face.ruled) {
        rule_rows(s, m, ctx.params, face.ruled_mid);
        const SurfaceProjector* inner = layer < n ? &surface[static_cast<std::size_t>(layer)] : nullptr;
        put_back_on_levels(s, m, ctx.params, face.ruled_mid, surface[static_cast<std::size_t>(layer - 1)], inner);
      }
      add_block(out, m, BlockKind::Shell, static_cast<int>(f), layer, layer - 1, std::move(s), layer == 1 ? 4 : -1);
      if (layer == n && face.collapsed) out.blocks.back().collapsed[5] = true;
    }
    progress.update(f + 1);
  }
  progress.finish();
}

}  // namespace

// The majority, not the cells at the centre: a fold through the centre
// turned a whole block inside out (a pelvis shell block: 3,639 of 4,096 cells).
void orient_block(SampledBlock& b, int m) {
  b.folded = count_folded(b, m);
  if (2 * b.folded <= (m - 1) * (m - 1) * (m - 1)) return;
  Eigen::MatrixXd s = b.samples;
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) s.row(i + m * (j + m * k)) = b.samples.row((m - 1 - i) + m * (j + m * k));
  b.samples = s;
  b.mirrored = true;
  std::swap(b.side_label[0], b.side_label[1]);
  std::swap(b.collapsed[0], b.collapsed[1]);
  b.folded = count_folded(b, m);
}

VolumeParam build_volume_param(const DecompositionMesh& H, const WField& w, const BaseLayout& layout,
                               const std::vector<double>& params, const VolumeParamOptions& options) {
  VolumeParam out;
  out.w0 = checked_w0(H, w, params, options);
  out.params = params;
  out.layers = H.num_surfaces;
  VolumeContext ctx(H, w, layout, params, options, out.w0);
  std::vector<RectGrid> rect = sample_rectangles(ctx);
  if (!ctx.strategy1) relax_lids(ctx, rect, out);
  std::vector<ShellBase> faces;
  if (ctx.strategy1) {
    add_strategy1_bases(ctx, rect, faces);
  } else {
    add_core_blocks(ctx, rect, out, faces);
    add_crest_blocks(ctx, rect, out, faces);
  }
  out.rectangles = static_cast<int>(layout.rectangles.size());
  out.crests = static_cast<int>(layout.crests.size());
  out.core_faces = static_cast<int>(faces.size());
  for (const ShellBase& f : faces) out.face_origins.push_back(f.origin);
  add_shell_blocks(ctx, H, faces, out);
  return out;
}

GridLines lines_halving_faces(const BaseLayout& layout, const VolumeParam& vp,
                              const std::vector<FaceDirection>& faces) {
  GridLines lines;
  for (const FaceDirection& fd : faces) {
    const ShellFaceOrigin& o = vp.face_origins.at(static_cast<std::size_t>(fd.face));
    const Eigen::Vector4d& r = layout.rectangles.at(static_cast<std::size_t>(o.rectangle));
    bool along_u = fd.direction == 0;
    if (o.crest >= 0) {
      if (fd.direction != 0) continue;
      const CrestSegment& seg = layout.crests.at(static_cast<std::size_t>(o.crest));
      along_u = std::abs(seg.b.y() - seg.a.y()) < std::abs(seg.b.x() - seg.a.x());
    }
    if (along_u) lines.u.push_back(0.5 * (r(0) + r(2)));
    else lines.v.push_back(0.5 * (r(1) + r(3)));
  }
  return lines;
}

}  // namespace igaprep::param
