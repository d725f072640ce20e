// Unit tests of the helpers of the volume parameterization: the smoothing of
// sampled point grids (grid_smoothing.h), closest points on a triangle surface
// (surface_projector.h) and the sliding (u, v) of a sheet (sliding_uv.h).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "igaprep/core/error.h"
#include "igaprep/param/grid_smoothing.h"
#include "igaprep/param/inset_base.h"
#include "igaprep/param/polycube_2d.h"
#include "igaprep/param/sliding_uv.h"
#include "igaprep/param/surface_projector.h"
#include "test_midsurface_cache.h"

using namespace igaprep::param;

namespace {

// The pipeline's sample parameters (spline/src/block_fit.cpp,
// block_sample_params): the Greville abscissae of the clamped uniform cubic
// knot vector with 6 elements, each interval halved; 17 values from exactly 0
// to exactly 1, unevenly spaced (1/36 at the ends, 1/12 inside).
std::vector<double> sample_params() {
  const int p = 3, elements = 6;
  std::vector<double> U(p + 1, 0.0);
  for (int k = 1; k < elements; ++k) U.push_back(static_cast<double>(k) / elements);
  U.insert(U.end(), p + 1, 1.0);
  const int n = elements + p;
  std::vector<double> g(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    double s = 0.0;
    for (int k = 1; k <= p; ++k) s += U[static_cast<std::size_t>(i + k)];
    g[static_cast<std::size_t>(i)] = s / p;
  }
  std::vector<double> out;
  for (int i = 0; i + 1 < n; ++i) {
    out.push_back(g[static_cast<std::size_t>(i)]);
    out.push_back(0.5 * (g[static_cast<std::size_t>(i)] + g[static_cast<std::size_t>(i + 1)]));
  }
  out.push_back(1.0);
  out.front() = 0.0;
  return out;
}

// Deterministic pseudo-random numbers in [-1, 1] from an integer key (splitmix64).
double hash_unit(std::uint64_t key) {
  std::uint64_t z = key + 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  z ^= z >> 31;
  return 2.0 * (static_cast<double>(z >> 11) / 9007199254740992.0) - 1.0;
}

// A unit vector of pseudo-random direction, from an integer key.
Eigen::Vector3d hash_direction(std::uint64_t key) {
  for (std::uint64_t attempt = 0;; ++attempt) {
    const Eigen::Vector3d d(hash_unit(3 * (key * 64 + attempt)), hash_unit(3 * (key * 64 + attempt) + 1),
                            hash_unit(3 * (key * 64 + attempt) + 2));
    const double n = d.norm();
    if (n > 0.1 && n <= 1.0) return d / n;
  }
}

using Surface = std::function<Eigen::Vector3d(double, double)>;

// m x m grid (first index fastest) of f at params x params.
std::vector<Eigen::Vector3d> sample_grid(const Surface& f, const std::vector<double>& params) {
  const std::size_t m = params.size();
  std::vector<Eigen::Vector3d> g(m * m);
  for (std::size_t j = 0; j < m; ++j)
    for (std::size_t i = 0; i < m; ++i) g[i + m * j] = f(params[i], params[j]);
  return g;
}

double max_distance(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
  double d = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) d = std::max(d, (a[k] - b[k]).norm());
  return d;
}

double max_abs(const std::vector<Eigen::Vector3d>& a) {
  double d = 0.0;
  for (const auto& p : a) d = std::max(d, p.cwiseAbs().maxCoeff());
  return d;
}

void expect_bad_input(const std::function<void()>& call, const std::string& what) {
  try {
    call();
    ADD_FAILURE() << what << ": no exception";
  } catch (const igaprep::Error& e) {
    EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput) << what << ": " << e.what();
  }
}

}  // namespace

// ---------------------------------------------------------------------------
// grid_smoothing.h

TEST(GridSmoothing, SampleParamsAreThePipelines) {
  const auto t = sample_params();
  ASSERT_EQ(t.size(), 17u);
  EXPECT_EQ(t.front(), 0.0);
  EXPECT_EQ(t.back(), 1.0);
  EXPECT_NEAR(t[1], 1.0 / 36.0, 1e-15);
  EXPECT_NEAR(t[2], 1.0 / 18.0, 1e-15);
  EXPECT_NEAR(t[8], 0.5, 1e-15);
  for (std::size_t k = 1; k < t.size(); ++k) EXPECT_GT(t[k], t[k - 1]);
}

TEST(GridSmoothing, PolylineReproducesPolynomialsOfTheDegree) {
  const auto t = sample_params();
  for (int degree : {2, 3, 4, 6}) {
    // Coordinates: polynomials of degree exactly `degree` (and lower) in t.
    std::vector<Eigen::Vector3d> P;
    for (double s : t)
      P.emplace_back(0.3 + 2.0 * s, -1.0 + s - 1.7 * std::pow(s, degree) + 0.4 * s * s,
                     0.5 * std::pow(s - 0.3, degree) - 0.2 * std::pow(s, degree - 1));
    const auto out = smooth_polyline(P, t, degree);
    ASSERT_EQ(out.size(), P.size());
    const double scale = max_abs(P);
    EXPECT_LE(max_distance(out, P), 1e-12 * scale) << "degree " << degree;
    // One degree more is not in the space: the fit must change it (the
    // degree is honoured, the function is not the identity).
    std::vector<Eigen::Vector3d> Q = P;
    for (std::size_t k = 0; k < t.size(); ++k) Q[k](2) += std::pow(t[k], degree + 1);
    EXPECT_GT(max_distance(smooth_polyline(Q, t, degree), Q), 1e-6) << "degree " << degree;
  }
}

