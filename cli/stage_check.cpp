#include "stage_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "stage_timer.h"

namespace igaprep::cli {

iga_check::CheckReport run_check_stage(const spline::MultiPatch& mp, const std::vector<mesh::TriMesh>& surfaces,
                                       const std::vector<std::string>& labels,
                                       const iga_check::CheckOptions& options, CheckFigures* figures) {
  StageTimer timer;
  const iga_check::CheckReport r = iga_check::build_check_report(mp, surfaces, labels, options, "model.h5");
  CheckFigures f;
  for (const auto& p : r.patches) {
    f.elements += p.elements;
    f.positive += p.positive;
    f.negative += p.negative;
    f.degenerate += p.degenerate;
    f.undecided += p.undecided;
  }
  f.min_scaled_jacobian = r.quality.overall.scaled_jacobian.min;
  for (const auto& s : r.fidelity) {
    const auto& V = surfaces.at(static_cast<std::size_t>(s.surface)).V;
    const double diag = (V.colwise().maxCoeff() - V.colwise().minCoeff()).norm();
    f.fidelity.push_back(std::max(s.spline_to_mesh.max, s.mesh_to_spline.max) / diag);
  }
  for (const auto& v : r.topology.regions) f.volume_difference.push_back(v.relative_difference);
  f.interface_gap = r.topology.interface_max_gap_relative;
  f.seconds = timer.seconds();
  std::printf("check      %7.2f s  %s; %ld elements: %ld positive, %ld negative, %ld degenerate, %ld undecided; "
              "min scaled Jacobian %.3f; interface gap %.1e",
              f.seconds, r.passed ? "passed" : "FAILED", f.elements, f.positive, f.negative, f.degenerate,
              f.undecided, f.min_scaled_jacobian, f.interface_gap);
  for (std::size_t i = 0; i < f.fidelity.size(); ++i)
    std::printf("; fidelity %s %.3f %%", labels.size() > i ? labels[i].c_str() : "?", 100.0 * f.fidelity[i]);
  for (std::size_t i = 0; i < f.volume_difference.size(); ++i)
    std::printf("; volume %zu %+.3f %%", i, 100.0 * f.volume_difference[i]);
  std::printf("\n");
  std::fflush(stdout);
  if (figures) *figures = f;
  return r;
}

std::string write_run_report(const iga_check::CheckReport& report, const std::string& dir) {
  iga_check::write_report(report, dir);
  return (std::filesystem::path(dir) / "report.html").string();
}

}  // namespace igaprep::cli
