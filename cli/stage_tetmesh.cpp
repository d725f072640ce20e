#include "stage_tetmesh.h"

#include <Eigen/Geometry>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "igaprep/mesh/tetrahedralize.h"
#include "igaprep/mesh/write_vtu.h"
#include "stage_timer.h"

namespace igaprep::cli {

TetMeshSummary summarize(const mesh::TetMesh& tets, int materials) {
  TetMeshSummary s;
  s.tets = tets.T.rows();
  s.vertices = tets.V.rows();
  s.tets_per_material.assign(static_cast<std::size_t>(materials), 0);
  s.volume_per_material.assign(static_cast<std::size_t>(materials), 0.0);
  for (Eigen::Index t = 0; t < tets.T.rows(); ++t) {
    const Eigen::Vector3d a = tets.V.row(tets.T(t, 0)), b = tets.V.row(tets.T(t, 1)), c = tets.V.row(tets.T(t, 2)),
                          d = tets.V.row(tets.T(t, 3));
    const double volume = (b - a).cross(c - a).dot(d - a) / 6.0;
    const int m = tets.material(t);
    if (m >= 0 && m < materials) {
      s.tets_per_material[static_cast<std::size_t>(m)] += 1;
      s.volume_per_material[static_cast<std::size_t>(m)] += volume;
    }
    s.volume += volume;
  }
  return s;
}

mesh::TetMesh run_tetmesh_stage(const CaseFile& c, const CaseSurfaces& surfaces, const std::string& vtu_path) {
  StageTimer timer;
  mesh::TetMesh tets = mesh::tetrahedralize(surfaces.meshes, {}, c.tetmesh);
  const TetMeshSummary s = summarize(tets, static_cast<int>(c.materials.size()));
  std::printf("tetmesh    %7.2f s  %ld tets, %ld vertices, volume %.6g (radius-edge %.2f)\n", timer.seconds(), s.tets,
              s.vertices, s.volume, c.tetmesh.radius_edge_ratio);
  for (std::size_t m = 0; m < s.tets_per_material.size(); ++m)
    std::printf("             material %zu (%s): %ld tets, volume %.6g\n", m, c.materials[m].name.c_str(),
                s.tets_per_material[m], s.volume_per_material[m]);
  if (!vtu_path.empty()) {
    std::filesystem::create_directories(std::filesystem::path(vtu_path).parent_path());
    mesh::write_vtu(vtu_path, tets);
    std::printf("             wrote %s\n", vtu_path.c_str());
  }
  std::fflush(stdout);
  return tets;
}

}  // namespace igaprep::cli
