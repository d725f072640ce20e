#pragma once
// Validation of a closed triangle surface: topology (closed, manifold,
// consistently oriented, one component), geometry (finite coordinates, no
// degenerate face, no self-intersection, decided with CGAL's exact
// predicates) and a report of its size, genus, volume and bounding box.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "igaprep/core/error.h"  // the functions here throw igaprep::Error
#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::mesh {

struct SurfaceReport {
  std::string file;            // the name the messages use
  int vertices = 0;            // referenced vertices
  int faces = 0;
  int components = 0;          // connected through shared vertices
  int genus = -1;              // from the Euler characteristic; -1 when not closed, manifold and oriented
  bool closed = false;         // no boundary edge
  bool manifold = false;       // every edge in exactly 1 or 2 faces, every vertex one fan
  bool oriented = false;       // neighbouring faces agree on orientation
  int self_intersections = -1; // pairs of intersecting faces; -1 when the test could not run
  double volume = 0.0;         // enclosed volume, each piece counted outward, when closed
  Eigen::Vector3d bbox_min = Eigen::Vector3d::Zero();
  Eigen::Vector3d bbox_max = Eigen::Vector3d::Zero();
  std::vector<int> inward_pieces;  // components (0-based) that face inward: orient_outward turns them
  int unused_vertices = 0;         // vertices no face uses: remove_unused_vertices drops them
  std::vector<std::string> errors;    // one message per defect, each "file: ..."
  std::vector<std::string> warnings;  // e.g. oriented inward, unreferenced vertices
  bool ok() const { return errors.empty(); }
};

// Inputs: mesh (any TriMesh, e.g. from read_surface), name for the messages.
// Output: the report; the mesh is not changed. Pieces of a closed, manifold,
// oriented surface that enclose negative volume and vertices no face uses
// are warnings (inward_pieces, unused_vertices), not errors: the repair
// below fixes them. Never throws for bad input.
SurfaceReport check_surface(const TriMesh& mesh, const std::string& name);

// check_surface, then the two repairs that are safe and warned about:
// inward pieces of a closed, manifold, oriented surface are turned outward
// (orient_outward), and, when there is no error, vertices that no face uses
// are removed (remove_unused_vertices). The warnings say what was done
// ("...; re-oriented outward", "... were removed").
SurfaceReport check_and_repair_surface(TriMesh& mesh, const std::string& name);

// Reads `path` (read_surface) and checks and repairs it
// (check_and_repair_surface, named by `path`).
// Output: the checked (possibly re-oriented) mesh; *report when given.
// Throws Error(BadInput) listing every defect, one per line, when the surface
// is not fit for use.
TriMesh load_checked_surface(const std::string& path, SurfaceReport* report = nullptr);

// One line per report field, for people ("vertices: 8", "genus: 0", ...).
std::string format_report(const SurfaceReport& report);

}  // namespace igaprep::mesh
