#include "igaprep/iga_check/jacobian_certificate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <queue>
#include <string>

#include "igaprep/core/error.h"
#include "igaprep/core/parallel.h"
#include "igaprep/core/progress.h"

namespace igaprep::iga_check {

const char* to_string(ElementStatus s) {
  switch (s) {
    case ElementStatus::Positive: return "positive";
    case ElementStatus::Negative: return "negative";
    case ElementStatus::Degenerate: return "degenerate";
    case ElementStatus::Undecided: return "undecided";
  }
  return "undecided";
}

namespace {

// A polynomial together with its magnitude (the same expression evaluated on
// absolute values, with every subtraction an addition): |rounding error| of a
// coefficient is a small multiple of eps times its magnitude.
struct Tracked {
  Bernstein3 v, m;
};

Tracked tracked(const Bernstein3& v) {
  Tracked t{v, v};
  for (double& c : t.m.coeffs) c = std::abs(c);
  return t;
}

Tracked derivative(const Tracked& a, int dir) {
  Tracked r{bernstein_derivative(a.v, dir), Bernstein3()};
  // magnitude: deg * (|c_{i+1}| + |c_i|): the derivative of the magnitudes
  // with the sign of the low term flipped, i.e. deg * c_{i+1} + deg * c_i.
  std::array<int, 3> deg = a.m.degree;
  const int p = deg[dir];
  if (p == 0) {
    r.m = Bernstein3(deg, 0.0);
    return r;
  }
  deg[dir] = p - 1;
  r.m = Bernstein3(deg, 0.0);
  for (int k = 0; k < r.m.size(2); ++k)
    for (int j = 0; j < r.m.size(1); ++j)
      for (int i = 0; i < r.m.size(0); ++i) {
        std::array<int, 3> n{{i, j, k}};
        n[dir] += 1;
        r.m(i, j, k) = p * (a.m(n[0], n[1], n[2]) + a.m(i, j, k));
      }
  return r;
}

Tracked mul(const Tracked& a, const Tracked& b) {
  return {bernstein_product(a.v, b.v), bernstein_product(a.m, b.m)};
}

Tracked add(const Tracked& a, double s, const Tracked& b) {
  return {bernstein_axpy(a.v, s, b.v), bernstein_axpy(a.m, std::abs(s), b.m)};
}

// a . (b x c) for vectors of polynomials (each vector's components share a degree).
Tracked triple(const std::array<Tracked, 3>& a, const std::array<Tracked, 3>& b,
               const std::array<Tracked, 3>& c) {
  Tracked result;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    Tracked cross = add(mul(b[j], c[k]), -1.0, mul(b[k], c[j]));
    Tracked term = mul(a[i], cross);
    result = i == 0 ? term : add(result, 1.0, term);
  }
  return result;
}

std::array<Tracked, 3> derivative(const std::array<Tracked, 3>& a, int dir) {
  return {derivative(a[0], dir), derivative(a[1], dir), derivative(a[2], dir)};
}

Bernstein3 component(const Eigen::MatrixXd& pts, int col, const std::array<int, 3>& degrees,
                     const Eigen::VectorXd* scale) {
  Bernstein3 b(degrees, 0.0);
  if (static_cast<size_t>(pts.rows()) != b.coeffs.size())
    throw internal_error("jacobian_numerator: element has " + std::to_string(pts.rows()) +
                         " control points, degrees need " + std::to_string(b.coeffs.size()));
  for (int i = 0; i < pts.rows(); ++i) b.coeffs[i] = (col < 0 ? 1.0 : pts(i, col)) * (scale ? (*scale)[i] : 1.0);
  return b;
}

struct Box {
  Bernstein3 c;
  Eigen::Vector3d lo, hi;
  int depth = 0;
  double minc = 0.0;
};
struct BoxOrder {
  bool operator()(const Box& a, const Box& b) const { return a.minc > b.minc; }
};

double min_coeff(const Bernstein3& b, int* arg = nullptr) {
  auto it = std::min_element(b.coeffs.begin(), b.coeffs.end());
  if (arg) *arg = static_cast<int>(it - b.coeffs.begin());
  return *it;
}

// det J >= 0 on the box and > 0 except on the element's boundary: every
// coefficient >= -tol and every coefficient not on a box face that lies on the
// element boundary > tol. (At a point off the element boundary some Bernstein
// function with a strictly positive coefficient is non-zero.)
bool positive_except_boundary(const Box& box, double tol) {
  const Bernstein3& c = box.c;
  for (int k = 0; k < c.size(2); ++k)
    for (int j = 0; j < c.size(1); ++j)
      for (int i = 0; i < c.size(0); ++i) {
        const double v = c(i, j, k);
        if (v < -tol) return false;
        const std::array<int, 3> idx{{i, j, k}};
        bool exempt = false;
        for (int d = 0; d < 3; ++d)
          if ((idx[d] == 0 && box.lo[d] == 0.0) || (idx[d] == c.degree[d] && box.hi[d] == 1.0)) exempt = true;
        if (!exempt && v <= tol) return false;
      }
  return true;
}

int split_direction(const Bernstein3& c) {
  std::array<double, 3> var{{0, 0, 0}};
  const std::array<int, 3> stride{{1, c.size(0), c.size(0) * c.size(1)}};
  for (int k = 0; k < c.size(2); ++k)
    for (int j = 0; j < c.size(1); ++j)
      for (int i = 0; i < c.size(0); ++i) {
        const std::array<int, 3> idx{{i, j, k}};
        const int at = c.index(i, j, k);
        for (int d = 0; d < 3; ++d)
          if (idx[d] < c.degree[d]) var[d] = std::max(var[d], std::abs(c.coeffs[at + stride[d]] - c.coeffs[at]));
      }
  int best = 0;
  for (int d = 1; d < 3; ++d)
    if (var[d] > var[best]) best = d;
  return best;
}

}  // namespace

