#pragma once
// The export stage of a run: DIR/model.h5, then the formats the case's
// "export" key asks for (gismo, mfem, vtu, bext) with the same base name
// (DIR/model.xml, ...), as `igaprep export model.h5 -o DIR/model` writes them.
#include <string>
#include <vector>

#include "igaprep/iga_check/jacobian_certificate.h"
#include "igaprep/pipeline/observer.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::pipeline {

struct Exported {
  std::vector<std::string> written;  // paths: model.h5 first, then in the order asked
  double seconds = 0.0;
};

// Inputs: the model, format names (case key "export"; "hdf5" adds nothing:
// model.h5 is always written), the output folder (created if needed), and
// the check's element certificates of this model (for model.vtu; may be
// empty).
Exported export_stage(const spline::MultiPatch& model, const std::vector<std::string>& formats, const std::string& dir,
                      const std::vector<iga_check::ElementCertificate>& certificates, Observer& observer);

}  // namespace igaprep::pipeline
