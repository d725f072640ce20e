#pragma once
// Private to spline/: which control points of a model (by global number,
// global_numbering; their positions: global_points) lie on given patch
// sides; shared by fit_model_surface and carry_moves_inside.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <utility>
#include <vector>

#include "igaprep/spline/curve_surface.h"
#include "igaprep/spline/label_sides.h"
#include "igaprep/spline/multipatch.h"
#include "igaprep/spline/multipatch_topology.h"
#include "igaprep/spline/side.h"

namespace igaprep::spline::detail {

using Sparse = Eigen::SparseMatrix<double>;
using Faces = std::vector<std::pair<int, Side>>;

// The faces standing for every surface whose label passes `keep`
// (sides_on_surface of each label that has sides).
template <class Keep>
inline Faces faces_of(const MultiPatch& mp, Keep keep) {
  Faces out;
  for (int label : labels_with_sides(mp))
    if (keep(label)) {
      const Faces f = sides_on_surface(mp, label);
      out.insert(out.end(), f.begin(), f.end());
    }
  return out;
}

inline void mark_faces(const MultiPatch& mp, const GlobalNumbering& gn, const Faces& faces, std::vector<char>& mark) {
  for (const auto& [patch, side] : faces)
    for (int local : side_control_points(mp.patches.at(static_cast<size_t>(patch)), side))
      mark[static_cast<size_t>(gn.global[static_cast<size_t>(patch)][static_cast<size_t>(local)])] = 1;
}

// Writes the global points back into every patch: shared points stay identical.
inline void scatter(const Eigen::MatrixXd& X, const GlobalNumbering& gn, MultiPatch& mp) {
  for (size_t p = 0; p < mp.patches.size(); ++p)
    for (int i = 0; i < mp.patches[p].control_points.rows(); ++i)
      mp.patches[p].control_points.row(i) = X.row(gn.global[p][static_cast<size_t>(i)]);
}

// Global number of every free point's column (-1: held), and back.
struct Columns {
  std::vector<int> of_point, point;
};

inline Columns free_columns(const std::vector<char>& on_faces, const std::vector<char>& held) {
  Columns c;
  c.of_point.assign(on_faces.size(), -1);
  for (size_t g = 0; g < on_faces.size(); ++g)
    if (on_faces[g] && !held[g]) {
      c.of_point[g] = static_cast<int>(c.point.size());
      c.point.push_back(static_cast<int>(g));
    }
  return c;
}

}  // namespace igaprep::spline::detail
