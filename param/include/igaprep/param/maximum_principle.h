#pragma once
// The discrete maximum principle as a check: a harmonic field has no strict
// local extremum at a free (non-Dirichlet) vertex. P1 fields on meshes with
// obtuse (non-Delaunay) elements can break it, which later shows up as
// folded parameterizations, so each harmonic stage can report it.
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace igaprep::param {

struct LocalExtremum {
  int vertex = -1;
  bool maximum = false;  // true: above all neighbours; false: below all
  double margin = 0.0;   // distance to the nearest neighbour value (> tolerance)
};

// Inputs: K (#V x #V) stiffness matrix, whose pattern gives the neighbours
// (vertices sharing a cell); u (#V) field; is_dirichlet (#V, nonzero for
// Dirichlet vertices, which are skipped); tolerance: a vertex counts only when
// it is above (below) every neighbour by more than tolerance * (max u - min u).
// Output: the strict interior local extrema, by vertex.
std::vector<LocalExtremum> find_interior_extrema(const Eigen::SparseMatrix<double>& K, const Eigen::VectorXd& u,
                                                 const std::vector<char>& is_dirichlet, double tolerance = 1e-12);

// Each strict interior extremum (as found above) takes the mean of its
// neighbours' values, in rounds until none is left or `max_rounds` have
// passed (a changed vertex can make a neighbour an extremum). A streamline
// of -grad u is caught at such a vertex. Returns the number of values changed.
int flatten_interior_extrema(const Eigen::SparseMatrix<double>& K, Eigen::VectorXd& u,
                             const std::vector<char>& is_dirichlet, double tolerance = 1e-12, int max_rounds = 50);

}  // namespace igaprep::param
