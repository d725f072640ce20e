// igaprep model NAME -o DIR: writes a built-in model's surfaces and case file.
#include <filesystem>
#include <iostream>

#include "commands.h"
#include "igaprep/core/atomic_file.h"
#include "igaprep/mesh/write_surface.h"
#include "igaprep/models/builtin_models.h"
#include "igaprep/pipeline/case.h"

namespace igaprep::cli {

namespace fs = std::filesystem;

void write_builtin_model(const std::string& name, const std::string& dir) {
  const models::BuiltinModel model = models::make_builtin_model(name);
  create_output_folder(dir);
  pipeline::Case c;
  c.name = model.name;
  for (std::size_t i = 0; i < model.surfaces.size(); ++i) {
    const std::string file = (fs::path(dir) / (model.labels[i] + ".off")).string();
    mesh::write_surface(file, model.surfaces[i]);
    pipeline::CaseSurface s;
    s.label = model.labels[i];
    s.file = file;
    c.surfaces.push_back(s);
    c.materials.push_back({model.materials[i].name, model.materials[i].young_modulus, model.materials[i].poisson_ratio});
  }
  c.output_dir = (fs::path(dir) / "output").string();
  const std::string text = pipeline::case_json(c, dir);
  write_file_atomically((fs::path(dir) / "case.json").string(), [&](std::ostream& out) { out << text; });
}

void add_model_command(CLI::App& app) {
  auto* sub = app.add_subcommand("model", "Write a built-in model (sphere2, ring2, torus3) with its case file");
  auto name = std::make_shared<std::string>();
  auto dir = std::make_shared<std::string>();
  sub->add_option("name", *name, "sphere2, ring2 (the default model) or torus3")->required();
  sub->add_option("-o,--output", *dir, "folder to write the surfaces and case.json into")->required();
  set_body(sub, [name, dir] {
    write_builtin_model(*name, *dir);
    std::cout << "wrote " << *name << " to " << *dir << "/case.json\n";
    return 0;
  });
}

}  // namespace igaprep::cli
