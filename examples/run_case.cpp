// Runs a case through the pipeline library and prints, besides one line per
// stage, the model's five worst elements by scaled Jacobian: where a user
// looks first when a model is to be improved.
//
//   run_case [CASE.json]     (no case: the built-in default model ring2)
#include <cstdio>

#include "igaprep/core/error.h"
#include "igaprep/models/builtin_models.h"
#include "igaprep/pipeline/run.h"

namespace {

// Prints each stage's headline as the run reports it.
class StagePrinter : public igaprep::pipeline::Observer {
 public:
  void stage_finished(const igaprep::pipeline::StageSummary& s) override {
    std::printf("%-10s %7.2f s  %.100s\n", s.stage.c_str(), s.seconds, s.headline.c_str());
  }
};

}  // namespace

int main(int argc, char** argv) {
  using namespace igaprep;
  try {
    const pipeline::Case c = argc > 1 ? pipeline::read_case(argv[1])
                                      : pipeline::builtin_case(models::default_model_name());
    StagePrinter printer;
    pipeline::RunOptions options;
    options.write_outputs = false;  // the model and report are returned; nothing is written
    const pipeline::RunResult r = pipeline::run(c, printer, options);
    std::printf("\n%zu patches; the five worst elements by scaled Jacobian:\n", r.model.patches.size());
    const auto& worst = r.report.quality.worst;
    for (std::size_t i = 0; i < worst.size() && i < 5; ++i)
      std::printf("  patch %3d element (%d, %d, %d): scaled Jacobian %.3f at (%.4g, %.4g, %.4g)\n", worst[i].patch,
                  worst[i].element[0], worst[i].element[1], worst[i].element[2], worst[i].scaled_jacobian,
                  worst[i].x.x(), worst[i].x.y(), worst[i].x.z());
    std::printf("%s\n", r.report.pipeline->verdict.c_str());
    return r.passed ? 0 : 2;
  } catch (const Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return e.exit_code();
  }
}
