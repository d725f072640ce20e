#pragma once
// What a run tells its caller while it works: one summary per stage,
// progress of long steps, and the intermediate meshes a person may want to
// look at. The library never prints or writes them itself: the CLI's
// observer prints and writes VTU files, a test's observer records, a Python
// caller's observer may do either. Every method has a do-nothing default.
#include <cstddef>
#include <string>
#include <vector>

#include "igaprep/core/progress.h"
#include "igaprep/mesh/write_vtu.h"

namespace igaprep::pipeline {

struct StageSummary {
  std::string stage;                 // "validate", "midsurface", ... (docs/cli.md)
  double seconds = 0.0;              // wall-clock time of the stage
  std::string headline;              // one line: the stage's main figures
  std::vector<std::string> details;  // further lines (loops, corners, repairs, ...)
};

class Observer {
 public:
  virtual ~Observer() = default;
  virtual void stage_finished(const StageSummary& summary) { (void)summary; }
  // `done` of `total` units of the named task; called often, cheap.
  virtual void progress(const std::string& task, std::size_t done, std::size_t total) {
    (void)task, (void)done, (void)total;
  }
  // Whether the intermediate `name` ("tetmesh", "midsurface_m0", ...; docs/cli.md)
  // is wanted: the run builds its VTU only then.
  virtual bool wants_intermediate(const std::string& name) const {
    (void)name;
    return false;
  }
  virtual void intermediate(const std::string& name, const mesh::VtuMesh& mesh) { (void)name, (void)mesh; }
  // A run that writes its outputs stages them in `folder` and puts them in
  // place together at its end (core/output_folder.h); an observer that
  // writes intermediates writes them there too, under the same names.
  virtual void staging_folder(const std::string& folder) { (void)folder; }
};

// A progress callback for the library's options that reports to the observer.
inline ProgressCallback progress_to(Observer& observer) {
  return [&observer](const std::string& task, std::size_t done, std::size_t total) {
    observer.progress(task, done, total);
  };
}

// Sends an intermediate to the observer when it wants it; `make` builds the
// VTU only then.
template <class Make>
void offer_intermediate(Observer& observer, const std::string& name, Make make) {
  if (observer.wants_intermediate(name)) observer.intermediate(name, make());
}

}  // namespace igaprep::pipeline
