// igaprep tspline MODEL.h5 -o OUT.h5
// A multipatch model in Bezier-extraction form (the form of T-splines,
// docs/hdf5-format.md), written as an igaprep-bezier-extraction file.
#include <iostream>
#include <memory>
#include <string>

#include "commands.h"
#include "igaprep/core/input_files.h"
#include "igaprep/export/hdf5_extraction.h"
#include "igaprep/export/hdf5_model.h"
#include "igaprep/spline/extraction_model.h"

namespace igaprep::cli {

void add_tspline_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "tspline", "Write an igaprep HDF5 model in Bezier-extraction form (igaprep-bezier-extraction, the T-spline form)");
  auto model = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>();
  sub->add_option("model", *model, "input model, igaprep HDF5 (MODEL.h5)")->required();
  sub->add_option("-o,--output", *output, "output file (HDF5)")->required();
  set_body(sub, [=] {
    refuse_replacing_inputs({*model}, {*output});
    const spline::MultiPatch mp = exporter::read_hdf5_model(*model);
    const spline::ExtractionModel m = spline::extraction_model(mp);
    exporter::write_hdf5_extraction(m, *output);
    std::cout << "tspline: " << m.function_count() << " functions, " << m.elements.size() << " elements, "
              << m.boundary_faces.size() << " labelled element faces\n"
              << "wrote " << *output << "\n";
    return 0;
  });
}

}  // namespace igaprep::cli
