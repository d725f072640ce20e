#pragma once
// The streamlines a shell face's blocks are sampled on (volume_param.cpp):
// one per traced sample of the face, or, where the face's streamlines fan
// out (shell_spread.h), one per sample and depth of the shell: the sample
// at depth h (0 on the face, 1 on T1) lies on the streamline from the face
// at p + s(h) (p' - p), p its grid parameter, p' the spread one and s the
// smoothstep, so that the block starts on the face's grid (shared with the
// core) and ends evenly spread on T1, every sample on a streamline.
#include <array>
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "igaprep/param/field_probe.h"
#include "igaprep/param/shell_spread.h"
#include "igaprep/param/streamline_column.h"

namespace igaprep::param {

// 3 h^2 - 2 h^3: 0 at h = 0, 1 at h = 1, flat at both; how far into the
// shell (depth h) a spread or relaxed sample's move has come.
double smoothstep(double h);

class ShellColumns {
 public:
  // face: m x m points (first index fastest) on params x params; traced(q):
  // whether sample q is traced (a ruled face: its long edges only);
  // fixed_sides: sides (bottom j = 0, right, top, left) not to spread;
  // spread: try spreading at all (strategy 2, not a ruled face), with `spread_options`.
  // The streamlines are traced on all cores; each depends on its start alone.
  ShellColumns(const FieldProbe& probe, double step, const std::vector<double>& params,
               const std::vector<Eigen::Vector3d>& face, const std::function<bool(int)>& traced,
               const std::array<bool, 4>& fixed_sides, bool spread, const std::vector<double>& depths,
               const SpreadOptions& spread_options = {});

  // The streamline for sample q at depth h, one of the depths given.
  const StreamlineColumn& at(int q, double h) const;
  int streamlines() const { return streamlines_; }
  bool spread() const { return !moved_.empty(); }

 private:
  // The streamline from the face at p; `traces` counts the attempts.
  StreamlineColumn trace_from(const Eigen::Vector2d& p, int& traces) const;
  void trace_spread_columns(const std::function<bool(int)>& traced);

  const FieldProbe& probe_;
  const double step_;
  const std::vector<double>& params_;
  const std::vector<Eigen::Vector3d>& face_;
  const std::vector<double> depths_;
  std::vector<StreamlineColumn> grid_;                 // per sample, from its grid point
  std::vector<Eigen::Vector2d> moved_;                 // spread parameters; empty: none moved
  std::vector<std::vector<StreamlineColumn>> depth_;   // [q][depth index] when spread (empty: the grid one)
  int streamlines_ = 0;
};

}  // namespace igaprep::param
