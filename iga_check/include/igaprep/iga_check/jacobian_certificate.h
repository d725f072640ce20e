#pragma once
// Certified sign of the Jacobian determinant, element by element.
//
// On a Bezier element of degrees (p,q,r) a polynomial map x(t) has
// det J = x_u . (x_v x x_w), a polynomial of degrees (3p-1, 3q-1, 3r-1); its
// Bernstein coefficients are computed exactly (derivatives are Bernstein
// forms of one degree less, products use the binomial-product formula). The
// smallest coefficient is a lower bound of det J on the element (convex hull
// property) and every value (corners, samples) an upper bound of its minimum.
//
// Rational elements: with homogeneous coordinates P = w x (P and w polynomial)
//   det J = N / w^4,  N = det [ w  w_u  w_v  w_w ]
//                             [ P  P_u  P_v  P_w ]   (a 4 x 4 determinant),
// since x_d = (w P_d - w_d P) / w^2 and the column operations c_d <- w c_d -
// w_d c_0 turn the 4 x 4 matrix into [w 0; P, w P_d - w_d P]. N is a
// polynomial of degrees (4p-1, 4q-1, 4r-1) and, weights being positive, has
// the sign of det J. Polynomial elements use N = det J directly.
//
// Where the bounds do not decide, the box is split in two (de Casteljau on the
// coefficients of N) and the halves examined, smallest lower bound first, up
// to a depth and box budget. Zero tolerance: a coefficient within
// zero_tolerance * (the same coefficient computed from absolute values, i.e. a
// bound of its rounding error scale) of zero counts as zero.
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "igaprep/core/progress.h"
#include "igaprep/iga_check/bernstein3.h"
#include "igaprep/spline/bezier_extraction.h"
#include "igaprep/spline/extraction_model.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::iga_check {

enum class ElementStatus {
  Positive,    // det J > 0 on the closed element, certified
  Negative,    // det J < 0 at `location` (a point where it was evaluated)
  Degenerate,  // det J >= 0, zero somewhere on the element boundary (collapsed
               // face or edge), > 0 everywhere inside, certified
  Undecided,   // depth or box budget reached before the sign was decided
};
const char* to_string(ElementStatus s);  // "positive", "negative", "degenerate", "undecided"

struct CertifyOptions {
  int max_depth = 24;           // splits along any path (about 8 per direction)
  int max_boxes = 4000;         // boxes examined per element
  double zero_tolerance = 1e-12;
  // Degrees above this are refused before any work: det J has (3p)^3
  // Bernstein coefficients per element (degree 30: 729,000, and up to
  // max_boxes copies while an element is subdivided).
  int max_degree = 10;
  ProgressCallback progress;    // patches certified (certify_model)
};

struct ElementCertificate {
  int patch = -1;
  std::array<int, 3> element{{0, 0, 0}};  // element index per direction
  ElementStatus status = ElementStatus::Undecided;
  // Bounds of min det J over the element, in the patch's own parameters:
  // lower_bound <= min det J <= upper_bound. For rational elements the lower
  // bound divides N's bound by the extreme weight (convex hull of weights).
  double lower_bound = 0.0;
  double upper_bound = 0.0;
  Eigen::Vector3d location = Eigen::Vector3d::Zero();  // patch parameters where upper_bound
                                                       // was attained (the negative point)
  int boxes = 0;      // boxes examined
  int max_depth = 0;  // deepest split reached
};

// Whether an element passes the check: certified positive, or degenerate
// where that is allowed.
inline bool element_certified(const ElementCertificate& c, bool allow_degenerate) {
  return c.status == ElementStatus::Positive || (allow_degenerate && c.status == ElementStatus::Degenerate);
}
// The sign-carrying numerator N in local coordinates t in [0,1]^3 of the
// element (det J with respect to t; divide by the element's parameter lengths
// for det J with respect to patch parameters). `magnitude` (optional)
// receives the same computation on absolute values: the scale of each
// coefficient's rounding error.
Bernstein3 jacobian_numerator(const spline::BezierElement& e, const std::array<int, 3>& degrees,
                              Bernstein3* magnitude = nullptr);

// Certifies one Bezier element (`patch` and `element` are copied into the result).
ElementCertificate certify_element(const spline::BezierElement& e, const std::array<int, 3>& degrees,
                                   const CertifyOptions& options = {}, int patch = -1,
                                   const std::array<int, 3>& element = {{0, 0, 0}});

// All elements of a patch (u fastest, then v, then w). Throws bad_input naming
// the patch when a degree is 0 or a weight is not positive.
std::vector<ElementCertificate> certify_patch(const spline::Patch& p, int patch_index,
                                              const CertifyOptions& options = {});

// Every Bezier element of a model in extraction form (a T-spline), in its
// order; each certificate names the element's patch and index when it has
// them. Throws bad_input when a degree is 0 or above the limit, or a weight
// is not positive.
std::vector<ElementCertificate> certify_extraction_model(const spline::ExtractionModel& m,
                                                         const CertifyOptions& options = {});

// All elements of all patches, patch by patch.
std::vector<ElementCertificate> certify_model(const spline::MultiPatch& mp,
                                              const CertifyOptions& options = {});

}  // namespace igaprep::iga_check
