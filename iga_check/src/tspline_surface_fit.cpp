#include "igaprep/iga_check/tspline_surface_fit.h"

#include <set>

#include "igaprep/core/error.h"

namespace igaprep::iga_check {

namespace {

std::vector<int> uncertified_elements(const spline::ExtractionModel& m, const CertifyOptions& certify) {
  const std::vector<ElementCertificate> c = certify_extraction_model(m, certify);
  std::vector<int> out;
  for (std::size_t e = 0; e < c.size(); ++e)
    if (!element_certified(c[e], false)) out.push_back(static_cast<int>(e));
  return out;
}

}  // namespace

TSplineRepairResult back_off_uncertified(spline::ExtractionModel& m, const Eigen::MatrixXd& unfitted,
                                         const CertifyOptions& certify, int max_steps) {
  if (unfitted.rows() != m.control_points.rows() || unfitted.cols() != 3)
    throw bad_input("T-spline repair: the unfitted control points are not one per function");
  TSplineRepairResult r;
  std::vector<int> bad = uncertified_elements(m, certify);
  r.uncertified_before = static_cast<int>(bad.size());
  std::set<int> backed_off;
  for (int step = 1; step <= max_steps && !bad.empty(); ++step) {
    std::set<int> functions;
    for (const int e : bad)
      for (const int f : m.elements[static_cast<std::size_t>(e)].functions) functions.insert(f);
    const double keep = step == max_steps ? 0.0 : 0.75;
    for (const int f : functions)
      m.control_points.row(f) = unfitted.row(f) + keep * (m.control_points.row(f) - unfitted.row(f));
    backed_off.insert(functions.begin(), functions.end());
    r.steps = step;
    bad = uncertified_elements(m, certify);
  }
  r.functions_backed_off = static_cast<int>(backed_off.size());
  r.uncertified_after = static_cast<int>(bad.size());
  return r;
}

TSplineSurfaceFitResult fit_tspline_to_surfaces(spline::TSplineModel& model, const std::vector<mesh::TriMesh>& surfaces,
                                                const spline::TSplineFitOptions& options,
                                                const SurfaceFitPairOptions& pair_options, const CertifyOptions& certify) {
  std::vector<int> fitted;
  for (std::size_t s = 0; s < surfaces.size(); ++s)
    if (surfaces[s].F.rows() > 0) fitted.push_back(static_cast<int>(s));
  TSplineSurfaceFitResult out;
  out.fit = spline::fit_tspline(
      model, fitted,
      [&](const spline::ExtractionModel& m, int s) { return extraction_fit_pairs(m, s, surfaces[static_cast<std::size_t>(s)], pair_options); },
      options);
  const Eigen::MatrixXd unfitted = spline::extraction_model(model).control_points;
  out.repair = back_off_uncertified(out.fit.model, unfitted, certify);
  return out;
}

}  // namespace igaprep::iga_check
