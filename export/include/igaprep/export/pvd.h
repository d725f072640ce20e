#pragma once
// A ParaView collection (.pvd): one file that opens several VTU files
// together, each as a part of one multiblock (a run's model, its boundary
// and its intermediates). Names are written relative to the .pvd's folder.
#include <string>
#include <vector>

namespace igaprep::exporter {

// Inputs: the .pvd's path; the files, relative to its folder, in the order
// ParaView lists them. Written atomically. Throws bad_input for a name that
// XML cannot hold (not well-formed UTF-8 text).
void write_pvd(const std::string& path, const std::vector<std::string>& files);

}  // namespace igaprep::exporter