TEST(GridSmoothing, GridReproducesTensorPolynomialsOfTheDegree) {
  const auto t = sample_params();
  // Degree <= 4 in each of s and t.
  const Surface f = [](double s, double u) {
    return Eigen::Vector3d(s, u + 0.25 * s * s * u - 0.1 * std::pow(u, 4), s * s * std::pow(u, 3) - 0.3 * std::pow(s, 4));
  };
  const auto G = sample_grid(f, t);
  const double scale = max_abs(G);
  for (int degree : {4, 5, 6}) {
    const auto out = smooth_grid(G, t, degree);
    ASSERT_EQ(out.size(), G.size());
    EXPECT_LE(max_distance(out, G), 1e-12 * scale) << "degree " << degree;
  }
  // s^4 is not of degree 3: the fit moves the grid.
  EXPECT_GT(max_distance(smooth_grid(G, t, 3), G), 1e-6);
  // Degree 6 in both directions, with a mixed term of full degree.
  const Surface h = [](double s, double u) {
    return Eigen::Vector3d(std::pow(s, 6) * std::pow(u, 6) - s, 0.7 * std::pow(s - 0.5, 5) * u + u,
                           std::pow(s * u, 3) - 2.0 * std::pow(u, 6) * s * s);
  };
  const auto H = sample_grid(h, t);
  EXPECT_LE(max_distance(smooth_grid(H, t, 6), H), 1e-12 * max_abs(H));
}

TEST(GridSmoothing, EndsAndCornersAreKeptBitForBit) {
  const auto t = sample_params();
  const std::size_t m = t.size();
  // Noisy data, so that the fit really moves the inner samples.
  std::vector<Eigen::Vector3d> P;
  for (std::size_t k = 0; k < m; ++k)
    P.push_back(Eigen::Vector3d(std::cos(3.0 * t[k]), std::sin(2.0 * t[k]), t[k]) + 0.01 * hash_direction(k) +
                Eigen::Vector3d(1.0 / 3.0, 1e-7, -2.0 / 7.0));
  for (int degree : {2, 4, 6}) {
    const auto out = smooth_polyline(P, t, degree);
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(out.front()(c), P.front()(c));
      EXPECT_EQ(out.back()(c), P.back()(c));
    }
    EXPECT_GT(max_distance(out, P), 1e-4);  // the inside did move
  }
  const Surface f = [](double s, double u) {
    return Eigen::Vector3d(s + 0.1 * std::sin(4.0 * u), u, std::exp(s * u) / 3.0);
  };
  auto G = sample_grid(f, t);
  for (std::size_t k = 0; k < G.size(); ++k) G[k] += 0.01 * hash_direction(1000 + k);
  auto at = [&](std::size_t i, std::size_t j) { return i + m * j; };
  for (int degree : {3, 6}) {
    const auto out = smooth_grid(G, t, degree);
    for (std::size_t corner : {at(0, 0), at(m - 1, 0), at(0, m - 1), at(m - 1, m - 1)})
      for (int c = 0; c < 3; ++c) EXPECT_EQ(out[corner](c), G[corner](c)) << "corner " << corner;
    // Each side is the smoothed polyline of its own samples, bit for bit
    // (so its two ends are the grid's corners, unchanged).
    const std::vector<std::function<std::size_t(std::size_t)>> sides = {
        [&](std::size_t k) { return at(k, 0); }, [&](std::size_t k) { return at(k, m - 1); },
        [&](std::size_t k) { return at(0, k); }, [&](std::size_t k) { return at(m - 1, k); }};
    for (std::size_t s = 0; s < sides.size(); ++s) {
      std::vector<Eigen::Vector3d> side;
      for (std::size_t k = 0; k < m; ++k) side.push_back(G[sides[s](k)]);
      const auto expected = smooth_polyline(side, t, degree);
      for (std::size_t k = 0; k < m; ++k)
        for (int c = 0; c < 3; ++c) EXPECT_EQ(out[sides[s](k)](c), expected[k](c)) << "side " << s << " sample " << k;
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(out[sides[s](0)](c), G[sides[s](0)](c)) << "side " << s;
        EXPECT_EQ(out[sides[s](m - 1)](c), G[sides[s](m - 1)](c)) << "side " << s;
      }
    }
    EXPECT_GT(max_distance(out, G), 1e-4);  // the inside did move
  }
}

