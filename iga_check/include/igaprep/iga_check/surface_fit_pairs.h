#pragma once
// The point pairs that fit a model's faces standing for one input surface to
// its triangle mesh (spline/fit_model_surface.h), both ways as the fidelity
// measures them (fidelity.h): each face sample with its closest mesh point,
// and each mesh vertex with the faces' point nearest it (so parts of the
// input the faces do not reach pull them there).
#include <vector>

#include "igaprep/iga_check/fidelity.h"
#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/spline/fit_model_surface.h"
#include "igaprep/spline/multipatch.h"
#include "igaprep/spline/tspline_fit.h"

namespace igaprep::iga_check {

struct SurfaceFitPairOptions {
  int samples_per_element = 4;       // face -> mesh: per direction, per face element (ends included)
  int tessellation_per_element = 4;  // mesh -> face: quads per direction, per face element
  int newton_iterations = 10;
};

std::vector<spline::SurfaceFitPair> surface_fit_pairs(const spline::MultiPatch& mp, int surface,
                                                      const mesh::TriMesh& mesh,
                                                      const SurfaceFitPairOptions& options = {});

// The same for the element faces of a model in extraction form (a T-spline,
// spline/tspline_fit.h): per element face.
std::vector<spline::ExtractionFitPair> extraction_fit_pairs(const spline::ExtractionModel& m, int surface,
                                                            const mesh::TriMesh& mesh,
                                                            const SurfaceFitPairOptions& options = {});

}  // namespace igaprep::iga_check
