#include "igaprep/iga_check/surface_fit_pairs.h"
#include "igaprep/param/surface_projector.h"
#include "igaprep/pipeline/fit_retry.h"
#include "igaprep/pipeline/volume.h"
#include "igaprep/spline/block_fit.h"
#include "igaprep/spline/find_interfaces.h"
#include "igaprep/spline/label_sides.h"
#include "stage_timer.h"
#include "igaprep/core/text.h"

namespace igaprep::pipeline {
namespace {

// Each block fitted alone; stitching then makes shared side control points identical.
void fit_blocks(const Case& c, const param::VolumeParam& vp, spline::MultiPatch& mp) {
  for (const auto& s : c.surfaces) mp.labels.push_back(s.label);
  for (const auto& m : c.materials) mp.materials.push_back({m.name, m.young_modulus, m.poisson_ratio});
  for (const auto& b : vp.blocks) {
    spline::Patch p = spline::fit_block(b.samples, c.fit);
    p.material = b.material;
    mp.patches.push_back(std::move(p));
  }
}

int connect_and_label(const param::VolumeParam& vp, double diag, spline::MultiPatch& mp) {
  spline::find_interfaces(mp, 1e-12 * diag);
  std::vector<std::array<int, 6>> labels;
  std::vector<std::array<bool, 6>> collapsed;
  for (const auto& b : vp.blocks) {
    labels.push_back(b.side_label);
    collapsed.push_back(b.collapsed);
  }
  return spline::label_sides(mp, labels, collapsed);
}

// Sides (patch, side) collapsed to a curve or point: their control points stay.
std::vector<std::pair<int, spline::Side>> collapsed_sides(const param::VolumeParam& vp) {
  std::vector<std::pair<int, spline::Side>> fixed;
  for (std::size_t p = 0; p < vp.blocks.size(); ++p)
    for (const spline::Side side : spline::Side::all())
      if (vp.blocks[p].collapsed[static_cast<std::size_t>(side.index() - 1)]) fixed.emplace_back(static_cast<int>(p), side);
  return fixed;
}

// Calls repair(slide, fixed sides, options) with what both repairs of a
// fitted model take: control points on T1 and the Ti slide along them,
// collapsed sides stay, the case's options.
template <class F>
spline::JacobianOptimizationResult with_repair_inputs(const Case& c, const Decomposition& d,
                                                      const param::VolumeParam& vp, Observer& observer, F&& repair) {
  const std::vector<param::SurfaceProjector> surfaces = param::surface_projectors(d.H);
  const spline::SlideFn slide = [&](int surface, const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
    return surfaces.at(static_cast<std::size_t>(surface)).slide(from, to);
  };
  spline::JacobianOptimizationOptions options = c.jacobian;
  options.progress = progress_to(observer);
  return repair(slide, collapsed_sides(vp), options);
}

// Moves the control points where the sampled scaled Jacobian is below the
// case's target (optimize_jacobian.h).
spline::JacobianOptimizationResult raise_jacobians(const Case& c, const Decomposition& d, const param::VolumeParam& vp,
                                                   spline::MultiPatch& mp, Observer& observer) {
  return with_repair_inputs(c, d, vp, observer, [&](const auto& slide, const auto& fixed, const auto& options) {
    return spline::optimize_jacobians(mp, slide, fixed, options);
  });
}

// The faces on each input surface fitted to it, then the other control
// points moved with them so the elements next to the surfaces keep their shape.
std::vector<spline::SurfaceFitResult> fit_surfaces(const Case& c, const Surfaces& surfaces,
                                                   const param::VolumeParam& vp, spline::MultiPatch& mp) {
  const spline::MultiPatch before = mp;
  const auto fixed = collapsed_sides(vp);
  std::vector<spline::SurfaceFitResult> out;
  for (std::size_t s = 0; s < surfaces.inputs.size(); ++s) {
    const int label = static_cast<int>(s);
    auto pairs = [&](const spline::MultiPatch& now) {
      return iga_check::surface_fit_pairs(now, label, surfaces.inputs[s]);
    };
    out.push_back(spline::fit_model_surface(mp, label, pairs, fixed, c.surface_fit));
  }
  spline::carry_moves_inside(mp, before, fixed);
  return out;
}

}  // namespace

std::vector<std::pair<int, Eigen::Vector3d>> negative_points(const iga_check::CheckReport& report) {
  std::vector<std::pair<int, Eigen::Vector3d>> out;
  for (const iga_check::ElementCertificate& e : report.certificates)
    if (e.status == iga_check::ElementStatus::Negative) out.emplace_back(e.patch, e.location);
  return out;
}

spline::JacobianOptimizationResult repair_at_negative_points(
    const Case& c, const Decomposition& d, const param::VolumeParam& vp, spline::MultiPatch& mp,
    const std::vector<std::pair<int, Eigen::Vector3d>>& witnesses, Observer& observer) {
  return with_repair_inputs(c, d, vp, observer, [&](const auto& slide, const auto& fixed, const auto& options) {
    return spline::repair_at_witnesses(mp, slide, fixed, witnesses, options);
  });
}

Fit fit_stage(const Case& c, const Surfaces& surfaces, const Decomposition& d, const param::VolumeParam& vp,
              Observer& observer) {
  StageTimer timer;
  Fit out;
  spline::MultiPatch& mp = out.model;
  fit_blocks(c, vp, mp);
  const double diag = d.diagonal;
  out.stitched = spline::stitch_control_points(mp, 1e-9 * diag, &out.max_stitch);
  out.unmatched_sides = connect_and_label(vp, diag, mp);
  StageSummary s{"fit", 0.0,
                 text("%zu patches, degree %d, %d elements per direction; %zu interfaces (%d stitched points, max "
                      "move %.1e), %zu boundary sides, %d unmatched sides, %zu layer(s)",
                      mp.patches.size(), c.fit.degree, c.fit.elements, mp.interfaces.size(), out.stitched,
                      out.max_stitch, mp.boundaries.size(), out.unmatched_sides, c.surfaces.size()),
                 {}};
  auto fit_to_surfaces = [&] {
    StageTimer st;
    out.surface_fits = fit_surfaces(c, surfaces, vp, mp);
    for (std::size_t i = 0; i < out.surface_fits.size(); ++i) {
      const auto& r = out.surface_fits[i];
      if (r.rms.empty()) continue;
      s.details.push_back(text("surface '%s' fitted: rms distance of the pairs %.3g -> %.3g in %d iterations, %d "
                               "control points free, moved at most %.2g (%.2f s so far)",
                               c.surfaces[i].label.c_str(), r.rms.front(), r.rms.back(), r.iterations, r.moved_points,
                               r.max_move, st.seconds()));
    }
  };
  auto repair = [&] {
    StageTimer jt;
    out.jacobians = raise_jacobians(c, d, vp, mp, observer);
    const auto& r = out.jacobians;
    const std::string focus =
        r.focus_patches == 0 ? ""
                             : text(", %d in a last pass aimed at negative samples (their lowest %.3f -> %.3f%s)",
                                    r.focus_patches, r.focus_min_before, r.focus_min_after,
                                    r.focus_kept ? "" : ", not kept");
    s.details.push_back(text("Jacobians %.2f s: lowest sampled scaled Jacobian %.3f -> %.3f, points below %.2f: %d -> "
                             "%d (%d control points moved, at most %.2g, %d patches on dense samples%s; joint: %d points, "
                             "%d iterations, stopped: %s; %d sweeps, stopped: %s)",
                             jt.seconds(), r.min_before, r.min_after, c.jacobian.target, r.below_before,
                             r.below_after, r.moved_points, r.max_move, r.dense_patches, focus.c_str(), r.joint_variables,
                             r.joint_iterations, r.joint_stop.empty() ? "off" : r.joint_stop.c_str(), r.sweeps,
                             r.stop_reason.c_str()));
  };
  if (c.surface_fit.iterations > 0) fit_to_surfaces();
  if (c.jacobian.target > 0.0) {
    const std::string skip = repair_skip_reason(vp);
    if (skip.empty()) repair();
    else s.details.push_back("Jacobian repair skipped: " + skip);
  }
  s.seconds = timer.seconds();
  observer.stage_finished(s);
  return out;
}

}  // namespace igaprep::pipeline
