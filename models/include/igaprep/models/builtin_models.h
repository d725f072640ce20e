#pragma once
// The built-in models (sphere2, ring2, torus3): nested closed surfaces made by
// deterministic code.
#include <string>
#include <vector>

#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::models {

struct BuiltinMaterial {
  std::string name;
  double young_modulus;
  double poisson_ratio;
};

struct BuiltinModel {
  std::string name;
  std::string description;
  std::vector<mesh::TriMesh> surfaces;     // T1..Tn, outermost first
  std::vector<std::string> labels;         // one per surface ("outer", "inner", ...)
  std::vector<BuiltinMaterial> materials;  // one per surface: material i lies inside T(i+1)
  int expected_genus = 0;
};

// The names of the built-in models; ring2 is the default model.
std::vector<std::string> builtin_model_names();
std::string default_model_name();

// Generates the surfaces of a built-in model; throws Error(BadInput) for an
// unknown name.
BuiltinModel make_builtin_model(const std::string& name);

}  // namespace igaprep::models
