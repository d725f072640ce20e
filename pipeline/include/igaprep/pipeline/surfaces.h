#pragma once
// The surfaces of a case, read, checked, offset and nested: the first stage
// of every job that starts from a case.
#include <string>
#include <vector>

#include "igaprep/mesh/check_surface.h"
#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/pipeline/case.h"

namespace igaprep::pipeline {

struct Surfaces {
  std::vector<mesh::TriMesh> inputs;         // T1..Tn as read or offset, validated and outward: the
                                             // surfaces the model is checked against
  std::vector<mesh::TriMesh> meshes;         // what the method meshes: the inputs, remeshed where
                                             // their triangles are too long and thin (see remeshed)
  std::vector<mesh::SurfaceReport> reports;  // one per surface
  std::vector<std::string> names;            // labels, for messages
  std::vector<double> remeshed_to;           // per surface: the remeshing's edge length, 0 if kept
};

// Input triangles this elongated or worse (the 95th percentile of (longest
// edge)^2 / (2 area); CAD exports reach 50) are remeshed isotropically to
// their median edge length, keeping edges sharper than 60 degrees: long
// slivers give slivers in the tet mesh, and the harmonic fields on them break
// the midsurface into non-manifold pieces.
constexpr double kRemeshAspect = 8.0;
constexpr double kRemeshSharpAngle = 60.0;

// Reads every file surface (or takes the in-memory one), makes every offset
// surface (from the input it is offset of), checks each, remeshes those with
// poorly shaped triangles, and checks the nesting of what will be meshed. Throws Error(BadInput) listing every
// defect found.
Surfaces load_surfaces(const Case& c);

}  // namespace igaprep::pipeline
