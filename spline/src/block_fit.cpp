#include "igaprep/spline/block_fit.h"

#include <string>

#include "igaprep/core/error.h"
#include "igaprep/spline/fit.h"
#include "igaprep/spline/knot_vector.h"

namespace igaprep::spline {

namespace {
std::vector<double> block_knots(const BlockFitOptions& o) {
  if (o.degree < 1 || o.elements < 1) throw bad_input("block fit: degree and elements must be at least 1");
  return uniform_knot_vector(o.degree, o.elements + o.degree);
}
}  // namespace

std::vector<double> block_sample_params(const BlockFitOptions& options) {
  std::vector<double> g = greville_abscissae(block_knots(options), options.degree);
  g.front() = 0.0;  // exact ends: the sides are sampled at exactly 0 and 1
  g.back() = 1.0;
  return g;
}

Patch interpolate_block(const Eigen::MatrixXd& samples, const BlockFitOptions& options) {
  const std::vector<double> U = block_knots(options);
  const std::vector<double> g = block_sample_params(options);
  const Eigen::Index m = static_cast<Eigen::Index>(g.size());
  if (samples.rows() != m * m * m || samples.cols() != 3)
    throw bad_input("block fit: expected " + std::to_string(m * m * m) + " x 3 samples, got " +
                    std::to_string(samples.rows()) + " x " + std::to_string(samples.cols()));
  return fit_grid({options.degree, options.degree, options.degree}, {U, U, U}, {g, g, g}, samples);
}

}  // namespace igaprep::spline
