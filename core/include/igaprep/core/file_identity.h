#pragma once
// Inputs are never replaced by outputs: before any work, each output a
// command would write is compared with its inputs by file identity (device
// and inode, through symlinks, hard links and different spellings).
#include <string>
#include <vector>

namespace igaprep {

// Throws bad_input naming both when an existing output is one of the inputs.
// Outputs that do not exist yet are fine.
void refuse_replacing_inputs(const std::vector<std::string>& inputs, const std::vector<std::string>& outputs);

}  // namespace igaprep
