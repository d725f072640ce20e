#pragma once
// A spline model in Bezier-extraction form (Scott, Borden, Verhoosel,
// Sederberg & Hughes 2011): global functions with their control points and
// weights, and per element the ids of the functions that do not vanish on
// it and the operator C_e that maps them to the element's Bernstein basis.
// It is the form of T-splines (issue 18): an element's functions need not
// come from one tensor-product patch. Here it is made from a conforming
// multipatch, each function one class of its global numbering.
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "igaprep/spline/bezier_extraction.h"
#include "igaprep/spline/multipatch.h"
#include "igaprep/spline/side.h"

namespace igaprep::spline {

struct ExtractionElement {
  std::array<int, 3> degrees{{0, 0, 0}};
  std::vector<int> functions;  // global function ids
  int extraction = 0;          // index into ExtractionModel::operators: C_e
  int material = 0;
  // Where it came from: the patch, the element index per direction and its
  // parameter box (the Bernstein variable t maps to domain[d][0] + t * length).
  int patch = -1;
  std::array<int, 3> index{{0, 0, 0}};
  std::array<std::array<double, 2>, 3> domain{};
  int box = -1;  // a T-spline's: the box of its patch's T-mesh it lies in (tensor: the element index)
};

// An element face on a labelled boundary of the model.
struct ExtractionBoundaryFace {
  int element = 0;
  Side side;  // the element's own side, numbered as a patch's
  int label = 0;
};

struct ExtractionModel {
  Eigen::MatrixXd control_points;  // functions x 3, Cartesian
  Eigen::VectorXd weights;         // one per function (all 1 for a polynomial model)
  std::vector<ExtractionElement> elements;
  // The distinct operators C_e, each functions x (p_u+1)(p_v+1)(p_w+1): row r
  // = the element's function r in its Bernstein polynomials (u fastest).
  // Elements with the same knot pattern share one (ring2: 125 for 27,648
  // elements; stored per element they would take 0.9 GB).
  std::vector<Eigen::MatrixXd> operators;
  std::vector<ExtractionBoundaryFace> boundary_faces;
  // Element faces on a material interface that lies on an input surface
  // (Interface::surface; patch a's side): label = that surface.
  std::vector<ExtractionBoundaryFace> interface_faces;
  std::vector<std::string> labels;
  std::vector<Material> materials;
  std::string provenance_generator, provenance_case, provenance_inputs;
  // A solve result (as MultiPatch's): one displacement (ux, uy, uz) per
  // function, coefficients in this basis; empty otherwise.
  Eigen::MatrixXd displacement;
  bool has_solution = false;
  double strain_energy = 0.0;
  double max_displacement = 0.0;

  int function_count() const { return static_cast<int>(control_points.rows()); }
  const Eigen::MatrixXd& C(int element) const {
    return operators[static_cast<std::size_t>(elements[static_cast<std::size_t>(element)].extraction)];
  }
  bool rational() const;  // a weight other than 1
};

// The multipatch's elements (patch by patch, u fastest) over its global
// functions (global_numbering): the same basis, geometry, labels and
// materials. Throws bad_input for a model that is not conforming (copies of
// one function with different control points or weights, beyond 1e-12 of
// the diagonal) or has no patches.
ExtractionModel extraction_model(const MultiPatch& mp);

// Copies what describes the model besides its geometry (labels, materials,
// provenance) from the multipatch it was made from.
void copy_model_descriptions(const MultiPatch& mp, ExtractionModel& out);

// The element's functions (positions in its `functions`) that do not vanish
// on its face `side`: a coefficient beyond 1e-14 on a Bernstein polynomial
// of that face (open knots: the face's trace).
std::vector<int> face_functions(const ExtractionModel& m, int element, Side side);

// The element as a Bezier element: its Bernstein points C_e^T times its
// functions' control points in homogeneous coordinates (weights only when
// the model is rational), and its parameter box.
BezierElement bernstein_element(const ExtractionModel& m, int element);

// The element's (rational) basis functions at Bernstein coordinates t in
// [0, 1]^3, in the order of its `functions`: they sum to 1.
Eigen::VectorXd element_basis(const ExtractionModel& m, int element, const Eigen::Vector3d& t);

// The element's point at Bernstein coordinates t in [0, 1]^3 (rational when
// the weights are not all 1).
Eigen::Vector3d evaluate_element(const ExtractionModel& m, int element, const Eigen::Vector3d& t);

}  // namespace igaprep::spline
