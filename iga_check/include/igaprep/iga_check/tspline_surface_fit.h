#pragma once
// Fit-driven refinement of a T-spline to its input surfaces (issue 18):
// spline::fit_tspline with the closest-point pairs of surface_fit_pairs.h,
// then the Jacobian repair: the fit moves control points, and where an
// element is no longer certified positive, the functions on it fall back
// toward the unfitted geometry of the same refined space (nestedness: the
// starting model's, which was certified) by halving their moves, repeated;
// the last step takes the moves back entirely. So the result keeps the
// starting model's certificate wherever the fit cannot, at the cost of the
// fit there, and says how much was given up.
#include <vector>

#include "igaprep/iga_check/fidelity.h"
#include "igaprep/iga_check/jacobian_certificate.h"
#include "igaprep/iga_check/surface_fit_pairs.h"
#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/spline/tspline_fit.h"

namespace igaprep::iga_check {

// Face samples as the fidelity's (9 per element and direction), so that the
// tolerance bounds what the check then measures face to surface.
inline SurfaceFitPairOptions tspline_fit_pair_options() {
  SurfaceFitPairOptions o;
  o.samples_per_element = FidelityOptions{}.samples_per_element;
  return o;
}

struct TSplineRepairResult {
  int steps = 0;                // halvings made
  int functions_backed_off = 0;  // functions whose move was reduced
  int uncertified_before = 0, uncertified_after = 0;  // elements not certified positive
};

struct TSplineSurfaceFitResult {
  spline::TSplineFitResult fit;  // fit.model is the repaired model
  TSplineRepairResult repair;
};

// Inputs: the T-spline (refined in place; its geometry is the starting
// model's), the surfaces (index = label, outermost first; an empty mesh is
// not fitted), the options.
TSplineSurfaceFitResult fit_tspline_to_surfaces(spline::TSplineModel& model, const std::vector<mesh::TriMesh>& surfaces,
                                                const spline::TSplineFitOptions& options,
                                                const SurfaceFitPairOptions& pair_options = tspline_fit_pair_options(),
                                                const CertifyOptions& certify = {});

// The repair alone: `m` fitted, `unfitted` the same functions' control
// points before the fit. At most `max_steps` halvings, the last one a full
// return.
TSplineRepairResult back_off_uncertified(spline::ExtractionModel& m, const Eigen::MatrixXd& unfitted,
                                         const CertifyOptions& certify = {}, int max_steps = 12);

}  // namespace igaprep::iga_check