Bernstein3 jacobian_numerator(const spline::BezierElement& e, const std::array<int, 3>& degrees,
                              Bernstein3* magnitude) {
  // det J does not change under translation: centre the points so that the
  // magnitudes measure the element, not its distance from the origin.
  Eigen::MatrixXd pts = e.points;
  const Eigen::RowVector3d centre = pts.colwise().mean();
  pts.rowwise() -= centre;
  Tracked N;
  if (e.weights.size() == 0) {
    std::array<Tracked, 3> x;
    for (int c = 0; c < 3; ++c) x[c] = tracked(component(pts, c, degrees, nullptr));
    N = triple(derivative(x, 0), derivative(x, 1), derivative(x, 2));
  } else {
    std::array<Tracked, 3> P;
    for (int c = 0; c < 3; ++c) P[c] = tracked(component(pts, c, degrees, &e.weights));
    const Tracked w = tracked(component(pts, -1, degrees, &e.weights));
    const auto Pu = derivative(P, 0), Pv = derivative(P, 1), Pw = derivative(P, 2);
    // Laplace expansion of the 4 x 4 determinant along the weight row.
    N = mul(w, triple(Pu, Pv, Pw));
    N = add(N, -1.0, mul(derivative(w, 0), triple(P, Pv, Pw)));
    N = add(N, 1.0, mul(derivative(w, 1), triple(P, Pu, Pw)));
    N = add(N, -1.0, mul(derivative(w, 2), triple(P, Pu, Pv)));
  }
  if (magnitude) *magnitude = N.m;
  return N.v;
}

