#pragma once
// Knot vectors: validation, span search and small utilities. A knot vector U
// of degree p for n basis functions is open (clamped): non-decreasing, first
// and last knot repeated p+1 times, length n + p + 1. The parameter domain is
// [U[p], U[n]].
#include <string>
#include <vector>

namespace igaprep::spline {

// Throws igaprep::bad_input naming `what` (e.g. "patch 3 direction v") and the
// fault (length, decreasing knot at index i, end multiplicity, interior
// multiplicity > p+1 is allowed only as <= p, non-finite value, empty domain).
// Inputs: U knots, p degree (>= 0), n number of basis functions (>= p + 1).
void validate_knot_vector(const std::vector<double>& U, int p, int n, const std::string& what);

// Index of the knot span containing u: the s with U[s] <= u < U[s+1] and
// p <= s <= n-1; u = U[n] maps to the last non-empty span. u outside the
// domain is clamped into it. Binary search, O(log n).
int find_span(const std::vector<double>& U, int p, double u);

// Open uniform knot vector with n basis functions of degree p on [a, b].
std::vector<double> uniform_knot_vector(int p, int n, double a = 0.0, double b = 1.0);

// Open knot vector of degree p with the given strictly increasing breakpoints
// (element boundaries), each interior breakpoint repeated `interior_multiplicity`
// times (1 = C^{p-1}).
std::vector<double> knot_vector_from_breaks(const std::vector<double>& breaks, int p,
                                            int interior_multiplicity = 1);

// Distinct knot values (element boundaries), increasing.
std::vector<double> unique_knots(const std::vector<double>& U);

// Number of knots equal to u (exact comparison).
int knot_multiplicity(const std::vector<double>& U, double u);

// Greville abscissae (knot averages), one per basis function.
std::vector<double> greville_abscissae(const std::vector<double>& U, int p);

// Number of basis functions n = U.size() - p - 1.
inline int basis_count(const std::vector<double>& U, int p) { return static_cast<int>(U.size()) - p - 1; }

}  // namespace igaprep::spline
