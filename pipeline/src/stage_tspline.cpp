#include <algorithm>
#include <cmath>
#include <string>

#include "igaprep/core/text.h"
#include "igaprep/iga_check/jacobian_certificate.h"
#include "igaprep/pipeline/tspline.h"
#include "igaprep/spline/tspline_model.h"
#include "stage_timer.h"

namespace igaprep::pipeline {
namespace {

void add_certificate(const spline::ExtractionModel& m, TSplineFigures& f) {
  const std::vector<iga_check::ElementCertificate> c = iga_check::certify_extraction_model(m);
  f.elements = static_cast<long>(c.size());
  f.min_lower_bound = INFINITY;
  for (const iga_check::ElementCertificate& e : c) {
    if (!iga_check::element_certified(e, false)) ++f.uncertified;
    f.min_lower_bound = std::min(f.min_lower_bound, e.lower_bound);
  }
}

StageSummary summary(const spline::ExtractionModel& m, const TSplineFigures& f, double seconds) {
  auto label = [&](std::size_t i) { return i < m.labels.size() ? m.labels[i] : std::to_string(i); };
  std::string line = text("%ld functions, %ld elements, %zu rounds, tolerance %g %s; %ld elements not certified",
                          static_cast<long>(m.function_count()), f.elements, f.rounds.size(), f.tolerance,
                          f.reached ? "reached" : "NOT reached", f.uncertified);
  for (std::size_t i = 0; i < f.fidelity.size(); ++i) line += text("; fidelity %s %.3f %%", label(i).c_str(), 100.0 * f.fidelity[i]);
  std::vector<std::string> details;
  for (std::size_t k = 0; k < f.rounds.size(); ++k)
    details.push_back(text("round %zu: %d functions, %d elements, largest distance %g, %d elements over, %d boxes refined",
                           k, f.rounds[k].functions, f.rounds[k].elements, f.rounds[k].max_distance,
                           f.rounds[k].elements_over, f.rounds[k].boxes_refined));
  details.push_back(text("Jacobian repair: %d elements not certified after the fit, %d after %d halvings of %d functions' moves",
                         f.repair.uncertified_before, f.repair.uncertified_after, f.repair.steps,
                         f.repair.functions_backed_off));
  return {"tspline", seconds, line, details};
}

}  // namespace

TSplineStage tspline_stage(const spline::MultiPatch& mp, const std::vector<mesh::TriMesh>& surfaces,
                           const TSplineSettings& settings, Observer& observer) {
  StageTimer timer;
  const double diagonal = surfaces.empty() ? iga_check::model_diagonal(mp) : iga_check::mesh_diagonal(surfaces.front());
  spline::TSplineModel t = spline::tspline_model(mp);
  spline::TSplineFitOptions options;
  options.tolerance = settings.tolerance > 0.0 ? settings.tolerance : settings.relative_tolerance * diagonal;
  options.max_rounds = settings.rounds;
  iga_check::TSplineSurfaceFitResult fit = iga_check::fit_tspline_to_surfaces(t, surfaces, options);
  TSplineStage s;
  s.model = std::move(fit.fit.model);
  TSplineFigures& f = s.figures;
  f.tolerance = options.tolerance;
  f.rounds = std::move(fit.fit.rounds);
  f.reached = fit.fit.reached;
  f.repair = fit.repair;
  add_certificate(s.model, f);
  for (const iga_check::SurfaceFidelity& d : iga_check::fidelity(s.model, surfaces, diagonal))
    f.fidelity.push_back(std::max(d.spline_to_mesh.max_relative, d.mesh_to_spline.max_relative));
  observer.stage_finished(summary(s.model, f, timer.seconds()));
  return s;
}

}  // namespace igaprep::pipeline
