#pragma once
// Harmonic fields and gradient traces as VTU files for ParaView (through
// mesh::write_vtu, so the files are written atomically).
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "igaprep/param/trace_gradient.h"

namespace igaprep::param {

// Inputs: V (#V x 3), cells (#C x 4 tets or #C x 3 triangles), named fields
// (each #V values, written as point data); optional named #C x 3 cell vectors
// (e.g. cell_gradients). Output: the file `path`. Throws bad_input for a field
// of the wrong size.
void write_field_vtu(const std::string& path, const Eigen::MatrixXd& V, const Eigen::MatrixXi& cells,
                     const std::vector<std::pair<std::string, Eigen::VectorXd>>& point_fields,
                     const std::vector<std::pair<std::string, Eigen::MatrixXd>>& cell_vectors = {});

// Inputs: traces (each a polyline). Output: one polyline cell per trace with
// cell data "status" (TraceStatus as int) and "steps", point data "trace".
void write_traces_vtu(const std::string& path, const std::vector<TraceResult>& traces);

}  // namespace igaprep::param
