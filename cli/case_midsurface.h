#pragma once
// The "midsurface" section of a case file (docs/midsurface.md):
//   "midsurface": {
//     "cut": "auto" | {"plane": {"point": [x, y, z], "normal": [x, y, z]}} | {"loops": [[i, j, ...], ...]},
//     "corners": [[x, y, z], ...],   // 4 per boundary loop of M0trim; default automatic
//     "m0": 0.3,                     // trim value of the base surface, in (0, 1)
//     "path_lengths": true           // trace the quality paths of section 4.1
//   }
#include <string>

#include <nlohmann/json.hpp>

#include "igaprep/param/midsurface_pipeline.h"

namespace igaprep::cli {

// Inputs: the section's JSON value, the case file's name for messages.
// Output: the options. Throws bad_input naming the key for an unknown key, a
// wrong type or a value out of range.
param::MidsurfaceOptions parse_midsurface_options(const nlohmann::json& section, const std::string& file);


}  // namespace igaprep::cli