TEST(GridSmoothing, NeighbouringGridsGetTheSameSharedSide) {
  const auto t = sample_params();
  const std::size_t m = t.size();
  // One curved surface over [0, 2] x [0, 2] cut into three grids: A = [0, 1]^2,
  // B to its right, C above it. Noise keyed by the global sample, so a shared
  // side has the same samples in both grids.
  const Surface f = [](double s, double u) {
    return Eigen::Vector3d(std::sin(s), u + 0.2 * s * u, 0.3 * std::cos(1.3 * s + u));
  };
  auto grid = [&](int ox, int oy) {
    std::vector<Eigen::Vector3d> g(m * m);
    for (std::size_t j = 0; j < m; ++j)
      for (std::size_t i = 0; i < m; ++i) {
        const std::uint64_t gi = static_cast<std::uint64_t>(ox) * (m - 1) + i,
                            gj = static_cast<std::uint64_t>(oy) * (m - 1) + j;
        g[i + m * j] = f(ox + t[i], oy + t[j]) + 0.01 * hash_direction(gi + 1000 * gj);
      }
    return g;
  };
  const auto A = grid(0, 0), B = grid(1, 0), C = grid(0, 1);
  for (std::size_t k = 0; k < m; ++k) {
    ASSERT_EQ(A[(m - 1) + m * k], B[0 + m * k]);
    ASSERT_EQ(A[k + m * (m - 1)], C[k]);
  }
  // Kept: A's corners (0, 0) and (1, 0), the latter B's first corner too;
  // flagged alike wherever grids share them.
  const KeptCorners none, kept_a{{{true, true, false, false}}, 0.15}, kept_b{{{true, false, false, false}}, 0.15};
  for (const auto& [degree, ka, kb] : {std::tuple{3, none, none}, std::tuple{6, none, none}, std::tuple{6, kept_a, kept_b}}) {
    const auto a = smooth_grid(A, t, degree, ka), b = smooth_grid(B, t, degree, kb), c = smooth_grid(C, t, degree, none);
    double moved = 0.0;
    for (std::size_t k = 0; k < m; ++k) {
      for (int x = 0; x < 3; ++x) {
        EXPECT_EQ(a[(m - 1) + m * k](x), b[0 + m * k](x)) << "A right / B left, sample " << k;
        EXPECT_EQ(a[k + m * (m - 1)](x), c[k](x)) << "A top / C bottom, sample " << k;
      }
      moved = std::max(moved, (a[(m - 1) + m * k] - A[(m - 1) + m * k]).norm());
    }
    EXPECT_GT(moved, 1e-4);  // the shared side was smoothed, not merely kept
  }
}

TEST(GridSmoothing, ReducesNoise) {
  const auto t = sample_params();
  const std::size_t m = t.size();
  // A doubly curved patch (smooth, not a polynomial).
  const Surface f = [](double s, double u) {
    return Eigen::Vector3d(std::sin(0.9 * s), u + 0.1 * s * s, std::cos(0.9 * s) + 0.15 * std::sin(2.0 * u) * s);
  };
  // Distance from x to the noise-free surface: Gauss-Newton from (s, u).
  auto distance_to_surface = [&](const Eigen::Vector3d& x, double s, double u) {
    for (int it = 0; it < 20; ++it) {
      const double h = 1e-6;
      Eigen::Matrix<double, 3, 2> J;
      J.col(0) = (f(s + h, u) - f(s - h, u)) / (2.0 * h);
      J.col(1) = (f(s, u + h) - f(s, u - h)) / (2.0 * h);
      const Eigen::Vector2d step = (J.transpose() * J).ldlt().solve(J.transpose() * (f(s, u) - x));
      s -= step(0);
      u -= step(1);
    }
    return (f(s, u) - x).norm();
  };
  struct Error {
    double max = 0.0, rms = 0.0;
  };
  auto error = [&](const std::vector<Eigen::Vector3d>& g) {
    Error e;
    for (std::size_t k = 0; k < g.size(); ++k) {
      const double d = distance_to_surface(g[k], t[k % m], t[k / m]);
      e.max = std::max(e.max, d);
      e.rms += d * d;
    }
    e.rms = std::sqrt(e.rms / static_cast<double>(g.size()));
    return e;
  };
  const auto clean = sample_grid(f, t);
  ASSERT_LT(error(clean).max, 1e-12);
  // Noise: a pseudo-random direction times amplitude 1e-2 at every sample but
  // the four corners (they are kept bit for bit: a noisy corner stays noisy);
  // with noisy_sides false also not on the sides (the pipeline's faces keep
  // their already smoothed sides).
  const double amplitude = 1e-2;
  auto make_noisy = [&](bool noisy_sides) {
    auto g = clean;
    for (std::size_t j = 0; j < m; ++j)
      for (std::size_t i = 0; i < m; ++i) {
        const bool side = i == 0 || j == 0 || i == m - 1 || j == m - 1;
        const bool corner = (i == 0 || i == m - 1) && (j == 0 || j == m - 1);
        if (!corner && (noisy_sides || !side)) g[i + m * j] += amplitude * hash_direction(7 + i + 100 * j);
      }
    return g;
  };
  // Measured (this noise): max / rms distance to the surface, in units of the amplitude,
  //   noisy sides, degree 4: 0.33 / 0.14;  degree 6: 0.55 / 0.20;
  //   clean sides, degree 6: 0.40 / 0.14;  unsmoothed: 0.999 / 0.58.
  struct Case {
    bool noisy_sides;
    int degree;
    double max_bound, rms_bound;  // in units of the amplitude
  };
  for (const Case c : {Case{true, 4, 0.45, 0.2}, Case{true, 6, 0.75, 0.3}, Case{false, 6, 0.5, 0.2}}) {
    const auto noisy = make_noisy(c.noisy_sides);
    const Error before = error(noisy);
    ASSERT_GT(before.max, 0.99 * amplitude);  // unsmoothed, every bound below fails
    ASSERT_GT(before.rms, 0.5 * amplitude);
    const Error after = error(smooth_grid(noisy, t, c.degree));
    const std::string name = std::string(c.noisy_sides ? "noisy" : "clean") + "_sides_degree_" + std::to_string(c.degree);
    RecordProperty(name + "_max", std::to_string(after.max / amplitude));
    RecordProperty(name + "_rms", std::to_string(after.rms / amplitude));
    EXPECT_LT(after.max, c.max_bound * amplitude) << name;
    EXPECT_LT(after.rms, c.rms_bound * amplitude) << name;
  }
}

