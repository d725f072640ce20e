// igaprep export MODEL.h5 --to FORMAT[,FORMAT...] -o BASENAME
// Reads an igaprep HDF5 model and writes it in the formats IGA solvers and
// viewers read; every file is written atomically.
#include <iostream>
#include <memory>
#include <string>

#include "commands.h"
#include "igaprep/core/input_files.h"
#include "igaprep/core/error.h"
#include "igaprep/export/export_model.h"
#include "igaprep/export/hdf5_extraction.h"
#include "igaprep/export/hdf5_model.h"

namespace igaprep::cli {

namespace {
// A model in Bezier-extraction form (igaprep tspline): vtu and bext.
int export_extraction(const std::string& model, const std::vector<exporter::Format>& formats, const std::string& basename) {
  for (const exporter::Format f : formats) exporter::extraction_format_paths(basename, f, 0);  // refused before reading
  const spline::ExtractionModel m = exporter::read_hdf5_extraction(model);
  std::vector<std::string> outputs;
  for (const exporter::Format f : formats)
    for (const std::string& path : exporter::extraction_format_paths(basename, f, static_cast<int>(m.materials.size())))
      outputs.push_back(path);
  refuse_replacing_inputs({model}, outputs);
  for (const std::string& path : exporter::export_extraction_model(m, basename, formats)) std::cout << "wrote " << path << "\n";
  return 0;
}
}  // namespace

void add_export_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "export", "Write an igaprep HDF5 model as hdf5 (.h5), gismo (.xml), mfem (.mesh), vtu (.vtu) or bext (LS-DYNA: .k and _partN.bext)");
  auto model = std::make_shared<std::string>();
  auto formats = std::make_shared<std::string>();
  auto basename = std::make_shared<std::string>();
  sub->add_option("model", *model, "input model, igaprep HDF5 (MODEL.h5)")->required();
  sub->add_option("--to", *formats, "comma-separated formats: hdf5, gismo, mfem, vtu, bext")->required();
  sub->add_option("-o,--output", *basename, "output base name; each format adds its extension")->required();
  set_body(sub, [=] {
    // Formats first: a typo is reported before any file is read or written.
    const std::vector<exporter::Format> list = exporter::parse_formats(*formats);
    if (exporter::is_hdf5_extraction(*model)) return export_extraction(*model, list, *basename);
    const spline::MultiPatch mp = exporter::read_hdf5_model(*model);
    std::vector<std::string> outputs;
    for (const exporter::Format f : list)
      for (const std::string& path : exporter::format_paths(*basename, f, static_cast<int>(mp.materials.size())))
        outputs.push_back(path);
    refuse_replacing_inputs({*model}, outputs);
    for (const std::string& path : exporter::export_model(mp, *basename, list)) std::cout << "wrote " << path << "\n";
    return 0;
  });
}

}  // namespace igaprep::cli