ElementCertificate certify_element(const spline::BezierElement& e, const std::array<int, 3>& degrees,
                                   const CertifyOptions& options, int patch,
                                   const std::array<int, 3>& element) {
  ElementCertificate cert;
  cert.patch = patch;
  cert.element = element;
  for (int d = 0; d < 3; ++d)
    if (degrees[d] < 1)
      throw bad_input("patch " + std::to_string(patch) + ": degree 0 in direction " + std::to_string(d) +
                      " has no Jacobian");
  double wmin = 1.0, wmax = 1.0;
  Bernstein3 wpoly;
  const bool rational = e.weights.size() > 0;
  if (rational) {
    wmin = e.weights.minCoeff();
    wmax = e.weights.maxCoeff();
    if (!(wmin > 0.0))
      throw bad_input("patch " + std::to_string(patch) + ": element has a non-positive weight");
    wpoly = component(e.points, -1, degrees, &e.weights);
  }
  // det J with respect to patch parameters = det J(t) / (h_u h_v h_w).
  double h = 1.0;
  for (int d = 0; d < 3; ++d) h *= e.domain[d][1] - e.domain[d][0];
  if (!(h > 0.0)) throw bad_input("patch " + std::to_string(patch) + ": empty element");

  Bernstein3 mag;
  Bernstein3 N = jacobian_numerator(e, degrees, &mag);
  const double tol = options.zero_tolerance * *std::max_element(mag.coeffs.begin(), mag.coeffs.end());

  auto to_patch = [&](const Eigen::Vector3d& t) {
    Eigen::Vector3d u;
    for (int d = 0; d < 3; ++d) u[d] = e.domain[d][0] + t[d] * (e.domain[d][1] - e.domain[d][0]);
    return u;
  };
  // det J from a value of N at local point t.
  auto detj_at = [&](double n, const Eigen::Vector3d& t) {
    if (!rational) return n / h;
    const double w = bernstein_evaluate(wpoly, t);
    return n / (h * w * w * w * w);
  };
  auto detj_lower = [&](double n) {
    if (!rational) return n / h;
    const double w = n >= 0.0 ? wmax : wmin;
    return n / (h * w * w * w * w);
  };

  double upper_n = std::numeric_limits<double>::infinity();
  Eigen::Vector3d upper_t = Eigen::Vector3d::Zero();
  double leaf_min = std::numeric_limits<double>::infinity();
  bool negative = false, undecided = false, degenerate = false;

  if (!std::all_of(N.coeffs.begin(), N.coeffs.end(), [](double x) { return std::isfinite(x); })) {
    // det J overflows (control points near the largest double): its sign is
    // unknown, so never positive nor degenerate.
    cert.status = ElementStatus::Undecided;
    cert.lower_bound = -std::numeric_limits<double>::infinity();
    cert.upper_bound = std::numeric_limits<double>::quiet_NaN();
    cert.location = to_patch(Eigen::Vector3d::Constant(0.5));
    cert.boxes = 1;
    return cert;
  }
  std::priority_queue<Box, std::vector<Box>, BoxOrder> queue;
  Box root{N, Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), 0, min_coeff(N)};
  const double maxabs = std::max(std::abs(root.minc), std::abs(*std::max_element(N.coeffs.begin(), N.coeffs.end())));
  if (maxabs <= tol) {
    // det J vanishes identically (a collapsed element): nothing to certify.
    cert.status = ElementStatus::Undecided;
    cert.lower_bound = detj_lower(root.minc);
    cert.upper_bound = detj_at(N.coeffs[0], Eigen::Vector3d::Zero());
    cert.location = to_patch(Eigen::Vector3d::Zero());
    cert.boxes = 1;
    return cert;
  }
  queue.push(std::move(root));
  while (!queue.empty()) {
    Box box = queue.top();
    queue.pop();
    ++cert.boxes;
    cert.max_depth = std::max(cert.max_depth, box.depth);
    const Bernstein3& c = box.c;
    // Values at the corners are the corner coefficients.
    for (int corner = 0; corner < 8; ++corner) {
      std::array<int, 3> idx;
      Eigen::Vector3d t;
      for (int d = 0; d < 3; ++d) {
        const bool high = (corner >> d) & 1;
        idx[d] = high ? c.degree[d] : 0;
        t[d] = high ? box.hi[d] : box.lo[d];
      }
      const double v = c(idx[0], idx[1], idx[2]);
      if (v < upper_n) {
        upper_n = v;
        upper_t = t;
      }
    }
    // The value at the Greville point of the smallest coefficient: a good
    // guess of where the minimum lies.
    int arg = 0;
    min_coeff(c, &arg);
    {
      const int i = arg % c.size(0), j = (arg / c.size(0)) % c.size(1), k = arg / (c.size(0) * c.size(1));
      const Eigen::Vector3d s(double(i) / c.degree[0], double(j) / c.degree[1], double(k) / c.degree[2]);
      const double v = bernstein_evaluate(c, s);
      if (v < upper_n) {
        upper_n = v;
        upper_t = box.lo + s.cwiseProduct(box.hi - box.lo);
      }
    }
    if (upper_n < -tol) {
      negative = true;
      leaf_min = std::min(leaf_min, box.minc);
      break;
    }
    if (box.minc > tol) {
      leaf_min = std::min(leaf_min, box.minc);
      continue;
    }
    if (positive_except_boundary(box, tol)) {
      degenerate = true;
      leaf_min = std::min(leaf_min, box.minc);
      continue;
    }
    if (box.depth >= options.max_depth ||
        cert.boxes + static_cast<int>(queue.size()) + 2 > options.max_boxes) {
      undecided = true;
      leaf_min = std::min(leaf_min, box.minc);
      continue;
    }
    const int dir = split_direction(c);
    Box low, high;
    bernstein_subdivide(c, dir, 0.5, &low.c, &high.c);
    const double mid = 0.5 * (box.lo[dir] + box.hi[dir]);
    low.lo = box.lo;
    low.hi = box.hi;
    low.hi[dir] = mid;
    high.lo = box.lo;
    high.hi = box.hi;
    high.lo[dir] = mid;
    low.depth = high.depth = box.depth + 1;
    low.minc = min_coeff(low.c);
    high.minc = min_coeff(high.c);
    queue.push(std::move(low));
    queue.push(std::move(high));
  }
  // Boxes left unexamined (after a negative value ended the search) still
  // cover part of the element: include their bounds.
  while (!queue.empty()) {
    leaf_min = std::min(leaf_min, queue.top().minc);
    queue.pop();
  }
  cert.status = negative     ? ElementStatus::Negative
                : undecided  ? ElementStatus::Undecided
                : degenerate ? ElementStatus::Degenerate
                             : ElementStatus::Positive;
  cert.lower_bound = detj_lower(leaf_min);
  cert.upper_bound = detj_at(upper_n, upper_t);
  cert.location = to_patch(upper_t);
  return cert;
}

