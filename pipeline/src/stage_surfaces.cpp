#include "igaprep/pipeline/surfaces.h"

#include "igaprep/core/error.h"
#include "igaprep/mesh/nesting.h"
#include "igaprep/mesh/offset_surface.h"
#include "igaprep/mesh/read_surface.h"
#include "igaprep/mesh/remesh_surface.h"

namespace igaprep::pipeline {
namespace {

// The surface the method meshes: the input, or the input remeshed when its
// triangles are poorly shaped and the remeshed one passes the same checks.
mesh::TriMesh mesh_to_use(const mesh::TriMesh& input, const CaseSurface& s, const std::string& name,
                          double& remeshed_to) {
  remeshed_to = 0.0;
  if (s.remesh == CaseSurface::Remesh::Off) return input;
  if (s.remesh == CaseSurface::Remesh::Auto && !(mesh::triangle_aspect_quantile(input, 0.95) > kRemeshAspect))
    return input;
  const double length = s.remesh == CaseSurface::Remesh::Length ? s.remesh_length : mesh::median_edge_length(input);
  mesh::TriMesh m = mesh::remesh_isotropic(input, {length, kRemeshSharpAngle, 5});
  const mesh::SurfaceReport report = mesh::check_and_repair_surface(m, name + " (remeshed)");
  if (!report.errors.empty()) return input;
  remeshed_to = length;
  return m;
}

}  // namespace

Surfaces load_surfaces(const Case& c) {
  Surfaces out;
  std::string errors;
  for (const CaseSurface& s : c.surfaces) {
    mesh::TriMesh m;
    std::string name = s.label;
    if (s.offset_of) {
      mesh::OffsetOptions options;
      options.distance = s.inward;
      try {
        m = mesh::offset_inward(out.inputs.at(static_cast<std::size_t>(*s.offset_of)), options);
      } catch (const Error& e) {
        throw Error(e.kind(), (c.path.empty() ? c.name : c.path) + ": surface '" + s.label + "' (offset of " +
                                  c.surfaces.at(static_cast<std::size_t>(*s.offset_of)).label + "): " + e.what());
      }
      name = s.label + " (offset of " + out.names.at(static_cast<std::size_t>(*s.offset_of)) + " by " +
             std::to_string(s.inward) + ")";
    } else if (s.mesh) {
      m = *s.mesh;
    } else {
      m = mesh::read_surface(s.file);
      name = s.file;
    }
    mesh::SurfaceReport report = mesh::check_and_repair_surface(m, name);
    for (const auto& e : report.errors) errors += "\n  " + e;
    double remeshed_to = 0.0;
    if (report.errors.empty()) out.meshes.push_back(mesh_to_use(m, s, name, remeshed_to));
    out.inputs.push_back(std::move(m));
    out.reports.push_back(std::move(report));
    out.names.push_back(s.label);
    out.remeshed_to.push_back(remeshed_to);
  }
  if (!errors.empty()) throw bad_input("the case's surfaces have defects:" + errors);
  if (out.meshes.size() > 1) {
    const mesh::NestingReport nesting = mesh::check_nesting(out.meshes, out.names);
    if (!nesting.nested) {
      std::string list;
      for (const auto& e : nesting.errors) list += "\n  " + e;
      throw bad_input("the case's surfaces are not nested (outermost first):" + list);
    }
  }
  return out;
}

}  // namespace igaprep::pipeline
