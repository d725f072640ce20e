#include <set>

#include <Eigen/Core>

#include "block_coverage.h"
#include "igaprep/param/blocks_tet_mesh.h"
#include "igaprep/pipeline/volume.h"
#include "stage_timer.h"
#include "igaprep/core/text.h"

namespace igaprep::pipeline {
namespace {

// Every block's sample points, with the block index.
mesh::VtuMesh samples_vtu(const param::VolumeParam& vp) {
  Eigen::Index total = 0;
  for (const auto& b : vp.blocks) total += b.samples.rows();
  mesh::VtuMesh v;
  v.points.resize(total, 3);
  Eigen::VectorXi block(total);
  Eigen::Index row = 0;
  for (std::size_t i = 0; i < vp.blocks.size(); ++i) {
    const auto& S = vp.blocks[i].samples;
    v.points.middleRows(row, S.rows()) = S;
    block.segment(row, S.rows()).setConstant(static_cast<int>(i));
    for (Eigen::Index k = 0; k < S.rows(); ++k) v.add_cell(mesh::kVtuVertex, {static_cast<int>(row + k)});
    row += S.rows();
  }
  v.add_point_data("block", block);
  return v;
}

// Every block's grid thinned to at most 8 cells per direction (the same
// samples on both sides of a shared face), or ring2's mesh would have 3
// million tets.
std::vector<param::SampledBlock> thinned_blocks(const param::VolumeParam& vp) {
  const int m = static_cast<int>(vp.params.size());
  int stride = 1;
  while ((m - 1) % (2 * stride) == 0 && (m - 1) / stride > 8) stride *= 2;
  const int mc = (m - 1) / stride + 1;
  std::vector<param::SampledBlock> coarse = vp.blocks;
  for (std::size_t b = 0; b < coarse.size(); ++b) {
    Eigen::MatrixXd s(mc * mc * mc, 3);
    for (int k = 0; k < mc; ++k)
      for (int j = 0; j < mc; ++j)
        for (int i = 0; i < mc; ++i)
          s.row(i + mc * (j + mc * k)) = vp.blocks[b].samples.row(stride * i + m * (stride * j + m * stride * k));
    coarse[b].samples = std::move(s);
  }
  return coarse;
}

// The blocks as one conforming tet mesh (blocks_tet_mesh.h): the
// decomposition surfaces are its faces.
void offer_blocks_mesh(const param::VolumeParam& vp, double diag, Observer& observer) {
  if (!observer.wants_intermediate("decomposition_blocks") &&
      !observer.wants_intermediate("decomposition_blocks_faces"))
    return;
  const param::BlocksTetMesh bm = param::blocks_tet_mesh(thinned_blocks(vp), 1e-9 * diag);
  offer_intermediate(observer, "decomposition_blocks", [&] {
    mesh::VtuMesh v = mesh::vtu_tets(bm.tets);
    v.add_cell_data("block", bm.block);
    return v;
  });
  offer_intermediate(observer, "decomposition_blocks_faces", [&] { return mesh::vtu_marked_faces(bm.tets); });
}

// The share of the check's fidelity limit a bulge of T1 between two samples
// may reach when the param stage spreads the faces a second time, so that
// the fit has room left within the limit.
constexpr double kBulgeShareOfFidelityLimit = 0.4;
// The spread samples are kept only if they come this much nearer T1: where
// the samples miss a whole part of it (the hand's fingers) spreading cannot
// bring it back, and its denser fans cost the fit (docs/decomposition.md,
// "Bulges between samples").
constexpr double kKeptBelowShareOfGap = 0.75;

// "spread_deviation": "auto". Where the blocks' sides labelled T1 miss T1
// by more than the fidelity limit, the fit cannot reach it: vp is built
// again with the shell faces spread where T1 bulges between samples, and
// kept (with the options that made it) if its sides come markedly nearer
// T1. Returns a line for the stage's summary (empty when nothing was done).
std::string spread_bulges_if_needed(const Case& c, const Decomposition& d, const std::vector<double>& params,
                                    param::VolumeParamOptions& options, const mesh::TriMesh& t1,
                                    param::VolumeParam& vp) {
  const double gap = t1_sample_gap(vp, t1);
  if (!(gap > c.check.fidelity_limit)) return {};
  param::VolumeParamOptions spread = options;
  spread.spread_deviation = kBulgeShareOfFidelityLimit * c.check.fidelity_limit;
  param::VolumeParam again = param::build_volume_param(d.H, d.w, d.layout, params, spread);
  const double gap_again = t1_sample_gap(again, t1);
  const bool kept = gap_again < kKeptBelowShareOfGap * gap;
  if (kept) {
    vp = std::move(again);
    options = spread;
  }
  return text("the samples missed T1 by %.3f %% of the diagonal (fidelity limit %.3f %%): spread where T1 bulges "
              "between samples by more than %.3f %% ('decomposition.spread_deviation' %g): %.3f %%, %s",
              100.0 * gap, 100.0 * c.check.fidelity_limit, 100.0 * spread.spread_deviation, spread.spread_deviation,
              100.0 * gap_again, kept ? "kept" : "not kept");
}

// "decomposition.cover_rounds". Where the blocks' sides on T1 still miss it
// by more than the fidelity limit (a part of T1 reached through too few
// samples: a kitten's ear spanned by cells 3 % of the diagonal wide), the
// rectangles under the shell faces nearest the missed vertices are halved,
// so those faces' shells get twice the streamlines, and vp is built again;
// kept when its sides come markedly nearer T1, repeated while they do.
// Returns a line for the stage's summary (empty when nothing was done).
std::string halve_rectangles_if_needed(const Case& c, const Decomposition& d, const std::vector<double>& params,
                                       const param::VolumeParamOptions& options, const mesh::TriMesh& t1,
                                       param::VolumeParam& vp) {
  std::string note;
  param::BaseLayout layout = d.layout;
  double gap = t1_sample_gap(vp, t1);
  for (int round = 0; round < c.cover_rounds && gap > c.check.fidelity_limit; ++round) {
    const std::vector<param::FaceDirection> faces = faces_missing_t1(vp, t1, c.check.fidelity_limit);
    if (faces.empty()) break;
    std::set<int> distinct;
    for (const param::FaceDirection& f : faces) distinct.insert(f.face);
    param::BaseLayout finer = param::with_more_lines(layout, param::lines_halving_faces(layout, vp, faces));
    param::VolumeParam again = param::build_volume_param(d.H, d.w, finer, params, options);
    const double gap_again = t1_sample_gap(again, t1);
    const bool kept = gap_again < kKeptBelowShareOfGap * gap;
    note += text("%sthe samples missed T1 by %.3f %% of the diagonal next to %zu shell faces: their rectangles "
                 "halved ('decomposition.cover_rounds' %d), %zu -> %zu rectangles, %.3f %%, %d folded sample cells, %s",
                 note.empty() ? "" : "; ", 100.0 * gap, distinct.size(), c.cover_rounds, layout.rectangles.size(),
                 finer.rectangles.size(), 100.0 * gap_again, again.folded_cells, kept ? "kept" : "not kept");
    if (!kept) break;
    vp = std::move(again);
    layout = std::move(finer);
    gap = gap_again;
  }
  return note;
}

}  // namespace

Decomposition decompose_stage(const Case& c, const Surfaces& surfaces, const param::BaseSurface& base,
                              Observer& observer) {
  StageTimer timer;
  Decomposition d;
  d.H = param::decomposition_mesh(surfaces.meshes, base.m.mesh, c.tetmesh);
  d.w = param::w_field(d.H);
  d.layout = param::base_layout(base.m, c.base.max_aspect);
  d.diagonal = (d.H.tets.V.colwise().maxCoeff() - d.H.tets.V.colwise().minCoeff()).norm();
  StageSummary s{"decompose", timer.seconds(),
                 text("tet mesh with M inside (H): %lld vertices, %lld tets; field w (0 on the surface, 1 on M): %zu interior extrema "
                      "(%d values flattened); M's layout: %zu rectangles, %zu boundary segments",
                      static_cast<long long>(d.H.tets.V.rows()), static_cast<long long>(d.H.tets.T.rows()),
                      d.w.extrema.size(), d.w.flattened, d.layout.rectangles.size(), d.layout.crests.size()),
                 {}};
  observer.stage_finished(s);
  offer_intermediate(observer, "decomposition_w", [&] {
    mesh::VtuMesh v = mesh::vtu_tets(d.H.tets);
    v.add_point_data("w", d.w.w);
    return v;
  });
  return d;
}

param::VolumeParam param_stage(const Case& c, const Surfaces& surfaces, const Decomposition& d, Observer& observer) {
  StageTimer timer;
  param::VolumeParamOptions options = c.volume;
  options.progress = progress_to(observer);
  const std::vector<double> params = spline::block_sample_params(c.fit);
  param::VolumeParam vp = param::build_volume_param(d.H, d.w, d.layout, params, options);
  std::string spread_note;
  if (c.auto_spread_deviation && c.volume.strategy == 2 && !surfaces.inputs.empty()) {
    spread_note = spread_bulges_if_needed(c, d, params, options, surfaces.inputs.front(), vp);
  }
  std::string cover_note;
  if (c.cover_rounds > 0 && !surfaces.inputs.empty())
    cover_note = halve_rectangles_if_needed(c, d, params, options, surfaces.inputs.front(), vp);
  StageSummary s{"param", timer.seconds(),
                 text("strategy %d, core inside w = %.3f (w0): %zu blocks (%d core faces x %d layers + core), %d streamlines "
                      "(%d faces spread; their cells folded on T1 %d -> %d), core cells folded under the lids %d -> %d, "
                      "%d folded sample cells",
                      c.volume.strategy, vp.w0, vp.blocks.size(), vp.core_faces, vp.layers, vp.streamlines,
                      vp.spread_faces, vp.t1_folded_before, vp.t1_folded_after, vp.lid_folded_before,
                      vp.lid_folded_after, vp.folded_cells),
                 {}};
  if (vp.folded_cells > 0) {
    std::string line = "folded sample cells:";
    for (std::size_t i = 0; i < vp.blocks.size(); ++i)
      if (vp.blocks[i].folded > 0)
        line += text(" block %zu (%s %d, layer %d): %d;", i, param::to_string(vp.blocks[i].kind), vp.blocks[i].source,
                     vp.blocks[i].layer, vp.blocks[i].folded);
    s.details.push_back(line);
  }
  if (!spread_note.empty()) s.details.push_back(spread_note);
  if (!cover_note.empty()) s.details.push_back(cover_note);
  for (std::string& line : block_coverage_findings(vp, surfaces, c.check)) s.details.push_back(std::move(line));
  s.seconds = timer.seconds();
  observer.stage_finished(s);
  offer_intermediate(observer, "decomposition_samples", [&] { return samples_vtu(vp); });
  offer_blocks_mesh(vp, d.diagonal, observer);
  return vp;
}

}  // namespace igaprep::pipeline
