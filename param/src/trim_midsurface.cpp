#include "igaprep/param/trim_midsurface.h"

#include "igaprep/core/error.h"
#include "igaprep/param/sheet_topology.h"

namespace igaprep::param {

TrimmedSheet trim_midsurface(const mesh::TetMesh& tets, const Midsurface& m0, int innermost_material,
                             int expected_loops) {
  TrimmedSheet out;
  std::vector<int> faces;
  for (Eigen::Index f = 0; f < m0.mesh.F.rows(); ++f)
    if (tets.material(m0.tet(f)) == innermost_material) faces.push_back(static_cast<int>(f));
  if (faces.empty())
    throw bad_input("M0trim: the midsurface M0 does not enter the innermost surface (material " +
                    std::to_string(innermost_material) + "); choose cut loops whose midsurface crosses it");
  Eigen::VectorXi map = Eigen::VectorXi::Constant(m0.mesh.V.rows(), -1);
  std::vector<int> verts;
  out.mesh.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  out.m0_face.resize(static_cast<Eigen::Index>(faces.size()));
  for (std::size_t i = 0; i < faces.size(); ++i) {
    out.m0_face(static_cast<Eigen::Index>(i)) = faces[i];
    for (int k = 0; k < 3; ++k) {
      const int v = m0.mesh.F(faces[i], k);
      if (map(v) < 0) {
        map(v) = static_cast<int>(verts.size());
        verts.push_back(v);
      }
      out.mesh.F(static_cast<Eigen::Index>(i), k) = map(v);
    }
  }
  out.mesh.V.resize(static_cast<Eigen::Index>(verts.size()), 3);
  out.m0_vertex.resize(static_cast<Eigen::Index>(verts.size()));
  for (std::size_t i = 0; i < verts.size(); ++i) {
    out.mesh.V.row(static_cast<Eigen::Index>(i)) = m0.mesh.V.row(verts[i]);
    out.m0_vertex(static_cast<Eigen::Index>(i)) = verts[i];
  }
  const SheetTopology topo = analyze_sheet(out.mesh.F, out.mesh.V.rows());
  const std::string problem = describe_sheet_problem(topo, expected_loops, "M0trim (M0 inside the innermost surface)");
  if (!problem.empty())
    throw bad_input(problem + "; the midsurface must cross the innermost surface in one sheet "
                              "(choose other cut loops, or a thicker inner surface)");
  out.boundary_loops = topo.boundary_loops;
  return out;
}

}  // namespace igaprep::param
