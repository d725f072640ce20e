#pragma once
// The CLI's observer of a pipeline run: one line per stage on stdout (with
// its details indented below), intermediates written as DIR/NAME.vtu.
#include <chrono>
#include <set>
#include <string>

#include "igaprep/pipeline/observer.h"

namespace igaprep::cli {

class PrintObserver : public pipeline::Observer {
 public:
  // Writes the intermediates named in `wanted` (all when `all`) into `dir`.
  PrintObserver(std::string dir, std::set<std::string> wanted, bool all = false);
  void stage_finished(const pipeline::StageSummary& s) override;
  // A bar on stderr when stderr is a terminal and IGAPREP_NO_PROGRESS is unset.
  void progress(const std::string& task, std::size_t done, std::size_t total) override;
  bool wants_intermediate(const std::string& name) const override;
  // Written into the staging folder when there is one.
  void intermediate(const std::string& name, const mesh::VtuMesh& mesh) override;
  void staging_folder(const std::string& folder) override { staging_ = folder; }

 private:
  std::string dir_;
  std::string staging_;  // empty: write into dir_
  std::set<std::string> wanted_;
  bool all_;
  bool bar_;
  std::chrono::steady_clock::time_point task_start_;
};

// The intermediates every run writes (tetmesh and the midsurface stage's);
// --keep-intermediate adds the rest.
std::set<std::string> default_intermediates();

}  // namespace igaprep::cli
