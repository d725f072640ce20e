#include "stage_volume.h"

#include <cstdio>
#include <filesystem>

#include "igaprep/mesh/write_vtu.h"
#include "igaprep/param/base_layout.h"
#include "igaprep/param/blocks_tet_mesh.h"
#include "igaprep/param/decomposition_mesh.h"
#include "igaprep/param/inset_base.h"
#include "igaprep/param/sliding_uv.h"
#include "igaprep/param/surface_projector.h"
#include "igaprep/param/w_field.h"
#include "igaprep/spline/find_interfaces.h"
#include "igaprep/spline/optimize_jacobian.h"
#include "stage_timer.h"

namespace igaprep::cli {

namespace {

double diag_of(const Eigen::MatrixXd& V) { return (V.colwise().maxCoeff() - V.colwise().minCoeff()).norm(); }

// The blocks as one conforming tet mesh (blocks_tet_mesh.h): the
// decomposition surfaces are its faces. Every block's grid is thinned to at
// most 8 cells per direction (the same samples on both sides of a shared
// face), or ring2's mesh would have 3 million tets.
void write_blocks_mesh(const param::VolumeParam& vp, double diag, const std::string& dir) {
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
  const param::BlocksTetMesh bm = param::blocks_tet_mesh(coarse, 1e-9 * diag);
  mesh::VtuMesh v = mesh::vtu_tets(bm.tets);
  v.add_cell_data("block", bm.block);
  mesh::write_vtu((std::filesystem::path(dir) / "decomposition_blocks.vtu").string(), v);
  mesh::write_vtu((std::filesystem::path(dir) / "decomposition_blocks_faces.vtu").string(), mesh::vtu_marked_faces(bm.tets));
  std::printf("           blocks as one tet mesh (%d cells per block direction): %lld tets, %d merged points, %d "
              "non-positive, %d open faces, %d non-manifold faces; wrote %s/decomposition_blocks*.vtu\n",
              mc - 1, static_cast<long long>(bm.tets.T.rows()), bm.merged_points, bm.non_positive_tets, bm.open_faces,
              bm.nonmanifold_faces, dir.c_str());
}

// Moves the control points where the sampled scaled Jacobian is below the
// case's target (optimize_jacobian.h): those on T1 and the Ti slide along
// them, collapsed sides stay.
spline::JacobianOptimizationResult raise_jacobians(const CaseFile& c, const param::DecompositionMesh& H,
                                                   const param::VolumeParam& vp, spline::MultiPatch& mp) {
  StageTimer timer;
  const std::vector<param::SurfaceProjector> surfaces = param::surface_projectors(H);
  auto slide = [&](int surface, const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
    return surfaces.at(static_cast<std::size_t>(surface)).slide(from, to);
  };
  std::vector<std::pair<int, int>> fixed;
  for (std::size_t p = 0; p < vp.blocks.size(); ++p)
    for (int s = 0; s < 6; ++s)
      if (vp.blocks[p].collapsed[static_cast<std::size_t>(s)]) fixed.emplace_back(static_cast<int>(p), s + 1);
  const spline::JacobianOptimizationResult r = spline::optimize_jacobians(mp, slide, fixed, c.jacobian);
  std::printf("           Jacobians %.2f s: lowest sampled scaled Jacobian %.3f -> %.3f, points below %.2f: %d -> %d "
              "(%d control points moved, at most %.2g, %d sweeps, %d patches on dense samples)\n",
              timer.seconds(), r.min_before, r.min_after, c.jacobian.target, r.below_before, r.below_after,
              r.moved_points, r.max_move, r.sweeps, r.dense_patches);
  std::fflush(stdout);
  return r;
}

}  // namespace

VolumeStageResult run_volume_stages(const CaseFile& c, const CaseSurfaces& surfaces,
                                    const param::MidsurfaceResult& mid, const std::string& dir, bool keep_intermediate) {
  namespace fs = std::filesystem;
  const int n = static_cast<int>(surfaces.meshes.size());

  StageTimer t_decomp;
  // M is cut along iso-lines of a (u, v) whose sides slide (sliding_uv.h):
  // its corners are closer to right angles in 3D; the midsurface's (u, v)
  // stays when the sliding one folds.
  param::Polycube2D pc = mid.polycube;
  param::SlidingUv sliding;
  if (c.volume.sliding_uv) sliding = param::sliding_uv(mid.m0trim.mesh, pc);
  if (sliding.valid) pc.uv = sliding.uv;
  const param::InsetBase base = param::inset_base_surface(mid.m0trim.mesh, pc, c.volume.inset, c.volume.smoothing);

  if (keep_intermediate) {
    fs::create_directories(dir);
    mesh::VtuMesh v = mesh::vtu_triangles(base.mesh);
    v.add_point_data("u", Eigen::VectorXd(base.uv.col(0)));
    v.add_point_data("v", Eigen::VectorXd(base.uv.col(1)));
    mesh::write_vtu((fs::path(dir) / "decomposition_base.vtu").string(), v);
  }
  const param::DecompositionMesh H = param::decomposition_mesh(surfaces.meshes, base.mesh, c.tetmesh);
  const param::WField w = param::w_field(H);
  const param::BaseLayout layout = param::base_layout(base);
  char uv_note[160];
  if (!c.volume.sliding_uv)
    std::snprintf(uv_note, sizeof uv_note, "midsurface's (u, v)");
  else if (sliding.valid)
    std::snprintf(uv_note, sizeof uv_note, "sliding (u, v) (share of the sliding side positions >= %.2f)",
                  sliding.min_sliding_share);
  else
    std::snprintf(uv_note, sizeof uv_note, "midsurface's (u, v) (the sliding one: %s)", sliding.reason.c_str());
  std::printf("decompose  %7.2f s  M cut along the %s; H: %lld vertices, %lld tets; w: %zu interior extrema; "
              "M: %zu rectangles, %zu boundary segments\n",
              t_decomp.seconds(), uv_note, static_cast<long long>(H.tets.V.rows()), static_cast<long long>(H.tets.T.rows()),
              w.extrema.size(), layout.rectangles.size(), layout.crests.size());
  if (base.smoothing < c.volume.smoothing)
    std::printf("           M smoothed %d rounds, not %d (decomposition.smoothing): more made it intersect itself\n",
                base.smoothing, c.volume.smoothing);
  std::fflush(stdout);
  if (keep_intermediate) {
    fs::create_directories(dir);
    mesh::VtuMesh v = mesh::vtu_tets(H.tets);
    v.add_point_data("w", w.w);
    mesh::write_vtu((fs::path(dir) / "decomposition_w.vtu").string(), v);
  }

  const double decompose_seconds = t_decomp.seconds();
  StageTimer t_param;
  const spline::BlockFitOptions fit_options = c.fit;
  const param::VolumeParam vp =
      param::build_volume_param(H, w, layout, spline::block_sample_params(fit_options), c.volume);
  std::printf("param      %7.2f s  strategy %d, w0 = %.3f: %zu blocks (%d core faces x %d layers + core), %d "
              "streamlines, %d folded sample cells\n",
              t_param.seconds(), c.volume.strategy, vp.w0, vp.blocks.size(), vp.core_faces, vp.layers, vp.streamlines, vp.folded_cells);
  std::fflush(stdout);

  if (vp.folded_cells > 0) {
    std::printf("           folded sample cells:");
    for (std::size_t i = 0; i < vp.blocks.size(); ++i)
      if (vp.blocks[i].folded > 0)
        std::printf(" block %zu (%s %d, layer %d): %d;", i, param::to_string(vp.blocks[i].kind), vp.blocks[i].source,
                    vp.blocks[i].layer, vp.blocks[i].folded);
    std::printf("\n");
  }
  const double param_seconds = t_param.seconds();
  StageTimer t_fit;
  VolumeStageResult out;
  out.decompose_seconds = decompose_seconds;
  out.param_seconds = param_seconds;
  spline::MultiPatch& mp = out.model;
  for (const auto& s : c.surfaces) mp.labels.push_back(s.label);
  for (const auto& m : c.materials) mp.materials.push_back({m.name, m.young_modulus, m.poisson_ratio});
  if (keep_intermediate) {  // every block's sample points, with the block index
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
    mesh::write_vtu((fs::path(dir) / "decomposition_samples.vtu").string(), v);
    write_blocks_mesh(vp, diag_of(H.tets.V), dir);
  }
  for (const auto& b : vp.blocks) {
    spline::Patch p = spline::fit_block(b.samples, fit_options);
    p.material = b.material;
    mp.patches.push_back(std::move(p));
  }
  const Eigen::MatrixXd& V = H.tets.V;
  const double diag = diag_of(V);
  out.stitched = spline::stitch_control_points(mp, 1e-9 * diag, &out.max_stitch);
  spline::find_interfaces(mp, 1e-12 * diag);
  // Interfaces between materials lie on the Ti between them.
  for (auto& itf : mp.interfaces) {
    const int ma = mp.patches[itf.patch_a].material, mb = mp.patches[itf.patch_b].material;
    if (ma != mb) itf.surface = std::max(ma, mb);
  }
  std::vector<std::array<bool, 6>> on_interface(mp.patches.size(), std::array<bool, 6>{});
  for (const auto& itf : mp.interfaces) {
    on_interface[itf.patch_a][itf.side_a - 1] = true;
    on_interface[itf.patch_b][itf.side_b - 1] = true;
  }
  for (std::size_t p = 0; p < vp.blocks.size(); ++p)
    for (int s = 0; s < 6; ++s) {
      const int label = vp.blocks[p].side_label[s];
      if (label >= 0 && !on_interface[p][s]) mp.boundaries.push_back({static_cast<int>(p), s + 1, label});
      else if (!on_interface[p][s] && !vp.blocks[p].collapsed[s]) ++out.unmatched_sides;
    }
  std::printf("fit        %7.2f s  %zu patches, degree %d, %d elements per direction; %zu interfaces (%d stitched "
              "points, max move %.1e), %zu T1 sides, %d unmatched sides, %d layer(s)\n",
              t_fit.seconds(), mp.patches.size(), fit_options.degree, fit_options.elements, mp.interfaces.size(),
              out.stitched, out.max_stitch, mp.boundaries.size(), out.unmatched_sides, n);
  std::fflush(stdout);
  if (c.jacobian.target > 0.0) out.jacobians = raise_jacobians(c, H, vp, mp);
  out.fit_seconds = t_fit.seconds();
  return out;
}

}  // namespace igaprep::cli
