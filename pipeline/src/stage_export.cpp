#include <filesystem>

#include "igaprep/export/export_model.h"
#include "igaprep/export/hdf5_model.h"
#include "igaprep/pipeline/export.h"
#include "stage_timer.h"

namespace igaprep::pipeline {

Exported export_stage(const spline::MultiPatch& model, const std::vector<std::string>& formats, const std::string& dir,
                      const std::vector<iga_check::ElementCertificate>& certificates, Observer& observer) {
  StageTimer timer;
  std::vector<exporter::Format> list;
  for (const std::string& name : formats)
    for (exporter::Format f : exporter::parse_formats(name))
      if (f != exporter::Format::Hdf5) list.push_back(f);
  Exported r;
  std::filesystem::create_directories(dir);
  const std::string base = (std::filesystem::path(dir) / "model").string();
  exporter::write_hdf5_model(model, base + ".h5");
  r.written.push_back(base + ".h5");
  exporter::VtuOptions vtu;
  for (const iga_check::ElementCertificate& c : certificates) vtu.certified_lower_bound.push_back(c.lower_bound);
  if (!list.empty())
    for (const std::string& path : exporter::export_model(model, base, list, vtu, progress_to(observer)))
      r.written.push_back(path);
  r.seconds = timer.seconds();
  std::string names;
  for (std::size_t i = 0; i < r.written.size(); ++i)
    names += (i ? ", " : "") + std::filesystem::path(r.written[i]).filename().string();
  observer.stage_finished({"export", r.seconds, names, {}});
  return r;
}

}  // namespace igaprep::pipeline