// The fits are least-squares fits: computed here independently, with
// monomial bubbles t (1 - t) t^a and a dense QR.
TEST(GridSmoothing, FitsAreLeastSquares) {
  const auto t = sample_params();
  const std::size_t m = t.size();
  const int inner = static_cast<int>(m) - 2;
  for (int degree : {2, 3, 4, 6}) {
    const int nb = degree - 1;
    auto bubble = [&](double x, int a) { return x * (1.0 - x) * std::pow(x, a); };
    // Polyline.
    std::vector<Eigen::Vector3d> P;
    for (std::size_t k = 0; k < m; ++k)
      P.push_back(Eigen::Vector3d(std::exp(t[k]), std::sin(3.0 * t[k]), t[k] * t[k]) + 0.01 * hash_direction(300 + k));
    Eigen::MatrixXd A(inner, nb), rhs(inner, 3);
    for (int k = 1; k <= inner; ++k) {
      const double x = t[static_cast<std::size_t>(k)];
      for (int a = 0; a < nb; ++a) A(k - 1, a) = bubble(x, a);
      rhs.row(k - 1) = (P[static_cast<std::size_t>(k)] - (1.0 - x) * P.front() - x * P.back()).transpose();
    }
    const Eigen::MatrixXd fit = A * A.householderQr().solve(rhs);
    const auto out = smooth_polyline(P, t, degree);
    double worst = 0.0;
    for (int k = 1; k <= inner; ++k) {
      const double x = t[static_cast<std::size_t>(k)];
      const Eigen::Vector3d expected = (1.0 - x) * P.front() + x * P.back() + fit.row(k - 1).transpose();
      worst = std::max(worst, (out[static_cast<std::size_t>(k)] - expected).norm());
    }
    EXPECT_LT(worst, 1e-11) << "polyline, degree " << degree;
    // Grid: the Coons patch of the (smoothed) sides plus the tensor bubbles fitted to the rest.
    const Surface f = [](double s, double u) {
      return Eigen::Vector3d(s + 0.2 * std::cos(2.0 * u), u * std::exp(0.5 * s), std::sin(2.0 * s * u));
    };
    auto G = sample_grid(f, t);
    for (std::size_t k = 0; k < G.size(); ++k) G[k] += 0.01 * hash_direction(2000 + k);
    const auto g = smooth_grid(G, t, degree);
    auto at = [&](std::size_t i, std::size_t j) { return i + m * j; };
    auto coons = [&](std::size_t i, std::size_t j) {
      const double s = t[i], u = t[j];
      return Eigen::Vector3d((1 - u) * g[at(i, 0)] + u * g[at(i, m - 1)] + (1 - s) * g[at(0, j)] + s * g[at(m - 1, j)] -
                             (1 - s) * (1 - u) * g[at(0, 0)] - s * (1 - u) * g[at(m - 1, 0)] -
                             (1 - s) * u * g[at(0, m - 1)] - s * u * g[at(m - 1, m - 1)]);
    };
    Eigen::MatrixXd B(inner * inner, nb * nb), r(inner * inner, 3);
    int row = 0;
    for (std::size_t j = 1; j + 1 < m; ++j)
      for (std::size_t i = 1; i + 1 < m; ++i, ++row) {
        for (int b = 0; b < nb; ++b)
          for (int a = 0; a < nb; ++a) B(row, a + nb * b) = bubble(t[i], a) * bubble(t[j], b);
        r.row(row) = (G[at(i, j)] - coons(i, j)).transpose();
      }
    const Eigen::MatrixXd gfit = B * B.householderQr().solve(r);
    worst = 0.0;
    row = 0;
    for (std::size_t j = 1; j + 1 < m; ++j)
      for (std::size_t i = 1; i + 1 < m; ++i, ++row)
        worst = std::max(worst, (g[at(i, j)] - coons(i, j) - gfit.row(row).transpose()).norm());
    EXPECT_LT(worst, 1e-11) << "grid, degree " << degree;
  }
}

