// igaprep tnurcc MODEL.h5 [--surface LABEL] [--fit SURFACE] -o DIR
// [--crease-angle DEG] [--iterations N]: the T-NURCC surfaces of a model
// (docs/tnurcc.md). Per surface: its cage (OBJ with crease tags), the cage's
// knot intervals (JSON) and the limit surface (VTU with normals and mean
// curvature); with --fit the cage is first fitted to the given mesh. Prints
// the figures that compare the limit surface with the C0 model. Exit 0, or
// 1 on bad input (nothing written).
#include <iostream>
#include <memory>

#include "commands.h"
#include "igaprep/core/error.h"
#include "igaprep/core/input_files.h"
#include "igaprep/export/hdf5_model.h"
#include "igaprep/mesh/read_surface.h"
#include "igaprep/pipeline/tnurcc.h"
#include "igaprep/spline/label_sides.h"
#include "print_observer.h"

namespace igaprep::cli {

namespace {

struct TnurccArgs {
  std::string model, output, surface, fit;
  pipeline::TnurccSettings settings;
};

// A label given by name or by index.
int find_label(const spline::MultiPatch& mp, const std::string& name) {
  int label = spline::label_index(mp, name);
  if (label < 0 && !name.empty() && name.find_first_not_of("0123456789") == std::string::npos &&
      std::stoul(name) < mp.labels.size())
    label = std::stoi(name);
  if (label < 0)
    throw bad_input("--surface " + name + ": the model has no such label (its labels: " + spline::label_list(mp) + ")");
  return label;
}

int run_tnurcc(TnurccArgs a) {
  std::vector<std::string> inputs{a.model};
  if (!a.fit.empty()) inputs.push_back(a.fit);
  refuse_replacing_inputs(inputs, {a.output});
  const spline::MultiPatch mp = exporter::read_hdf5_model(a.model);
  const int label = a.surface.empty() ? 0 : find_label(mp, a.surface);
  if (!a.surface.empty()) a.settings.labels = {label};
  std::vector<mesh::TriMesh> meshes;
  if (!a.fit.empty()) {
    meshes.resize(label + 1);
    meshes[label] = mesh::read_surface(a.fit);
  }
  PrintObserver observer("", {});
  const auto surfaces = pipeline::tnurcc_surfaces(mp, meshes, a.settings, observer);
  for (const auto& path : pipeline::write_tnurcc(surfaces, a.output, a.settings)) std::cout << "wrote " << path << "\n";
  return 0;
}

}  // namespace

void add_tnurcc_command(CLI::App& app) {
  auto* sub = app.add_subcommand("tnurcc", "T-NURCC surfaces of a model: cages, knot intervals and limit surfaces");
  auto args = std::make_shared<TnurccArgs>();
  sub->add_option("model", args->model, "Model file (HDF5, docs/hdf5-format.md)")->required()->check(CLI::ExistingFile);
  sub->add_option("-o,--output", args->output, "Folder for the cages (OBJ), intervals (JSON) and limit surfaces (VTU)")
      ->required();
  sub->add_option("--surface", args->surface, "The surface's label (name or index); default: every labelled surface");
  sub->add_option("--fit", args->fit, "Fit the cage to this mesh (the surface's input; label 0 without --surface)")
      ->check(CLI::ExistingFile);
  sub->add_option("--crease-angle", args->settings.crease_angle,
                  "Patch edges where the model (and the --fit mesh) turn by more than this many degrees become creases")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 180.0));
  sub->add_option("--iterations", args->settings.fit_iterations, "Fit iterations (closest points, then least squares)")
      ->capture_default_str()
      ->check(CLI::Range(0, 100));
  sub->add_flag("--equal-intervals", args->settings.equal_intervals,
               "Every knot interval 1: the cage as a Catmull-Clark cage (for models with non-uniform knots)");
  sub->add_option("--smoothing", args->settings.smoothing, "The fit's fairing weight, per point pair and cage point")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1e6));
  set_body(sub, [args] { return run_tnurcc(*args); });
}

}  // namespace igaprep::cli
