#pragma once
// B-spline basis functions and their derivatives at a parameter (all p+1
// non-zero functions of the span at once), and 1-D basis tables for many
// parameters: analysed once, reused by grid evaluation and fitting.
#include <Eigen/Core>
#include <vector>

namespace igaprep::spline {

// Inputs: U knots, p degree, span from find_span(U, p, u), u parameter.
// Output: N[0..p], N[r] = N_{span-p+r,p}(u). Raw pointer for inner loops.
void basis_functions(const std::vector<double>& U, int p, int span, double u, double* N);
Eigen::VectorXd basis_functions(const std::vector<double>& U, int p, int span, double u);

// Derivatives of order 0..order (order may exceed p: those rows are zero).
// Output: ders[k*(p+1) + r] = d^k/du^k N_{span-p+r,p}(u) (raw version), or
// an (order+1) x (p+1) matrix.
void basis_derivatives(const std::vector<double>& U, int p, int span, double u, int order,
                       double* ders);
Eigen::MatrixXd basis_derivatives(const std::vector<double>& U, int p, int span, double u,
                                  int order);

// Basis values and derivatives up to `order` at a list of parameters.
struct BasisTable {
  int degree = 0;
  int order = 0;
  std::vector<int> span;       // per parameter; first non-zero function = span - degree
  std::vector<double> values;  // per parameter i, derivative k, function r:
                               // values[(i*(order+1) + k)*(degree+1) + r]
  int size() const { return static_cast<int>(span.size()); }
  const double* at(int i, int k) const { return values.data() + (static_cast<size_t>(i) * (order + 1) + k) * (degree + 1); }
};
BasisTable basis_table(const std::vector<double>& U, int p, const std::vector<double>& params,
                       int order);
// The same for parameters of one knot span, U[span] <= u <= U[span + 1]:
// no search, so a parameter that rounds onto the span's end still gets this
// span's functions (quadrature points of an element).
BasisTable basis_table_on_span(const std::vector<double>& U, int p, int span, const std::vector<double>& params,
                               int order);

// Dense collocation matrix B (m x n), B(i, j) = d^k/du^k N_j(params[i]).
Eigen::MatrixXd collocation_matrix(const std::vector<double>& U, int p,
                                   const std::vector<double>& params, int derivative = 0);

// Bernstein polynomials of degree p on [0, 1] at t: B[0..p].
void bernstein_basis(int p, double t, double* B);

}  // namespace igaprep::spline
