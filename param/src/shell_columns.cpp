#include "shell_columns.h"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <iterator>

#include "igaprep/core/error.h"
#include "igaprep/core/parallel.h"
#include "igaprep/param/shell_spread.h"

namespace igaprep::param {
namespace {

// The face at parameter p, bilinear in the grid cell that holds it (exact
// at grid points, and on an edge a function of that edge's points only).
Eigen::Vector3d face_point(const std::vector<Eigen::Vector3d>& face, const std::vector<double>& params,
                           const Eigen::Vector2d& p) {
  const std::size_t m = params.size();
  const auto [i, a] = param_cell(params, p.x());
  const auto [j, b] = param_cell(params, p.y());
  const Eigen::Vector3d lo = (1.0 - a) * face[i + m * j] + a * face[i + 1 + m * j];
  const Eigen::Vector3d hi = (1.0 - a) * face[i + m * (j + 1)] + a * face[i + 1 + m * (j + 1)];
  return (1.0 - b) * lo + b * hi;
}

Eigen::Vector3d last_point(const StreamlineColumn& c) { return c.path.row(c.path.rows() - 1).transpose(); }

}  // namespace

double smoothstep(double h) { return h * h * (3.0 - 2.0 * h); }

ShellColumns::ShellColumns(const FieldProbe& probe, double step, const std::vector<double>& params,
                           const std::vector<Eigen::Vector3d>& face, const std::function<bool(int)>& traced,
                           const std::array<bool, 4>& fixed_sides, bool spread, const std::vector<double>& depths,
                           const SpreadOptions& spread_options)
    : probe_(probe), step_(step), params_(params), face_(face), depths_(depths) {
  const int m = static_cast<int>(params.size());
  grid_.resize(face.size());
  std::vector<Eigen::Vector2d> grid(face.size());
  for (int q = 0; q < m * m; ++q)
    grid[static_cast<std::size_t>(q)] = {params[static_cast<std::size_t>(q % m)], params[static_cast<std::size_t>(q / m)]};
  std::vector<int> count(face.size(), 0);
  parallel_for(face.size(), [&](std::size_t q) {
    if (traced(static_cast<int>(q))) grid_[q] = trace_from(grid[q], count[q]);
  });
  for (int c : count) streamlines_ += c;
  if (!spread) return;
  std::vector<Eigen::Vector3d> ends(face.size());
  for (int q = 0; q < m * m; ++q) {
    if (!traced(q)) throw internal_error("shell columns: a face is spread only when every sample is traced");
    ends[static_cast<std::size_t>(q)] = last_point(grid_[static_cast<std::size_t>(q)]);
  }
  std::atomic<int> spread_traces{0};
  std::vector<Eigen::Vector2d> moved = spread_face_params(
      [&](const Eigen::Vector2d& p) {
        int n = 0;
        const Eigen::Vector3d e = last_point(trace_from(p, n));
        spread_traces += n;
        return e;
      },
      params, ends, fixed_sides, spread_options);
  streamlines_ += spread_traces;
  if (moved == grid) return;
  moved_ = std::move(moved);
  trace_spread_columns(traced);
}

StreamlineColumn ShellColumns::trace_from(const Eigen::Vector2d& p, int& traces) const {
  // Between the face's samples the bilinear face can leave H where H is
  // curved and thin (a hub's wall): the start moves halfway to the nearest
  // grid point, up to 4 times, then onto it (a function of p alone, so the
  // faces that share an edge still agree). Each trace starts without a hint
  // (the grid finds its tet), so that it depends on p alone, whichever
  // thread runs it.
  auto nearest = [&](double x) {
    const auto it = std::lower_bound(params_.begin(), params_.end(), x);
    if (it == params_.begin()) return params_.front();
    if (it == params_.end()) return params_.back();
    return *it - x < x - *std::prev(it) ? *it : *std::prev(it);
  };
  const Eigen::Vector2d grid(nearest(p.x()), nearest(p.y()));
  Eigen::Vector2d at = p;
  for (int attempt = 0;; ++attempt) {
    ++traces;
    try {
      int hint = -1;
      return trace_column(probe_, face_point(face_, params_, attempt < 5 ? at : grid), step_, &hint);
    } catch (const Error& e) {
      if (e.kind() == ErrorKind::Internal || attempt == 5) throw;
      at = 0.5 * (at + grid);
    }
  }
}

void ShellColumns::trace_spread_columns(const std::function<bool(int)>& traced) {
  const int m = static_cast<int>(params_.size());
  depth_.resize(face_.size());
  std::vector<int> count(face_.size(), 0);
  parallel_for(face_.size(), [&](std::size_t q) {
    const Eigen::Vector2d p(params_[q % static_cast<std::size_t>(m)], params_[q / static_cast<std::size_t>(m)]);
    const Eigen::Vector2d d = moved_[q] - p;
    if (!traced(static_cast<int>(q)) || d.isZero(0.0)) return;
    auto& cols = depth_[q];
    cols.resize(depths_.size());
    for (std::size_t k = 0; k < depths_.size(); ++k)
      if (depths_[k] > 0.0) cols[k] = trace_from(p + smoothstep(depths_[k]) * d, count[q]);
  });
  for (int c : count) streamlines_ += c;
}

const StreamlineColumn& ShellColumns::at(int q, double h) const {
  if (depth_.empty() || depth_[static_cast<std::size_t>(q)].empty() || h == 0.0) return grid_[static_cast<std::size_t>(q)];
  const auto& cols = depth_[static_cast<std::size_t>(q)];
  const auto it = std::lower_bound(depths_.begin(), depths_.end(), h);
  if (it == depths_.end() || *it != h) throw internal_error("shell columns: a depth that was not traced");
  return cols[static_cast<std::size_t>(it - depths_.begin())];
}

}  // namespace igaprep::param
