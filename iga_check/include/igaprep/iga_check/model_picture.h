#pragma once
// A picture of a model for report.html, drawn by our code as inline SVG (no
// image library, nothing to load): the labelled boundary seen obliquely
// from (1, -1, 0.6) in orthographic projection, one quadrilateral per
// element face (its corners evaluated on the side), painted far to near and
// shaded by its angle to the light, coloured by its patch's smallest sampled
// scaled Jacobian (red 0 or less, yellow 0.5, blue 1), by patch or by
// material, the faces of patches that fail the check outlined in red. A sketch for orientation, not a
// rendering: faces are flat and overlap is resolved by depth order only.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "igaprep/spline/multipatch.h"

namespace igaprep::iga_check {

// What the faces are coloured by.
enum class PictureColour { quality, patch, material };

// A point to mark on the picture (drawn on top, so seen through the model):
// a ring and a short label, e.g. the worst elements' numbers.
struct PictureMark {
  Eigen::Vector3d at = Eigen::Vector3d::Zero();
  std::string label;
};

// Inputs: the model; per patch its smallest sampled scaled Jacobian and
// whether it fails (both may be shorter than the patches: then grey, not
// outlined); the colouring (quality: by the patch's smallest scaled
// Jacobian; patch, material: a palette by index); marks. Output: an <svg>
// element (empty for a model without labelled boundary sides).
std::string model_picture_svg(const spline::MultiPatch& mp, const std::vector<double>& patch_min_scaled_jacobian,
                              const std::vector<bool>& patch_failed, PictureColour colour = PictureColour::quality,
                              const std::vector<PictureMark>& marks = {});

}  // namespace igaprep::iga_check
