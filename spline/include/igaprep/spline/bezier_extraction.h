#pragma once
// Bezier extraction (Borden, Scott, Evans & Hughes 2011): on every element
// (non-empty knot span) the B-spline basis functions are linear combinations
// of Bernstein polynomials, N_e = C_e B. The operators are built once per
// direction; the tensor-product operator of a volume element is their
// Kronecker product. Bernstein control points of an element: P_b = C_e^T P_e
// (homogeneous for NURBS).
#include <Eigen/Core>
#include <array>
#include <vector>

#include "igaprep/spline/multipatch.h"

namespace igaprep::spline {

struct Extraction1d {
  int degree = 0;
  std::vector<double> breaks;        // element e spans [breaks[e], breaks[e+1]]
  std::vector<int> first;            // first non-zero basis function on element e
  std::vector<Eigen::MatrixXd> C;    // (p+1) x (p+1): row r = local function first[e]+r
                                     // in the Bernstein basis of the element (columns)
  int element_count() const { return static_cast<int>(C.size()); }
};
Extraction1d bezier_extraction_1d(const std::vector<double>& U, int p);

struct PatchExtraction {
  std::array<Extraction1d, 3> dirs;
  int element_count(int d) const { return dirs[d].element_count(); }
  int element_count() const { return element_count(0) * element_count(1) * element_count(2); }
};
PatchExtraction bezier_extraction(const Patch& p);

// Kron(C_w, C_v, C_u): ((p_u+1)(p_v+1)(p_w+1))^2, rows local basis functions
// and columns Bernstein polynomials, both u fastest.
Eigen::MatrixXd element_extraction_operator(const PatchExtraction& ex, int eu, int ev, int ew);

// Patch control-point indices of the element's local functions, u fastest.
std::vector<int> element_control_points(const Patch& p, const PatchExtraction& ex, int eu, int ev,
                                        int ew);

struct BezierElement {
  Eigen::MatrixXd points;    // ((p_u+1)(p_v+1)(p_w+1)) x 3, Cartesian, u fastest
  Eigen::VectorXd weights;   // empty for B-spline patches
  std::array<std::array<double, 2>, 3> domain{};  // parameter interval per direction
};
BezierElement bernstein_control_points(const Patch& p, const PatchExtraction& ex, int eu, int ev,
                                       int ew);

// The Bernstein points C^T H of an element whose functions' control points
// are the rows of H: homogeneous (x w, y w, z w, w) with 4 columns (then
// Cartesian points and the weights come out), Cartesian with 3 (no
// weights). The domain is left for the caller.
BezierElement bezier_element_from(const Eigen::MatrixXd& C, const Eigen::MatrixXd& H);

// Evaluation of a Bezier element at local coordinates t in [0,1]^3.
Eigen::Vector3d evaluate_bezier(const BezierElement& e, const std::array<int, 3>& degrees,
                                const Eigen::Vector3d& t);

}  // namespace igaprep::spline