// KeptCorners: within end_share of a side's parameters from a kept corner the side is
// (1 - w) smoothed + w sampled, w = (1 - d / share)^2 at distance d; farther
// in it is the plain smoothed side bit for bit. ring2's lid, sampled, bends
// at its outer layout corners within two samples (its height dips by 0.0025
// at the first sample), which the plain polynomial irons out, opening the
// corner from 102 to 130 degrees.
TEST(GridSmoothing, EndShareKeepsTheSamplesNearTheCorners) {
  const auto t = sample_params();
  const std::size_t m = t.size();
  const double share = 0.15;
  const Surface f = [](double s, double u) { return Eigen::Vector3d(s, u, 0.1 * std::sin(2.0 * s + u)); };
  auto G = sample_grid(f, t);
  G[1](2) -= 0.01;  // a bend at the corner (0, 0), along the side j = 0
  G[2](2) -= 0.005;
  const auto plain = smooth_grid(G, t, 6), kept = smooth_grid(G, t, 6, {{{true, false, false, false}}, share});
  for (std::size_t k = 0; k < m; ++k) {
    const double d = t[k];  // only the corner (0, 0) is kept
    if (d >= share) {
      EXPECT_EQ(kept[k], plain[k]) << "side j = 0, sample " << k;
      continue;
    }
    const double w = (1.0 - d / share) * (1.0 - d / share);
    EXPECT_LE((kept[k] - ((1.0 - w) * plain[k] + w * G[k])).norm(), 1e-15) << "side j = 0, sample " << k;
  }
  // The bend survives: the first sample along the side keeps most of its dip.
  EXPECT_LT(kept[1](2) - f(t[1], 0.0)(2), -0.005);
  EXPECT_GT(plain[1](2) - f(t[1], 0.0)(2), -0.004);
  // The other end of the side, not kept, is smoothed as without.
  EXPECT_EQ(kept[m - 2], plain[m - 2]);
  EXPECT_THROW(smooth_grid(G, t, 6, {{{true, false, false, false}}, 0.6}), igaprep::Error);
  EXPECT_THROW(smooth_grid(G, t, 6, {{{true, false, false, false}}, -0.1}), igaprep::Error);
}

TEST(GridSmoothing, RejectsBadInput) {
  const auto t = sample_params();
  const std::size_t m = t.size();
  std::vector<Eigen::Vector3d> line(m, Eigen::Vector3d(1.0, 2.0, 3.0));
  std::vector<Eigen::Vector3d> grid(m * m, Eigen::Vector3d(1.0, 2.0, 3.0));
  // Fewer than 3 parameters.
  const std::vector<double> two = {0.0, 1.0};
  expect_bad_input([&] { smooth_polyline({Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()}, two, 2); },
                   "polyline, 2 params");
  expect_bad_input([&] { smooth_grid(std::vector<Eigen::Vector3d>(4, Eigen::Vector3d::Zero()), two, 2); },
                   "grid, 2 params");
  expect_bad_input([&] { smooth_polyline({}, {}, 2); }, "polyline, no params");
  // Parameters not from 0 to 1.
  auto shifted = t;
  shifted.front() = 1e-3;
  expect_bad_input([&] { smooth_polyline(line, shifted, 3); }, "polyline, params from 1e-3");
  expect_bad_input([&] { smooth_grid(grid, shifted, 3); }, "grid, params from 1e-3");
  auto short_end = t;
  short_end.back() = 0.999;
  expect_bad_input([&] { smooth_polyline(line, short_end, 3); }, "polyline, params to 0.999");
  expect_bad_input([&] { smooth_grid(grid, short_end, 3); }, "grid, params to 0.999");
  // Size mismatch.
  expect_bad_input([&] { smooth_polyline(std::vector<Eigen::Vector3d>(m - 1, Eigen::Vector3d::Zero()), t, 3); },
                   "polyline, m - 1 points");
  expect_bad_input([&] { smooth_polyline(std::vector<Eigen::Vector3d>(m + 1, Eigen::Vector3d::Zero()), t, 3); },
                   "polyline, m + 1 points");
  expect_bad_input([&] { smooth_grid(std::vector<Eigen::Vector3d>(m * (m - 1), Eigen::Vector3d::Zero()), t, 3); },
                   "grid, m (m - 1) points");
  expect_bad_input([&] { smooth_grid(line, t, 3); }, "grid, m points");
  // Degree below 2.
  for (int degree : {1, 0, -3}) {
    expect_bad_input([&] { smooth_polyline(line, t, degree); }, "polyline, degree " + std::to_string(degree));
    expect_bad_input([&] { smooth_grid(grid, t, degree); }, "grid, degree " + std::to_string(degree));
  }
  // The smallest valid input is accepted.
  EXPECT_NO_THROW(smooth_polyline(std::vector<Eigen::Vector3d>(3, Eigen::Vector3d::Ones()), {0.0, 0.5, 1.0}, 2));
}

// smooth_polyline with m x m points (a grid's worth) for m parameters is a
// size mismatch like any other. DISABLED: it fails today. check_inputs in
// param/src/grid_smoothing.cpp accepts m or m^2 points for both functions, so
// smooth_polyline takes m^2 points, uses points.back() as the end, and returns
// m^2 points of which all but m are uninitialized. Enable with the fix.
TEST(GridSmoothing, PolylineRejectsAGridsWorthOfPoints) {
  const auto t = sample_params();
  const std::size_t m = t.size();
  std::vector<Eigen::Vector3d> grid(m * m, Eigen::Vector3d(1.0, 2.0, 3.0));
  expect_bad_input([&] { smooth_polyline(grid, t, 3); }, "polyline, m^2 points");
}

// ---------------------------------------------------------------------------
// surface_projector.h

