#pragma once
// Runs of the pipeline library for the tests: a case from a built-in model's
// committed case file with changes, run with an observer that records what
// the run told it.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "igaprep/pipeline/case.h"
#include "igaprep/pipeline/run.h"

namespace pipeline_test {

namespace fs = std::filesystem;

inline std::string models_dir() { return std::string(IGAPREP_SOURCE_DIR) + "/models"; }

// A fresh scratch folder under the build tree.
inline std::string scratch_dir(const std::string& name) {
  const fs::path dir = fs::path(IGAPREP_BINARY_DIR) / "tests" / "pipeline_scratch" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

// What a run told its observer.
class Recorder : public igaprep::pipeline::Observer {
 public:
  std::vector<igaprep::pipeline::StageSummary> stages;
  std::vector<std::string> wanted;  // intermediates to ask for
  std::vector<std::string> received;
  void stage_finished(const igaprep::pipeline::StageSummary& s) override { stages.push_back(s); }
  bool wants_intermediate(const std::string& name) const override {
    for (const auto& w : wanted)
      if (w == name) return true;
    return false;
  }
  void intermediate(const std::string& name, const igaprep::mesh::VtuMesh&) override { received.push_back(name); }
  std::vector<std::string> stage_names() const {
    std::vector<std::string> out;
    for (const auto& s : stages) out.push_back(s.stage);
    return out;
  }
};

// The committed case of a built-in model with `extra` keys merged in (a JSON
// object's text), its output folder the scratch folder `name`.
inline igaprep::pipeline::Case model_case(const std::string& model, const std::string& extra = "{}",
                                          const std::string& name = "") {
  std::ifstream in(models_dir() + "/" + model + "/case.json");
  nlohmann::json c = nlohmann::json::parse(in);
  c.update(nlohmann::json::parse(extra));
  c["output"] = scratch_dir(name.empty() ? model : name);
  return igaprep::pipeline::parse_case(c.dump(), models_dir() + "/" + model, model + "/case.json");
}

}  // namespace pipeline_test
