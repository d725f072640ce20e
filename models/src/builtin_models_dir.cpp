#include "igaprep/models/builtin_models.h"

namespace igaprep::models {

std::vector<std::string> builtin_model_names() { return {"sphere2", "ring2", "torus3"}; }

std::string default_model_name() { return "ring2"; }

std::string builtin_models_dir() { return IGAPREP_MODELS_SOURCE_DIR; }

std::string builtin_case_path(const std::string& name) {
  return builtin_models_dir() + "/" + name + "/case.json";
}

}  // namespace igaprep::models
