// igaprep run [CASE.json] [-o OUTDIR]: the main job on a case (the default
// model ring2 when no case is given). Today's stages: validate the surfaces
// and their nesting, tetrahedralize, midsurface and base surface; the
// decomposition, fit, check and export stages join as they land.
#include <cstdio>
#include <filesystem>

#include "case_file.h"
#include "case_surfaces.h"
#include "commands.h"
#include "igaprep/export/hdf5_model.h"
#include "igaprep/models/builtin_models.h"
#include "stage_midsurface.h"
#include "stage_tetmesh.h"
#include "stage_check.h"
#include "stage_timer.h"
#include "stage_volume.h"

namespace igaprep::cli {

void add_run_command(CLI::App& app) {
  auto* sub = app.add_subcommand("run", "Run the pipeline on a case file (default: the built-in model ring2)");
  auto case_path = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>();
  auto keep = std::make_shared<bool>(false);
  sub->add_option("case", *case_path, "case file (JSON, docs/case-format.md)");
  sub->add_option("-o,--output", *output, "output folder (default: the case's output folder)");
  sub->add_flag("--keep-intermediate", *keep, "also write the intermediate meshes and fields as VTU files");
  set_body(sub, [case_path, output, keep] {
    const std::string path = case_path->empty() ? models::builtin_case_path(models::default_model_name()) : *case_path;
    const CaseFile c = read_case_file(path);
    const std::string dir = output->empty() ? c.output_dir : *output;
    std::printf("igaprep run: case '%s' (%s), output %s\n", c.name.c_str(), path.c_str(), dir.c_str());

    StageTimer validate_timer;
    const CaseSurfaces surfaces = load_case_surfaces(c);
    std::printf("validate   %7.2f s  %zu surface(s), nested", validate_timer.seconds(), surfaces.meshes.size());
    for (std::size_t i = 0; i < surfaces.reports.size(); ++i)
      std::printf("; %s: %d faces, genus %d", surfaces.names[i].c_str(), surfaces.reports[i].faces,
                  surfaces.reports[i].genus);
    std::printf("\n");
    std::fflush(stdout);

    run_tetmesh_stage(c, surfaces, (std::filesystem::path(dir) / "tetmesh.vtu").string());
    const param::MidsurfaceResult mid = run_midsurface_stage(c, surfaces, dir);
    const VolumeStageResult volume = run_volume_stages(c, surfaces, mid, dir, *keep);
    std::filesystem::create_directories(dir);
    exporter::write_hdf5_model(volume.model, (std::filesystem::path(dir) / "model.h5").string());
    CheckFigures figures;
    run_check_stage(volume.model, surfaces.meshes, volume.model.labels, {}, dir, &figures);
    return 0;
  });
}

}  // namespace igaprep::cli