namespace {

// Closest point to p on triangle abc (Ericson, Real-Time Collision Detection 5.1.5).
Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                    const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

double brute_force_distance(const Eigen::Vector3d& p, const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  double d = 1e300;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    d = std::min(d, (p - closest_on_triangle(p, V.row(F(f, 0)), V.row(F(f, 1)), V.row(F(f, 2)))).norm());
  return d;
}

// Icosahedron subdivided `levels` times, vertices on the unit sphere.
void icosphere(int levels, Eigen::MatrixXd& V, Eigen::MatrixXi& F) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> v = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                                    {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  std::vector<Eigen::Vector3i> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                    {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                    {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                    {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (auto& x : v) x.normalize();
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      v.push_back((v[static_cast<std::size_t>(a)] + v[static_cast<std::size_t>(b)]).normalized());
      return mid[key] = static_cast<int>(v.size()) - 1;
    };
    std::vector<Eigen::Vector3i> next;
    for (const auto& t : f) {
      const int ab = midpoint(t(0), t(1)), bc = midpoint(t(1), t(2)), ca = midpoint(t(2), t(0));
      next.push_back({t(0), ab, ca});
      next.push_back({t(1), bc, ab});
      next.push_back({t(2), ca, bc});
      next.push_back({ab, bc, ca});
    }
    f = next;
  }
  V.resize(static_cast<Eigen::Index>(v.size()), 3);
  for (std::size_t k = 0; k < v.size(); ++k) V.row(static_cast<Eigen::Index>(k)) = v[k].transpose();
  F.resize(static_cast<Eigen::Index>(f.size()), 3);
  for (std::size_t k = 0; k < f.size(); ++k) F.row(static_cast<Eigen::Index>(k)) = f[k].transpose();
}

// The unit square [0, 1]^2 at z = 0, n x n cells, two triangles each.
void flat_square(int n, Eigen::MatrixXd& V, Eigen::MatrixXi& F) {
  V.resize((n + 1) * (n + 1), 3);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) V.row(i + (n + 1) * j) << static_cast<double>(i) / n, static_cast<double>(j) / n, 0.0;
  F.resize(2 * n * n, 3);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = i + (n + 1) * j, b = a + 1, c = a + (n + 1), d = c + 1;
      F.row(2 * (i + n * j)) << a, b, d;
      F.row(2 * (i + n * j) + 1) << a, d, c;
    }
}

}  // namespace

TEST(SurfaceProjector, FlatSquareProjectsAlongTheNormal) {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  flat_square(4, V, F);
  const SurfaceProjector proj(V, F);
  for (int k = 0; k < 200; ++k) {
    const double x = 0.5 + 0.5 * hash_unit(10 * k), y = 0.5 + 0.5 * hash_unit(10 * k + 1),
                 z = 2.0 * hash_unit(10 * k + 2);
    const Eigen::Vector3d q = proj.closest({x, y, z});
    EXPECT_NEAR(q.x(), x, 1e-12);
    EXPECT_NEAR(q.y(), y, 1e-12);
    EXPECT_NEAR(q.z(), 0.0, 1e-12);
  }
  // Outside the square in (x, y): the nearest point of a convex planar region
  // is (x, y) clamped to it.
  for (int k = 0; k < 200; ++k) {
    const double x = 0.5 + 1.5 * hash_unit(20 * k + 3), y = 0.5 + 1.5 * hash_unit(20 * k + 4),
                 z = hash_unit(20 * k + 5);
    const Eigen::Vector3d q = proj.closest({x, y, z});
    EXPECT_NEAR(q.x(), std::clamp(x, 0.0, 1.0), 1e-12) << x << " " << y << " " << z;
    EXPECT_NEAR(q.y(), std::clamp(y, 0.0, 1.0), 1e-12) << x << " " << y << " " << z;
    EXPECT_NEAR(q.z(), 0.0, 1e-12);
  }
}

// slide keeps a point's signed distance from the surface: 0.1 above the flat
// square, moved anywhere over it, it lands 0.1 above the point below `to`.
TEST(SurfaceProjector, SlideKeepsTheOffset) {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  flat_square(4, V, F);
  const SurfaceProjector proj(V, F);
  int tri = -1;
  proj.closest({0.3, 0.3, 1.0}, &tri);
  EXPECT_NEAR(std::abs(proj.normal(tri).z()), 1.0, 1e-12);
  for (int k = 0; k < 50; ++k) {
    const Eigen::Vector3d from(0.5 + 0.5 * hash_unit(40 * k), 0.5 + 0.5 * hash_unit(40 * k + 1), 0.1);
    const Eigen::Vector3d to(0.5 + 0.5 * hash_unit(40 * k + 2), 0.5 + 0.5 * hash_unit(40 * k + 3),
                             0.25 * hash_unit(40 * k + 4));
    const Eigen::Vector3d y = proj.slide(from, to);
    EXPECT_NEAR(y.x(), to.x(), 1e-12);
    EXPECT_NEAR(y.y(), to.y(), 1e-12);
    EXPECT_NEAR(y.z(), 0.1, 1e-12);
  }
}

