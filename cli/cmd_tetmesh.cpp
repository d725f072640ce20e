// igaprep tetmesh CASE.json: the case's surfaces checked and tetrahedralized,
// written as <output>/tetmesh.vtu.
#include <cstdio>
#include <filesystem>

#include "commands.h"
#include "igaprep/core/atomic_file.h"
#include "igaprep/mesh/tet_volume.h"
#include "igaprep/mesh/tetrahedralize.h"
#include "igaprep/mesh/write_vtu.h"
#include "igaprep/pipeline/surfaces.h"

namespace igaprep::cli {

void add_tetmesh_command(CLI::App& app) {
  auto* sub = app.add_subcommand("tetmesh", "Tetrahedralize a case's nested surfaces with a material per tet");
  auto case_path = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>();
  sub->add_option("case", *case_path, "case file (JSON, docs/case-format.md)")->required();
  sub->add_option("-o,--output", *output, "output folder (default: the case's output folder)");
  set_body(sub, [case_path, output] {
    const pipeline::Case c = pipeline::read_case(*case_path);
    const pipeline::Surfaces surfaces = pipeline::load_surfaces(c);
    const mesh::TetMesh tets = mesh::tetrahedralize(surfaces.meshes, {}, c.tetmesh);
    const mesh::TetVolumes v = mesh::tet_volumes(tets, static_cast<int>(c.materials.size()));
    std::printf("tetmesh    %ld tets, %ld vertices, volume %.6g (radius-edge %.2f)\n", static_cast<long>(tets.T.rows()),
                static_cast<long>(tets.V.rows()), v.total, c.tetmesh.radius_edge_ratio);
    for (std::size_t m = 0; m < v.per_material.size(); ++m)
      std::printf("             material %zu (%s): %ld tets, volume %.6g\n", m, c.materials[m].name.c_str(),
                  v.tets_per_material[m], v.per_material[m]);
    const std::filesystem::path dir = output->empty() ? c.output_dir : *output;
    create_output_folder(dir.string());
    mesh::write_vtu((dir / "tetmesh.vtu").string(), tets);
    std::printf("             wrote %s\n", (dir / "tetmesh.vtu").c_str());
    return 0;
  });
}

}  // namespace igaprep::cli
