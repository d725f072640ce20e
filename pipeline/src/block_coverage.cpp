#include "block_coverage.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "igaprep/core/text.h"
#include "igaprep/iga_check/fidelity.h"
#include "igaprep/mesh/enclosed_volume.h"
#include "igaprep/mesh/tet_volume.h"
#include "igaprep/param/surface_projector.h"
#include "igaprep/spline/side.h"

namespace igaprep::pipeline {

namespace {

// The samples are the corners of a piecewise-linear grid whose chord error
// alone nears the check's limits: on the built-in models the blocks' volumes
// are 0.6 % to 1.1 % short and T1 lies up to 0.28 % of the diagonal off their
// sides (2026-12-02), while the fitted models pass. A part the method lost is
// far beyond that (the hand's fingers: 22 %), so the stage speaks only at
// this multiple of the check's limits; the check measures the fitted model.
constexpr double kSampleSlack = 4.0;
constexpr int kMaxRegions = 3;  // uncovered regions named

// Signed volume of a block's sample grid: each cell split into the six tets
// around its diagonal from corner (0,0,0) to (1,1,1).
double grid_volume(const Eigen::MatrixXd& s, int m) {
  auto at = [&](int i, int j, int k) -> Eigen::Vector3d { return s.row(i + m * (j + m * k)).transpose(); };
  double v = 0.0;
  for (int k = 0; k + 1 < m; ++k)
    for (int j = 0; j + 1 < m; ++j)
      for (int i = 0; i + 1 < m; ++i) {
        const Eigen::Vector3d p0 = at(i, j, k), p7 = at(i + 1, j + 1, k + 1);
        const Eigen::Vector3d p1 = at(i + 1, j, k), p2 = at(i, j + 1, k), p4 = at(i, j, k + 1);
        const Eigen::Vector3d p3 = at(i + 1, j + 1, k), p5 = at(i + 1, j, k + 1), p6 = at(i, j + 1, k + 1);
        v += mesh::signed_tet_volume(p0, p1, p3, p7) + mesh::signed_tet_volume(p0, p3, p2, p7) +
             mesh::signed_tet_volume(p0, p2, p6, p7) + mesh::signed_tet_volume(p0, p6, p4, p7) +
             mesh::signed_tet_volume(p0, p4, p5, p7) + mesh::signed_tet_volume(p0, p5, p1, p7);
      }
  return v;
}

// The sides labelled T1 (label 0) of every block, their sample grids cut
// into triangles; `block` (if given) receives each triangle's block.
mesh::TriMesh t1_sides(const param::VolumeParam& vp, std::vector<int>* block = nullptr) {
  const int m = static_cast<int>(vp.params.size());
  std::vector<Eigen::Vector3d> V;
  std::vector<Eigen::Vector3i> F;
  for (std::size_t bi = 0; bi < vp.blocks.size(); ++bi)
    for (const spline::Side side : spline::Side::all()) {
      const param::SampledBlock& b = vp.blocks[bi];
      if (b.side_label[static_cast<std::size_t>(side.array_index())] != 0) continue;
      const int d = side.direction(), fixed = side.parameter() ? m - 1 : 0;
      const auto [t0, t1] = side.tangent_directions();
      const int first = static_cast<int>(V.size());
      for (int y = 0; y < m; ++y)
        for (int x = 0; x < m; ++x) {
          std::array<int, 3> ijk{};
          ijk[static_cast<std::size_t>(d)] = fixed;
          ijk[static_cast<std::size_t>(t0)] = x;
          ijk[static_cast<std::size_t>(t1)] = y;
          V.push_back(b.samples.row(ijk[0] + m * (ijk[1] + m * ijk[2])).transpose());
        }
      for (int y = 0; y + 1 < m; ++y)
        for (int x = 0; x + 1 < m; ++x) {
          const int a = first + x + m * y;
          F.emplace_back(a, a + 1, a + m + 1);
          F.emplace_back(a, a + m + 1, a + m);
          if (block) block->insert(block->end(), 2, static_cast<int>(bi));
        }
    }
  mesh::TriMesh t;
  t.V.resize(static_cast<Eigen::Index>(V.size()), 3);
  for (std::size_t i = 0; i < V.size(); ++i) t.V.row(static_cast<Eigen::Index>(i)) = V[i].transpose();
  t.F.resize(static_cast<Eigen::Index>(F.size()), 3);
  for (std::size_t i = 0; i < F.size(); ++i) t.F.row(static_cast<Eigen::Index>(i)) = F[i].transpose();
  return t;
}

void add_volume_findings(const param::VolumeParam& vp, const std::vector<mesh::TriMesh>& inputs, double limit,
                         std::vector<std::string>& out) {
  const int n = static_cast<int>(inputs.size()), m = static_cast<int>(vp.params.size());
  std::vector<double> blocks(static_cast<std::size_t>(n), 0.0);
  for (const param::SampledBlock& b : vp.blocks)
    if (b.material >= 0 && b.material < n) blocks[static_cast<std::size_t>(b.material)] += grid_volume(b.samples, m);
  const std::vector<double> input = mesh::region_volumes(inputs);
  for (int k = 0; k < n; ++k) {
    const double difference = (blocks[static_cast<std::size_t>(k)] - input[static_cast<std::size_t>(k)]) /
                              input[static_cast<std::size_t>(k)];
    if (std::abs(difference) > limit)
      out.push_back(text("the blocks of material %d differ from the input's volume there by %+.3f %%", k,
                         100.0 * difference));
  }
}

// Per vertex of t1, its distance to the nearest block side labelled T1
// (sides: t1_sides(vp), not empty).
std::vector<double> distances_to_sides(const mesh::TriMesh& sides, const mesh::TriMesh& t1) {
  const param::SurfaceProjector projector(sides.V, sides.F);
  std::vector<double> distance(static_cast<std::size_t>(t1.V.rows()));
  for (Eigen::Index v = 0; v < t1.V.rows(); ++v) {
    const Eigen::Vector3d x = t1.V.row(v).transpose();
    distance[static_cast<std::size_t>(v)] = (projector.closest(x) - x).norm();
  }
  return distance;
}

void add_t1_findings(const param::VolumeParam& vp, const mesh::TriMesh& t1, const std::string& name, double limit,
                     std::vector<std::string>& out) {
  const mesh::TriMesh sides = t1_sides(vp);
  if (sides.F.rows() == 0) {
    out.push_back(text("no block side lies on '%s'", name.c_str()));
    return;
  }
  const double diagonal = iga_check::mesh_diagonal(t1);
  const std::vector<double> distance = distances_to_sides(sides, t1);
  const auto regions = iga_check::uncovered_regions(t1, distance, limit * diagonal);
  for (std::size_t i = 0; i < regions.size() && i < kMaxRegions; ++i)
    out.push_back(text("blocks leave '%s' uncovered: %d vertices around %s, the farthest %.3f %% of the diagonal away "
                       "at %s",
                       name.c_str(), regions[i].vertices, point_text(regions[i].centroid).c_str(),
                       100.0 * regions[i].max / diagonal, point_text(regions[i].farthest).c_str()));
  if (regions.size() > kMaxRegions)
    out.push_back(text("... and %zu more uncovered regions of '%s'", regions.size() - kMaxRegions, name.c_str()));
}

}  // namespace

double t1_sample_gap(const param::VolumeParam& vp, const mesh::TriMesh& t1) {
  const mesh::TriMesh sides = t1_sides(vp);
  if (sides.F.rows() == 0) return std::numeric_limits<double>::infinity();
  const std::vector<double> distance = distances_to_sides(sides, t1);
  return *std::max_element(distance.begin(), distance.end()) / iga_check::mesh_diagonal(t1);
}

std::vector<param::FaceDirection> faces_missing_t1(const param::VolumeParam& vp, const mesh::TriMesh& t1,
                                                   double limit) {
  std::vector<int> block;
  const mesh::TriMesh sides = t1_sides(vp, &block);
  if (sides.F.rows() == 0) return {};
  const param::SurfaceProjector projector(sides.V, sides.F);
  const double reach = limit * iga_check::mesh_diagonal(t1);
  std::vector<param::FaceDirection> out;
  for (Eigen::Index v = 0; v < t1.V.rows(); ++v) {
    const Eigen::Vector3d x = t1.V.row(v).transpose();
    int triangle = -1;
    if (!((projector.closest(x, &triangle) - x).norm() > reach)) continue;
    const param::SampledBlock& b = vp.blocks.at(static_cast<std::size_t>(block.at(static_cast<std::size_t>(triangle))));
    if (b.kind != param::BlockKind::Shell) continue;
    // Both directions: on a kitten's ear cut along the longer direction
    // alone, the samples came 0.543 % off T1 where both gave 0.381 %.
    out.push_back({b.source, 0});
    out.push_back({b.source, 1});
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<std::string> block_coverage_findings(const param::VolumeParam& vp, const Surfaces& surfaces,
                                                 const iga_check::CheckOptions& limits) {
  std::vector<std::string> out;
  if (surfaces.inputs.empty() || vp.blocks.empty()) return out;
  add_volume_findings(vp, surfaces.inputs, kSampleSlack * limits.volume_limit, out);
  add_t1_findings(vp, surfaces.inputs.front(), surfaces.names.empty() ? "T1" : surfaces.names.front(),
                  kSampleSlack * limits.fidelity_limit, out);
  return out;
}

}  // namespace igaprep::pipeline