TEST(SurfaceProjector, IcosphereMatchesBruteForce) {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  icosphere(2, V, F);
  ASSERT_EQ(F.rows(), 320);
  SurfaceProjector moved_from(V, F);
  const SurfaceProjector proj = std::move(moved_from);  // the move keeps the tree
  double worst_gap = 0.0, worst_on = 0.0, worst_point = 0.0;
  int compared = 0;
  for (int k = 0; k < 300; ++k) {
    const Eigen::Vector3d p(1.6 * hash_unit(30 * k + 7), 1.6 * hash_unit(30 * k + 8), 1.6 * hash_unit(30 * k + 9));
    const Eigen::Vector3d q = proj.closest(p);
    const double d = brute_force_distance(p, V, F);
    // As near as the nearest triangle, and on the surface.
    worst_gap = std::max(worst_gap, std::abs((p - q).norm() - d));
    worst_on = std::max(worst_on, brute_force_distance(q, V, F));
    // The brute-force closest point itself, where it is unique (p away from
    // the centre, where every triangle is about as near).
    if (p.norm() > 0.3) {
      Eigen::Vector3d best = Eigen::Vector3d::Zero();
      double bd = 1e300;
      for (Eigen::Index f = 0; f < F.rows(); ++f) {
        const Eigen::Vector3d c = closest_on_triangle(p, V.row(F(f, 0)), V.row(F(f, 1)), V.row(F(f, 2)));
        if ((p - c).norm() < bd) bd = (p - c).norm(), best = c;
      }
      worst_point = std::max(worst_point, (q - best).norm());
      ++compared;
    }
  }
  EXPECT_GT(compared, 200);
  EXPECT_LT(worst_gap, 1e-12);
  EXPECT_LT(worst_on, 1e-12);
  EXPECT_LT(worst_point, 1e-10);
  // A point on the surface is its own closest point.
  for (Eigen::Index v = 0; v < V.rows(); v += 7) {
    const Eigen::Vector3d p = V.row(v).transpose();
    EXPECT_LT((proj.closest(p) - p).norm(), 1e-14);
  }
}

TEST(SurfaceProjector, RejectsBadInput) {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  flat_square(2, V, F);
  expect_bad_input([&] { SurfaceProjector(V, Eigen::MatrixXi(0, 3)); }, "no triangles");
  Eigen::MatrixXi G = F;
  G(3, 1) = static_cast<int>(V.rows());
  expect_bad_input([&] { SurfaceProjector(V, G); }, "vertex index #V");
  G = F;
  G(0, 2) = -1;
  expect_bad_input([&] { SurfaceProjector(V, G); }, "vertex index -1");
  expect_bad_input([&] { SurfaceProjector(V, Eigen::MatrixXi(F.leftCols(2))); }, "two columns");
  EXPECT_NO_THROW(SurfaceProjector(V, F));
}

// ---------------------------------------------------------------------------
// sliding_uv.h

namespace {

struct CornerAngles {
  std::vector<double> degrees;  // angle between the iso-lines at each inset corner
  double mean_deviation = 0.0;  // mean |90 - angle|
};

// The angle in 3D between the iso-lines u = c and v = c of a map uv of S at
// the points of the pipeline's inset corners of the outer rectangle.
CornerAngles corner_angles_at(const igaprep::mesh::TriMesh& S, const Eigen::MatrixXd& uv, const RectilinearDomain& D, double m0) {
  const double d = m0 * 0.5 * narrowest_band(D);
  const double W = D.width, H = D.height;
  const std::vector<Eigen::Vector2d> points = {{d, d}, {W - d, d}, {d, H - d}, {W - d, H - d}};
  CornerAngles out;
  for (const Eigen::Vector2d& x : points) {
    // Brute-force location: the triangle with the largest smallest barycentric coordinate.
    Eigen::Index best = -1;
    double best_min = -1e300;
    for (Eigen::Index f = 0; f < S.F.rows(); ++f) {
      const Eigen::Vector2d a = uv.row(S.F(f, 0)), b = uv.row(S.F(f, 1)), c = uv.row(S.F(f, 2));
      const double area = (b - a)(0) * (c - a)(1) - (c - a)(0) * (b - a)(1);
      if (!(area > 0.0)) continue;
      const double l1 = ((b - x)(0) * (c - x)(1) - (c - x)(0) * (b - x)(1)) / area;
      const double l2 = ((c - x)(0) * (a - x)(1) - (a - x)(0) * (c - x)(1)) / area;
      const double l3 = 1.0 - l1 - l2;
      const double mn = std::min({l1, l2, l3});
      if (mn > best_min) best_min = mn, best = f;
    }
    EXPECT_GT(best_min, -1e-9) << "(" << x.transpose() << ") in no triangle";
    const Eigen::Vector3d p0 = S.V.row(S.F(best, 0)), p1 = S.V.row(S.F(best, 1)), p2 = S.V.row(S.F(best, 2));
    const Eigen::Vector3d e1 = p1 - p0, e2 = p2 - p0;
    Eigen::Matrix2d G;
    G << e1.dot(e1), e1.dot(e2), e1.dot(e2), e2.dot(e2);
    Eigen::Vector3d grad[2];
    for (int c = 0; c < 2; ++c) {
      const Eigen::Vector2d df(uv(S.F(best, 1), c) - uv(S.F(best, 0), c), uv(S.F(best, 2), c) - uv(S.F(best, 0), c));
      const Eigen::Vector2d a = G.ldlt().solve(df);
      grad[c] = a(0) * e1 + a(1) * e2;
    }
    const double cosine = grad[0].dot(grad[1]) / (grad[0].norm() * grad[1].norm());
    const double angle = std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / M_PI;
    out.degrees.push_back(angle);
    out.mean_deviation += std::abs(90.0 - angle) / static_cast<double>(points.size());
  }
  return out;
}

CornerAngles corner_angles(const igaprep::mesh::TriMesh& S, const Eigen::MatrixXd& uv, const RectilinearDomain& D) {
  return corner_angles_at(S, uv, D, 0.3);
}

std::string join(const std::vector<double>& x) {
  std::ostringstream s;
  s.precision(4);
  for (std::size_t k = 0; k < x.size(); ++k) s << (k ? " " : "") << x[k];
  return s.str();
}

// The automatic cut of each model (sphere2, ring2, torus3).
std::vector<midsurface_test::Variant> auto_variants() {
  std::vector<midsurface_test::Variant> out;
  for (const auto& v : midsurface_test::kVariants)
    if (v.variant == "auto") out.push_back(v);
  return out;
}

class SlidingUvModels : public ::testing::TestWithParam<midsurface_test::Variant> {};

}  // namespace

