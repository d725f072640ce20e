#pragma once
// The layout of the base surface M that the volume patches are built on: its
// (u, v) on a rectilinear domain (inset_base.h), the rectangles of the
// domain, and the boundary segments of M cut at the rectangles' corners (one
// crest volume each, seed paper section 5.2).
#include <vector>

#include <Eigen/Core>

#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/param/inset_base.h"
#include "igaprep/param/polycube_2d.h"

namespace igaprep::param {

// A side of a rectangle that lies on M's boundary, from a to b in (u, v), in
// the direction of the rectangle's own u (or v) parameter.
struct CrestSegment {
  int rectangle = 0;
  int side = 0;                    // DomainSide of the rectangle it is
  Eigen::Vector2d a, b;            // end points in (u, v)
};

// A straight side of the domain's boundary (outer boundary or hole), with
// the outward normal of the domain there: the direction M leaves through it.
struct DomainEdge {
  Eigen::Vector2d a, b, outward;
};

struct BaseLayout {
  mesh::TriMesh sheet;          // M
  Eigen::MatrixXd uv;           // #sheet.V x 2
  RectilinearDomain domain;
  std::vector<Eigen::Vector4d> rectangles;  // (umin, vmin, umax, vmax)
  std::vector<CrestSegment> crests;
  std::vector<DomainEdge> domain_edges;
  double max_aspect = 0.0;  // as given to base_layout
  GridLines extra;          // grid lines added beyond the holes', arms' and max_aspect's
};

// Inputs: the inset base surface; the largest aspect of the domain's grid
// intervals (domain_rectangles; 0: the holes' grid as it is); extra grid
// lines. Output: its layout.
BaseLayout base_layout(const InsetBase& base, double max_aspect = 0.0, const GridLines& extra = {});

// The same sheet and domain cut by more grid lines: L's own and `more`.
BaseLayout with_more_lines(const BaseLayout& L, const GridLines& more);

}  // namespace igaprep::param
