#pragma once
// Trivariate polynomials in tensor-product Bernstein form on a box, with the
// exact operations the Jacobian certificate needs: products (binomial-product
// formula), partial derivatives, de Casteljau subdivision and evaluation.
// Every operation is exact in real arithmetic; in floating point each result
// coefficient is a short sum of products, so its rounding error is a small
// multiple of machine epsilon times the same sum taken over absolute values.
#include <Eigen/Core>
#include <array>
#include <vector>

namespace igaprep::iga_check {

struct Bernstein3 {
  std::array<int, 3> degree{{0, 0, 0}};
  std::vector<double> coeffs;  // (d0+1)(d1+1)(d2+1), index i + (d0+1)*(j + (d1+1)*k)

  Bernstein3() : coeffs(1, 0.0) {}
  Bernstein3(const std::array<int, 3>& deg, double value = 0.0);
  int size(int d) const { return degree[d] + 1; }
  int index(int i, int j, int k) const { return i + size(0) * (j + size(1) * k); }
  double& operator()(int i, int j, int k) { return coeffs[index(i, j, k)]; }
  double operator()(int i, int j, int k) const { return coeffs[index(i, j, k)]; }
};

// Product of two polynomials: degree a.degree + b.degree, using
// B^m_i B^n_j = C(m,i) C(n,j) / C(m+n,i+j) B^{m+n}_{i+j} in each direction.
Bernstein3 bernstein_product(const Bernstein3& a, const Bernstein3& b);

// Partial derivative d/dt_dir on [0,1]: degree drops by one in `dir`,
// coefficients deg * (c_{i+1} - c_i). A direction of degree 0 gives the zero
// polynomial of degree 0 there.
Bernstein3 bernstein_derivative(const Bernstein3& a, int dir);

// a + s * b for equal degrees (throws internal_error otherwise).
Bernstein3 bernstein_axpy(const Bernstein3& a, double s, const Bernstein3& b);

// de Casteljau split of the box at parameter t in direction dir: the
// coefficients of the same polynomial on [0,t] and [t,1] (each reparameterized
// to [0,1]).
void bernstein_subdivide(const Bernstein3& a, int dir, double t, Bernstein3* low, Bernstein3* high);

// Value at t in [0,1]^3 (tensor de Casteljau).
double bernstein_evaluate(const Bernstein3& a, const Eigen::Vector3d& t);

// Coefficients of the tensor Bernstein form of degree `degree` that
// interpolates f at the (d+1)^3 points i/d (exact for polynomials of that
// degree, up to rounding). Used by tests and by callers who hold a map as a
// function.
Bernstein3 bernstein_from_samples(const std::array<int, 3>& degree,
                                  const std::vector<double>& values_on_uniform_grid);

}  // namespace igaprep::iga_check
