#include "igaprep/iga_check/elasticity_refine.h"

#include "igaprep/core/error.h"
#include "igaprep/spline/refine.h"

namespace igaprep::iga_check {

spline::MultiPatch refine_for_analysis(const spline::MultiPatch& model, int elevate, int refine) {
  if (elevate < 0 || elevate > 10) throw bad_input("degree elevation must lie in 0..10, got " + std::to_string(elevate));
  if (refine < 0 || refine > 10) throw bad_input("refinement levels must lie in 0..10, got " + std::to_string(refine));
  spline::MultiPatch out = model;
  out.has_solution = false;
  out.strain_energy = out.max_displacement = 0.0;
  for (spline::Patch& p : out.patches) {
    p.displacement.resize(0, 0);
    if (elevate > 0)
      for (int d = 0; d < 3; ++d) p = spline::elevate_degree(p, d, elevate);
    for (int level = 0; level < refine; ++level) p = spline::refine_uniformly(p, 1);
  }
  return out;
}

}  // namespace igaprep::iga_check