namespace {
// Degrees the certificate takes: 1 to options.max_degree.
void check_degrees(const std::array<int, 3>& degrees, const std::string& name, const CertifyOptions& options) {
  for (int d = 0; d < 3; ++d)
    if (degrees[d] < 1) throw bad_input(name + ": degree 0 in direction " + std::to_string(d) + " has no Jacobian");
  for (int d = 0; d < 3; ++d)
    if (degrees[d] > options.max_degree)
      throw bad_input(name + ": degree " + std::to_string(degrees[d]) + " in direction " + std::to_string(d) +
                      " is above the certificate's limit of " + std::to_string(options.max_degree) +
                      " (CertifyOptions::max_degree): det J would have " +
                      std::to_string(static_cast<long long>(std::pow(3.0 * degrees[d], 3))) +
                      " coefficients per element");
}
}  // namespace

std::vector<ElementCertificate> certify_extraction_model(const spline::ExtractionModel& m,
                                                         const CertifyOptions& options) {
  if (m.weights.size() > 0 && !(m.weights.minCoeff() > 0.0)) throw bad_input("extraction model: a weight is not positive");
  std::vector<ElementCertificate> out;
  out.reserve(m.elements.size());
  Progress progress("certify Jacobians", m.elements.size(), options.progress);
  for (int e = 0; e < static_cast<int>(m.elements.size()); ++e) {
    const spline::ExtractionElement& el = m.elements[static_cast<std::size_t>(e)];
    check_degrees(el.degrees, "element " + std::to_string(e), options);
    out.push_back(certify_element(spline::bernstein_element(m, e), el.degrees, options, el.patch, el.index));
    progress.update(static_cast<std::size_t>(e) + 1);
  }
  progress.finish();
  return out;
}

std::vector<ElementCertificate> certify_patch(const spline::Patch& p, int patch_index,
                                              const CertifyOptions& options) {
  const std::string name = "patch " + std::to_string(patch_index);
  check_degrees(p.degrees, name, options);
  if (p.rational() && !(p.weights.minCoeff() > 0.0)) throw bad_input(name + ": a weight is not positive");
  const spline::PatchExtraction ex = spline::bezier_extraction(p);
  std::vector<ElementCertificate> out;
  out.reserve(ex.element_count());
  for (int ew = 0; ew < ex.element_count(2); ++ew)
    for (int ev = 0; ev < ex.element_count(1); ++ev)
      for (int eu = 0; eu < ex.element_count(0); ++eu) {
        const spline::BezierElement e = spline::bernstein_control_points(p, ex, eu, ev, ew);
        out.push_back(certify_element(e, p.degrees, options, patch_index, {{eu, ev, ew}}));
      }
  return out;
}

std::vector<ElementCertificate> certify_model(const spline::MultiPatch& mp, const CertifyOptions& options) {
  // Patches on all cores (parallel_for), each into its own slot: the result
  // does not depend on the thread count.
  std::vector<std::vector<ElementCertificate>> parts(mp.patches.size());
  Progress progress("certify Jacobians", mp.patches.size(), options.progress);
  std::size_t done = 0;
  std::mutex report;
  parallel_for(mp.patches.size(), [&](std::size_t i) {
    parts[i] = certify_patch(mp.patches[i], static_cast<int>(i), options);
    const std::lock_guard<std::mutex> lock(report);
    progress.update(++done);
  });
  progress.finish();
  std::vector<ElementCertificate> out;
  for (const auto& part : parts) out.insert(out.end(), part.begin(), part.end());
  return out;
}

}  // namespace igaprep::iga_check
