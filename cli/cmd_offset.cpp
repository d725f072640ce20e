// igaprep offset IN --inward D -o OUT: a closed surface at distance D inside IN.
#include <chrono>
#include <iostream>

#include "commands.h"
#include "igaprep/core/input_files.h"
#include "igaprep/core/error.h"
#include "igaprep/mesh/check_surface.h"
#include "igaprep/mesh/offset_surface.h"
#include "igaprep/mesh/read_surface.h"
#include "igaprep/mesh/write_surface.h"

namespace igaprep::cli {

void add_offset_command(CLI::App& app) {
  auto* sub = app.add_subcommand("offset", "Make a closed surface at a distance inside a closed surface");
  struct Args {
    std::string input, output;
    double inward = 0.0;
  };
  auto args = std::make_shared<Args>();
  sub->add_option("input", args->input, "closed surface (STL, OBJ, OFF, PLY)")->required();
  sub->add_option("--inward", args->inward, "offset distance D, in the model's units")->required();
  sub->add_option("-o,--output", args->output, "output surface (.stl, .obj or .off)")->required();
  set_body(sub, [args] {
    if (!(args->inward > 0.0)) throw bad_input("--inward must be a positive distance");
    refuse_replacing_inputs({args->input}, {args->output});
    const auto start = std::chrono::steady_clock::now();
    mesh::TriMesh surface = mesh::load_checked_surface(args->input);
    mesh::OffsetOptions options;
    options.distance = args->inward;
    mesh::TriMesh inner;
    try {
      inner = mesh::offset_inward(surface, options);
    } catch (const Error& e) {
      throw Error(e.kind(), args->input + ": " + e.what());  // name the file at fault
    }
    mesh::SurfaceReport report = mesh::check_and_repair_surface(inner, args->output);
    if (!report.ok()) throw internal_error("the offset surface is defective: " + report.errors.front());
    mesh::write_surface(args->output, inner);
    std::cout << "offset: " << inner.V.rows() << " vertices, " << inner.F.rows() << " faces, genus " << report.genus
              << ", volume " << report.volume << " -> " << args->output << " (" << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s)\n";
    return 0;
  });
}

}  // namespace igaprep::cli
