// Knot vectors: validation, span search, constructors.
#include "igaprep/spline/knot_vector.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "igaprep/core/error.h"

namespace igaprep::spline {

void validate_knot_vector(const std::vector<double>& U, int p, int n, const std::string& what) {
  auto fail = [&](const std::string& msg) { throw bad_input(what + ": " + msg); };
  if (p < 0) fail("negative degree " + std::to_string(p));
  if (p > 30) fail("degree " + std::to_string(p) + " above the supported maximum 30");
  if (n < p + 1)
    fail(std::to_string(n) + " control points are too few for degree " + std::to_string(p) +
         " (need at least " + std::to_string(p + 1) + ")");
  if (static_cast<int>(U.size()) != n + p + 1)
    fail("knot vector has " + std::to_string(U.size()) + " knots, expected n + p + 1 = " +
         std::to_string(n + p + 1) + " for n = " + std::to_string(n) + ", p = " + std::to_string(p));
  for (size_t i = 0; i < U.size(); ++i)
    if (!std::isfinite(U[i])) fail("knot " + std::to_string(i) + " is not finite");
  for (size_t i = 1; i < U.size(); ++i)
    if (U[i] < U[i - 1]) {
      std::ostringstream s;
      s << "knots decrease at index " << i << " (" << U[i - 1] << " > " << U[i] << ")";
      fail(s.str());
    }
  for (int i = 1; i <= p; ++i)
    if (U[i] != U[0] || U[n + i - 1] != U[n + p])
      fail("not open: first and last knot must each be repeated p + 1 = " + std::to_string(p + 1) +
           " times");
  if (!(U[p] < U[n])) fail("empty parameter domain");
  if (U[p + 1] == U[p] || U[n - 1] == U[n])
    fail("end knot repeated more than p + 1 = " + std::to_string(p + 1) + " times");
  // Interior multiplicity up to p + 1 (p + 1 makes the spline discontinuous).
  int run = 1;
  for (int i = p + 2; i < n; ++i) {
    run = (U[i] == U[i - 1]) ? run + 1 : 1;
    if (run > p + 1) {
      std::ostringstream s;
      s << "interior knot " << U[i] << " repeated more than p + 1 = " << p + 1 << " times";
      fail(s.str());
    }
  }
}

int find_span(const std::vector<double>& U, int p, double u) {
  const int n = static_cast<int>(U.size()) - p - 1;
  if (u >= U[n]) {
    int s = n - 1;
    while (s > p && U[s] == U[s + 1]) --s;
    return s;
  }
  if (u <= U[p]) return p;
  // Last s in [p, n-1] with U[s] <= u.
  auto it = std::upper_bound(U.begin() + p, U.begin() + n + 1, u);
  return static_cast<int>(it - U.begin()) - 1;
}

std::vector<double> uniform_knot_vector(int p, int n, double a, double b) {
  if (p < 0 || n < p + 1) throw bad_input("uniform_knot_vector: need n >= p + 1 >= 1");
  std::vector<double> U(n + p + 1);
  const int ne = n - p;  // number of elements
  for (int i = 0; i <= p; ++i) {
    U[i] = a;
    U[n + i] = b;
  }
  for (int i = 1; i < ne; ++i) U[p + i] = a + (b - a) * i / ne;
  return U;
}

std::vector<double> knot_vector_from_breaks(const std::vector<double>& breaks, int p,
                                            int interior_multiplicity) {
  if (breaks.size() < 2) throw bad_input("knot_vector_from_breaks: need at least two breakpoints");
  if (interior_multiplicity < 1 || interior_multiplicity > p + 1)
    throw bad_input("knot_vector_from_breaks: interior multiplicity must be in 1..p+1");
  for (size_t i = 1; i < breaks.size(); ++i)
    if (!(breaks[i] > breaks[i - 1]))
      throw bad_input("knot_vector_from_breaks: breakpoints must increase strictly");
  std::vector<double> U(p + 1, breaks.front());
  for (size_t i = 1; i + 1 < breaks.size(); ++i) U.insert(U.end(), interior_multiplicity, breaks[i]);
  U.insert(U.end(), p + 1, breaks.back());
  return U;
}

std::vector<double> unique_knots(const std::vector<double>& U) {
  std::vector<double> out;
  for (double u : U)
    if (out.empty() || u != out.back()) out.push_back(u);
  return out;
}

int knot_multiplicity(const std::vector<double>& U, double u) {
  return static_cast<int>(std::count(U.begin(), U.end(), u));
}

std::vector<double> greville_abscissae(const std::vector<double>& U, int p) {
  const int n = basis_count(U, p);
  std::vector<double> g(n);
  for (int i = 0; i < n; ++i) {
    if (p == 0) {
      g[i] = 0.5 * (U[i] + U[i + 1]);
      continue;
    }
    double s = 0;
    for (int j = 1; j <= p; ++j) s += U[i + j];
    g[i] = s / p;
  }
  return g;
}

}  // namespace igaprep::spline