TEST_P(SlidingUvModels, ValidOnTheDomainAndCloserToOrthogonalAtTheCorners) {
  const auto& r = midsurface_test::cached(GetParam().model, GetParam().variant).result;
  const auto& S = r.m0trim.mesh;
  const Polycube2D& pc = r.polycube;
  ASSERT_EQ(pc.uv.rows(), S.V.rows());
  const SlidingUv su = sliding_uv(S, pc);
  ASSERT_TRUE(su.valid) << su.reason;
  EXPECT_TRUE(su.reason.empty());
  ASSERT_EQ(su.uv.rows(), S.V.rows());
  ASSERT_EQ(su.uv.cols(), 2);
  // Every triangle positively oriented, and min_jacobian is the smallest.
  const Eigen::VectorXd jac = uv_jacobians(S, su.uv);
  EXPECT_GT(jac.minCoeff(), 0.0);
  EXPECT_NEAR(su.min_jacobian, jac.minCoeff(), 1e-12 * jac.cwiseAbs().maxCoeff());
  EXPECT_GE(su.min_sliding_share, 0.0);
  EXPECT_LE(su.min_sliding_share, 1.0);
  RecordProperty("min_sliding_share", std::to_string(su.min_sliding_share));
  // The image tiles the domain: total (u, v) area = W H - holes.
  double total = 0.0;
  for (Eigen::Index f = 0; f < S.F.rows(); ++f) {
    const Eigen::Vector2d a = su.uv.row(S.F(f, 0)), b = su.uv.row(S.F(f, 1)), c = su.uv.row(S.F(f, 2));
    total += 0.5 * ((b - a)(0) * (c - a)(1) - (c - a)(0) * (b - a)(1));
  }
  double domain_area = pc.domain.width * pc.domain.height;
  for (const auto& h : pc.domain.holes) domain_area -= (h(2) - h(0)) * (h(3) - h(1));
  EXPECT_NEAR(total, domain_area, 1e-9 * domain_area);
  // Each boundary vertex exactly on its side, the side's vertices in order
  // along it, the ends (the corners) where polycube.uv has them.
  for (std::size_t k = 0; k < pc.segments.size(); ++k) {
    const BoundarySegment& s = pc.segments[k];
    const int iso = s.u_iso ? 0 : 1, free = 1 - iso;
    ASSERT_GE(s.vertices.size(), 2u);
    for (int v : s.vertices) EXPECT_EQ(su.uv(v, iso), s.value) << "segment " << k << " vertex " << v;
    const double first = su.uv(s.vertices.front(), free), last = su.uv(s.vertices.back(), free);
    EXPECT_EQ(first, pc.uv(s.vertices.front(), free)) << "segment " << k;
    EXPECT_EQ(last, pc.uv(s.vertices.back(), free)) << "segment " << k;
    const double dir = last > first ? 1.0 : -1.0;
    EXPECT_NE(first, last) << "segment " << k;
    int out_of_order = 0;
    for (std::size_t i = 1; i < s.vertices.size(); ++i)
      if (!(dir * (su.uv(s.vertices[i], free) - su.uv(s.vertices[i - 1], free)) > 0.0)) ++out_of_order;
    EXPECT_EQ(out_of_order, 0) << "segment " << k << " (" << to_string(s.side) << ")";
  }
  // The iso-lines at the inset corners of the outer rectangle.
  const CornerAngles before = corner_angles(S, pc.uv, pc.domain);
  const CornerAngles after = corner_angles(S, su.uv, pc.domain);
  RecordProperty("polycube_uv_corner_angles", join(before.degrees));
  RecordProperty("sliding_uv_corner_angles", join(after.degrees));
  RecordProperty("polycube_uv_mean_deviation", std::to_string(before.mean_deviation));
  RecordProperty("sliding_uv_mean_deviation", std::to_string(after.mean_deviation));
  // Measured mean |90 - angle| (polycube.uv -> sliding): sphere2 33.9 -> 18.4,
  // ring2 46.7 -> 35.4, torus3 30.5 -> 16.2 degrees. Bounds: about 5 degrees
  // above the sliding value, below the polycube.uv one.
  const std::map<std::string, double> bound = {{"sphere2", 24.0}, {"ring2", 41.0}, {"torus3", 22.0}};
  ASSERT_EQ(bound.count(GetParam().model), 1u);
  EXPECT_LT(before.mean_deviation, 90.0);
  EXPECT_LT(after.mean_deviation, before.mean_deviation);
  EXPECT_LT(after.mean_deviation, 0.85 * before.mean_deviation);
  EXPECT_LT(after.mean_deviation, bound.at(GetParam().model));
  EXPECT_GT(before.mean_deviation, bound.at(GetParam().model));  // the bound separates the two maps
}

INSTANTIATE_TEST_SUITE_P(SlidingUv, SlidingUvModels,
                         ::testing::ValuesIn(auto_variants()),
                         midsurface_test::variant_name);
