#include "stage_export.h"

#include <cstdio>
#include <filesystem>

#include "igaprep/export/export_model.h"
#include "igaprep/export/hdf5_model.h"
#include "stage_timer.h"

namespace igaprep::cli {

ExportStageResult run_export_stage(const spline::MultiPatch& model, const std::vector<std::string>& formats,
                                   const std::string& dir) {
  StageTimer timer;
  std::vector<exporter::Format> list;
  for (const std::string& name : formats)
    for (exporter::Format f : exporter::parse_formats(name))
      if (f != exporter::Format::Hdf5) list.push_back(f);
  ExportStageResult r;
  std::filesystem::create_directories(dir);
  const std::string base = (std::filesystem::path(dir) / "model").string();
  exporter::write_hdf5_model(model, base + ".h5");
  r.written.push_back(base + ".h5");
  if (!list.empty())
    for (const std::string& path : exporter::export_model(model, base, list)) r.written.push_back(path);
  r.seconds = timer.seconds();
  std::printf("export     %7.2f s ", r.seconds);
  for (std::size_t i = 0; i < r.written.size(); ++i)
    std::printf("%s %s", i ? "," : "", std::filesystem::path(r.written[i]).filename().c_str());
  std::printf("\n");
  std::fflush(stdout);
  return r;
}

}  // namespace igaprep::cli
