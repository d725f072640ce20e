#include "igaprep/core/error.h"
#include "igaprep/models/builtin_models.h"
#include "igaprep/models/shapes.h"

namespace igaprep::models {

// Sizes are chosen for 2,000 to 20,000 triangles per model with similar
// triangle sizes on nested surfaces.
BuiltinModel make_builtin_model(const std::string& name) {
  BuiltinModel model;
  model.name = name;
  if (name == "sphere2") {
    model.description = "ellipsoid (1.0 x 0.8 x 0.6) with a nested inner ellipsoid, two materials";
    model.surfaces = {make_ellipsoid(1.0, 0.8, 0.6, 4), make_ellipsoid(0.55, 0.44, 0.33, 3)};
    model.labels = {"outer", "inner"};
    model.materials = {{"shell", 1000.0, 0.3}, {"core", 100.0, 0.25}};
    model.expected_genus = 0;
  } else if (name == "ring2") {
    model.description = "solid torus (R 1.0, r 0.45) with a nested inner torus (r 0.25), two materials";
    model.surfaces = {make_torus(1.0, 0.45, 72, 32), make_torus(1.0, 0.25, 72, 18)};
    model.labels = {"outer", "inner"};
    model.materials = {{"shell", 1000.0, 0.3}, {"core", 100.0, 0.25}};
    model.expected_genus = 1;
  } else if (name == "torus3") {
    model.description = "genus-3 solid: a tube of radius 0.22 around a frame with three holes";
    model.surfaces = {make_three_hole_frame(0.22, 0.07)};
    model.labels = {"outer"};
    model.materials = {{"solid", 1000.0, 0.3}};
    model.expected_genus = 3;
  } else {
    throw bad_input("unknown built-in model '" + name + "' (known: sphere2, ring2, torus3)");
  }
  return model;
}

}  // namespace igaprep::models

namespace igaprep::models {

std::vector<std::string> builtin_model_names() { return {"sphere2", "ring2", "torus3"}; }

std::string default_model_name() { return "ring2"; }

}  // namespace igaprep::models
