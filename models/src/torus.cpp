#include <cmath>

#include "igaprep/models/shapes.h"

namespace igaprep::models {

mesh::TriMesh make_torus(double major_radius, double minor_radius, int n_major, int n_minor) {
  mesh::TriMesh m;
  m.V.resize(n_major * n_minor, 3);
  for (int i = 0; i < n_major; ++i) {
    const double phi = 2.0 * M_PI * i / n_major;
    for (int j = 0; j < n_minor; ++j) {
      const double theta = 2.0 * M_PI * j / n_minor;
      const double rho = major_radius + minor_radius * std::cos(theta);
      m.V.row(i * n_minor + j) << rho * std::cos(phi), rho * std::sin(phi), minor_radius * std::sin(theta);
    }
  }
  m.F.resize(2 * n_major * n_minor, 3);
  int f = 0;
  for (int i = 0; i < n_major; ++i) {
    const int i1 = (i + 1) % n_major;
    for (int j = 0; j < n_minor; ++j) {
      const int j1 = (j + 1) % n_minor;
      const int a = i * n_minor + j, b = i1 * n_minor + j, c = i1 * n_minor + j1, d = i * n_minor + j1;
      // Alternate the diagonal so the triangulation has no preferred twist.
      if ((i + j) % 2 == 0) {
        m.F.row(f++) << a, b, c;
        m.F.row(f++) << a, c, d;
      } else {
        m.F.row(f++) << a, b, d;
        m.F.row(f++) << b, c, d;
      }
    }
  }
  return m;
}

}  // namespace igaprep::models
