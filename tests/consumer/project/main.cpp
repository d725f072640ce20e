// A downstream program built against the installed igaprep package.
#include <iostream>

#include "igaprep/core/error.h"
#include "igaprep/mesh/tri_mesh.h"

int main() {
  igaprep::mesh::TriMesh m;
  m.V.resize(3, 3);
  m.V << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  m.F.resize(1, 3);
  m.F << 0, 1, 2;
  try {
    throw igaprep::bad_input("consumer ok");
  } catch (const igaprep::Error& e) {
    std::cout << e.what() << " " << m.F.rows() << " " << e.exit_code() << "\n";
    return e.exit_code() == 1 ? 0 : 1;
  }
}
