#include "igaprep/pipeline/reduce.h"

#include <algorithm>
#include <cmath>

#include "igaprep/core/error.h"
#include "igaprep/core/text.h"
#include "igaprep/iga_check/jacobian_certificate.h"
#include "igaprep/iga_check/topology_checks.h"
#include "igaprep/spline/refine.h"
#include "stage_timer.h"

namespace igaprep::pipeline {
namespace {

double asked_tolerance(const ReduceSettings& s, double diagonal) {
  if (s.tolerance > 0.0 && s.relative_tolerance > 0.0)
    throw bad_input("reduce: give either a tolerance (model units) or a relative tolerance, not both");
  if (s.tolerance > 0.0 && std::isfinite(s.tolerance)) return s.tolerance;
  if (s.relative_tolerance > 0.0 && std::isfinite(s.relative_tolerance)) return s.relative_tolerance * diagonal;
  throw bad_input("reduce: the tolerance must be a positive distance (model units) or a positive fraction of the "
                  "model's diagonal");
}

// A distance to an input surface grows by at most the tolerance.
void limit_by_fidelity(const iga_check::CheckReport& before, const iga_check::CheckOptions& options, ReduceFigures& f) {
  const double distance_limit = options.fidelity_limit * before.input_diagonal;
  for (const iga_check::SurfaceFidelity& s : before.fidelity) {
    const double distance = std::max(s.spline_to_mesh.max, s.mesh_to_spline.max);
    if (distance <= distance_limit && distance_limit - distance < f.tolerance) {
      f.tolerance = distance_limit - distance;
      f.limited_by = "fidelity " + s.label;
    }
  }
}

// The region whose volume was within its limit before and is not now ("" when none).
std::string volume_lost(const spline::MultiPatch& reduced, const iga_check::CheckReport& before,
                        const iga_check::CheckOptions& options) {
  const iga_check::TopologyReport& t = before.topology;
  for (const iga_check::RegionVolume& r : t.regions) {
    const double allowed = options.volume_limit * r.input_volume;
    if (std::abs(r.spline_volume - r.input_volume) > allowed) continue;
    double volume = 0.0;
    for (std::size_t p = 0; p < reduced.patches.size() && p < t.patch_region.size(); ++p)
      if (t.patch_region[p] == r.region) volume += iga_check::patch_volume(reduced.patches[p]);
    if (std::abs(volume - r.input_volume) > allowed) return "volume region " + std::to_string(r.region);
  }
  return "";
}

// No element the check certified loses its certificate: the reduced patch,
// refined back to the original's knots, is certified element by element.
// Where every element was certified, the reduced patch's own (fewer, larger)
// elements are tried first: positive there is positive on every part.
spline::ReducedPatchCheck certificate_check(const spline::MultiPatch& mp, const iga_check::CheckReport& before,
                                            const iga_check::CheckOptions& options) {
  std::vector<std::vector<bool>> certified(mp.patches.size());
  for (const iga_check::ElementCertificate& c : before.certificates)
    if (c.patch >= 0 && static_cast<std::size_t>(c.patch) < certified.size())
      certified[static_cast<std::size_t>(c.patch)].push_back(iga_check::element_certified(c, options.allow_degenerate));
  iga_check::CertifyOptions certify = options.certify;
  certify.progress = nullptr;
  const bool allow_degenerate = options.allow_degenerate;
  auto all_certified = [certify, allow_degenerate](const spline::Patch& p, int patch) {
    for (const iga_check::ElementCertificate& c : iga_check::certify_patch(p, patch, certify))
      if (!iga_check::element_certified(c, allow_degenerate)) return false;
    return true;
  };
  return [&mp, certified, certify, allow_degenerate, all_certified](int patch, const spline::Patch& reduced) {
    const std::vector<bool>& was = certified[static_cast<std::size_t>(patch)];
    const bool whole = std::all_of(was.begin(), was.end(), [](bool b) { return b; });
    if (whole && all_certified(reduced, patch)) return true;
    const spline::Patch& original = mp.patches[static_cast<std::size_t>(patch)];
    const auto certificates = iga_check::certify_patch(spline::refine_to_knots(reduced, original.knots), patch, certify);
    if (certificates.size() != was.size()) return false;
    for (std::size_t e = 0; e < was.size(); ++e)
      if (was[e] && !iga_check::element_certified(certificates[e], allow_degenerate)) return false;
    return true;
  };
}

std::string headline(const ReduceFigures& f) {
  const double kept = f.control_points_before > 0 ? 100.0 * f.control_points_after / f.control_points_before : 0.0;
  std::string line = text("%ld control points -> %ld (%.1f %%), %ld elements -> %ld; %d knots removed; bound %.3g "
                          "(tolerance %.3g",
                          f.control_points_before, f.control_points_after, kept, f.elements_before, f.elements_after,
                          f.knots_removed, f.bound, f.tolerance);
  if (!f.limited_by.empty()) line += text(", lowered from %.3g by the margin of %s", f.tolerance_asked, f.limited_by.c_str());
  return line + text("); measured %.3g at %ld parameters", f.measured, f.samples);
}

std::vector<std::string> details(const ReduceFigures& f) {
  std::vector<std::string> out;
  if (f.removals_undone > 0)
    out.push_back(text("%d removals undone: an element the check certified would have lost its certificate",
                       f.removals_undone));
  if (f.inconsistent_families > 0)
    out.push_back(text("%d knot families left as they are: their members' knot vectors differ (not conforming)",
                       f.inconsistent_families));
  return out;
}

}  // namespace

Reduction reduce_stage(const spline::MultiPatch& mp, const ReduceSettings& settings,
                       const iga_check::CheckReport& before, const iga_check::CheckOptions& options,
                       Observer& observer) {
  StageTimer timer;
  Reduction r;
  ReduceFigures& f = r.figures;
  f.tolerance_asked = f.tolerance = asked_tolerance(settings, before.diagonal);
  limit_by_fidelity(before, options, f);
  spline::ModelReductionOptions o;
  o.progress = progress_to(observer);
  const spline::ReducedPatchCheck check = certificate_check(mp, before, options);
  spline::ModelReduction m;
  for (;;) {  // a volume changes by less than the tolerance times its boundary's area: halve until it holds
    o.tolerance = f.tolerance;
    m = spline::reduce_model(mp, o, check);
    const std::string lost = volume_lost(m.model, before, options);
    if (lost.empty()) break;
    f.tolerance *= 0.5;
    f.limited_by = lost;
  }
  r.model = std::move(m.model);
  f.control_points_before = m.control_points_before;
  f.control_points_after = m.control_points_after;
  f.elements_before = m.elements_before;
  f.elements_after = m.elements_after;
  for (const iga_check::ElementCertificate& c : before.certificates)
    f.uncertified_before += iga_check::element_certified(c, options.allow_degenerate) ? 0 : 1;
  f.knots_removed = m.knots_removed;
  f.removals_undone = m.removals_undone;
  f.inconsistent_families = m.inconsistent_families;
  f.bound = m.bound;
  f.measured = m.measured;
  f.samples = m.samples;
  f.seconds = timer.seconds();
  observer.stage_finished({"reduce", f.seconds, headline(f), details(f)});
  return r;
}

CheckedReduction reduce_checked(const spline::MultiPatch& mp, const ReduceSettings& settings,
                                const std::vector<mesh::TriMesh>& surfaces, const iga_check::CheckOptions& options,
                                Observer& observer) {
  CheckedReduction out;
  out.fitted = check_stage(mp, surfaces, options, observer, "check_fitted");
  out.reduction = reduce_stage(mp, settings, out.fitted.report, options, observer);
  out.reduced = check_stage(out.reduction.model, surfaces, options, observer);
  return out;
}

}  // namespace igaprep::pipeline
