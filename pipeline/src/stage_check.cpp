#include "igaprep/pipeline/check.h"

#include <algorithm>

#include "stage_timer.h"
#include "igaprep/core/text.h"

namespace igaprep::pipeline {
namespace {

CheckFigures figures_of(const iga_check::CheckReport& r) {
  CheckFigures f;
  const iga_check::ElementTotals totals = iga_check::element_totals(r);
  f.elements = totals.elements;
  f.positive = totals.positive;
  f.negative = totals.negative;
  f.degenerate = totals.degenerate;
  f.undecided = totals.undecided;
  f.min_scaled_jacobian = r.quality.overall.scaled_jacobian.min;
  for (const auto& s : r.fidelity)
    f.fidelity.push_back(std::max(s.spline_to_mesh.max_relative, s.mesh_to_spline.max_relative));
  for (const auto& v : r.topology.regions) f.volume_difference.push_back(v.relative_difference);
  f.interface_gap = r.topology.interface_max_gap_relative;
  return f;
}

std::string headline(const iga_check::CheckReport& r, const CheckFigures& f, const std::vector<std::string>& labels) {
  std::string line = text("%s; %ld elements: %ld positive, %ld negative, %ld degenerate, %ld undecided; min scaled "
                          "Jacobian %.3f; interface gap %.1e",
                          r.passed ? "passed" : "FAILED", f.elements, f.positive, f.negative, f.degenerate,
                          f.undecided, f.min_scaled_jacobian, f.interface_gap);
  for (std::size_t i = 0; i < f.fidelity.size(); ++i)
    line += text("; fidelity %s %.3f %%", labels.size() > i ? labels[i].c_str() : "?", 100.0 * f.fidelity[i]);
  for (std::size_t i = 0; i < f.volume_difference.size(); ++i)
    line += text("; volume %zu %+.3f %%", i, 100.0 * f.volume_difference[i]);
  return line;
}

}  // namespace

Check check_stage(const spline::MultiPatch& mp, const std::vector<mesh::TriMesh>& surfaces,
                  const iga_check::CheckOptions& options, Observer& observer, const std::string& stage) {
  StageTimer timer;
  Check c;
  iga_check::CheckOptions with_progress = options;
  with_progress.certify.progress = progress_to(observer);
  c.report = iga_check::build_check_report(mp, surfaces, mp.labels, with_progress, "model.h5");
  c.figures = figures_of(c.report);
  c.figures.seconds = timer.seconds();
  observer.stage_finished({stage, c.figures.seconds, headline(c.report, c.figures, mp.labels),
                            iga_check::failure_lines(c.report)});
  return c;
}

}  // namespace igaprep::pipeline
