// A downstream program built against the installed igaprep package: a mesh,
// an error, and the pipeline's built-in case (made in memory).
#include <iostream>

#include "igaprep/core/error.h"
#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/pipeline/case.h"

int main() {
  igaprep::mesh::TriMesh m;
  m.V.resize(3, 3);
  m.V << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  m.F.resize(1, 3);
  m.F << 0, 1, 2;
  const igaprep::pipeline::Case c = igaprep::pipeline::builtin_case("sphere2");
  try {
    throw igaprep::bad_input("consumer ok");
  } catch (const igaprep::Error& e) {
    std::cout << e.what() << " " << m.F.rows() << " " << e.exit_code() << " " << c.surfaces.size() << "\n";
    return e.exit_code() == 1 && c.surfaces.size() == 2 ? 0 : 1;
  }
}
