#pragma once
// The data of a multipatch trivariate spline model, as plain structs. This is
// the model every later stage (fit, reduce, check, solve, export) passes
// around; the algorithms that act on it live in their own headers.
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "igaprep/spline/side.h"

namespace igaprep::spline {

// One trivariate tensor-product patch, B-spline or NURBS.
struct Patch {
  std::array<int, 3> degrees{{0, 0, 0}};        // (p_u, p_v, p_w)
  std::array<std::vector<double>, 3> knots;      // full open knot vectors, length n_d + p_d + 1
  Eigen::MatrixXd control_points;                // (n_u*n_v*n_w) x 3, Cartesian, u fastest, then v, then w
  Eigen::VectorXd weights;                       // empty for a B-spline patch, else one per control point
  int material = 0;                              // index into MultiPatch::materials
  Eigen::MatrixXd displacement;                  // empty, or a solve result: one row (ux, uy, uz)
                                                 // per control point, coefficients in this basis

  int count(int dir) const { return static_cast<int>(knots[dir].size()) - degrees[dir] - 1; }
  int index(int i, int j, int k) const { return i + count(0) * (j + count(1) * k); }
  bool rational() const { return weights.size() > 0; }
};

// Two patch sides that touch (G+Smo convention): dirmap[d] is the direction
// of patch b that runs along direction d of patch a; orient[d] is 1 when it
// runs the same sense, 0 when reversed.
struct Interface {
  int patch_a = 0;
  Side side_a;
  int patch_b = 0;
  Side side_b;
  std::array<int, 3> dirmap{{0, 1, 2}};
  std::array<int, 3> orient{{1, 1, 1}};
  int surface = -1;  // index into MultiPatch::labels of the input surface it lies on, or -1
};

struct BoundarySide {
  int patch = 0;
  Side side;
  int label = 0;  // index into MultiPatch::labels
};

struct Material {
  std::string name;
  double young_modulus = 1.0;
  double poisson_ratio = 0.3;
};

struct MultiPatch {
  std::vector<Patch> patches;
  std::vector<Interface> interfaces;
  std::vector<BoundarySide> boundaries;
  std::vector<std::string> labels;  // label 0 is the outer surface T1
  std::vector<Material> materials;

  // Present in solve results (ARCHITECTURE.md): root attributes of the file.
  bool has_solution = false;
  double strain_energy = 0.0;
  double max_displacement = 0.0;

  // Optional provenance: generator name, the case file as JSON, inputs as JSON.
  std::string provenance_generator, provenance_case, provenance_inputs;
};

}  // namespace igaprep::spline
