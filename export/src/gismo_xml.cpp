// G+Smo XML writer. Conventions follow G+Smo's reader (src/gsIO/gsXml.cpp
// getInterfaces / getBoundaries, gsXmlUtils.hpp gsXml<gsMultiPatch>):
// patch numbers in <interfaces> and <boundary> are Geometry ids, mapped
// through <patches>; sides are 1..6 (u0 u1 v0 v1 w0 w1); for the normal
// direction G+Smo itself sets dirmap = normal of patch b and orient =
// (both sides at the same end), so we write exactly those values there.
#include "igaprep/export/gismo_xml.h"

#include <algorithm>
#include <map>
#include <vector>

#include "igaprep/core/atomic_file.h"
#include "igaprep/spline/curve_surface.h"
#include "model_checks.h"
#include "number_text.h"
#include "xml_text.h"

namespace igaprep::exporter {

namespace {
using detail::exact;
using detail::xml_escape;

// "--" may not appear inside an XML comment.
std::string comment_safe(const std::string& s) {
  std::string out;
  for (char c : s) out += (c == '-' && !out.empty() && out.back() == '-') ? std::string(" -") : std::string(1, c);
  return out;
}

void write_tensor_basis(const spline::Patch& p, std::ostream& out, const std::string& indent) {
  out << indent << "<Basis type=\"TensorBSplineBasis3\">\n";
  for (int d = 0; d < 3; ++d) {
    out << indent << " <Basis type=\"BSplineBasis\" index=\"" << d << "\">\n";
    out << indent << "  <KnotVector degree=\"" << p.degrees[d] << "\">";
    for (size_t k = 0; k < p.knots[d].size(); ++k) out << (k ? " " : "") << exact(p.knots[d][k]);
    out << "</KnotVector>\n";
    out << indent << " </Basis>\n";
  }
  out << indent << "</Basis>\n";
}

// One patch as a G+Smo geometry with the given coefficients (its control
// points, or a field on its basis such as the displacement).
void write_geometry(const spline::Patch& p, const Eigen::MatrixXd& coefs, int id, std::ostream& out) {
  const bool nurbs = p.rational();
  out << " <Geometry type=\"" << (nurbs ? "TensorNurbs3" : "TensorBSpline3") << "\" id=\"" << id << "\">\n";
  if (nurbs) {
    out << "  <Basis type=\"TensorNurbsBasis3\">\n";
    write_tensor_basis(p, out, "   ");
    out << "   <weights>";
    for (Eigen::Index k = 0; k < p.weights.size(); ++k) out << (k ? " " : "") << exact(p.weights[k]);
    out << "</weights>\n";
    out << "  </Basis>\n";
  } else {
    write_tensor_basis(p, out, "  ");
  }
  out << "  <coefs geoDim=\"3\">\n";
  for (Eigen::Index r = 0; r < coefs.rows(); ++r)
    out << exact(coefs(r, 0)) << " " << exact(coefs(r, 1)) << " " << exact(coefs(r, 2)) << "\n";
  out << "  </coefs>\n";
  out << " </Geometry>\n";
}

void write_interface(const spline::Interface& f, std::ostream& out) {
  std::array<int, 3> dirmap = f.dirmap, orient = f.orient;
  const int na = f.side_a.direction();
  dirmap[na] = f.side_b.direction();
  orient[na] = f.side_a.parameter() == f.side_b.parameter() ? 1 : 0;
  out << f.patch_a << " " << f.side_a.index() << " " << f.patch_b << " " << f.side_b.index() << " " << dirmap[0] << " "
      << dirmap[1] << " " << dirmap[2] << " " << orient[0] << " " << orient[1] << " " << orient[2] << "\n";
}
// A template of boundary conditions (G+Smo's gsBoundaryConditions, read
// by src/gsPde/gsBoundaryConditions.hpp): every labelled boundary group
// traction-free (Neumann, the zero function), to be edited into Dirichlet
// where the model is held.
void write_boundary_conditions(const spline::MultiPatch& model, int multipatch_id, int id, std::ostream& out) {
  std::map<int, int> labels;
  for (const spline::BoundarySide& b : model.boundaries) ++labels[b.label];
  out << " <!-- Boundary conditions, a template: every labelled boundary traction-free; set type=\"Dirichlet\"\n"
         "      where the model is held (function 0 is the zero displacement). -->\n";
  out << " <boundaryConditions multipatch=\"" << multipatch_id << "\" id=\"" << id << "\">\n";
  out << "  <Function type=\"FunctionExpr\" dim=\"3\" index=\"0\"><c index=\"0\">0</c><c index=\"1\">0</c>"
         "<c index=\"2\">0</c></Function>\n";
  for (const auto& [label, sides] : labels)
    out << "  <bc type=\"Neumann\" function=\"0\" unknown=\"0\" name=\"" << xml_escape(model.labels[label]) << "\"/>\n";
  out << " </boundaryConditions>\n";
}

// Per material a gsOptionList: its name, E, nu and the patches made of it
// (Geometry ids). G+Smo's assemblers take E and nu as options of these names.
void write_material(const spline::MultiPatch& model, int material, int id, std::ostream& out) {
  const spline::Material& m = model.materials[static_cast<std::size_t>(material)];
  std::string patches;
  for (std::size_t i = 0; i < model.patches.size(); ++i)
    if (model.patches[i].material == material) patches += (patches.empty() ? "" : " ") + std::to_string(i);
  out << " <OptionList id=\"" << id << "\">\n";
  out << "  <string label=\"Material\" desc=\"material " << material << "\" value=\"" << xml_escape(m.name) << "\"/>\n";
  out << "  <real label=\"YoungsModulus\" desc=\"Young's modulus\" value=\"" << exact(m.young_modulus) << "\"/>\n";
  out << "  <real label=\"PoissonsRatio\" desc=\"Poisson's ratio\" value=\"" << exact(m.poisson_ratio) << "\"/>\n";
  out << "  <string label=\"Patches\" desc=\"Geometry ids of its patches\" value=\"" << patches << "\"/>\n";
  out << " </OptionList>\n";
}

// A solve result as a second multipatch on the same bases, its
// coefficients the displacement per control point (G+Smo's gsField of the
// geometry's multipatch and this one).
void write_displacement(const spline::MultiPatch& model, int first_id, std::ostream& out) {
  const int np = static_cast<int>(model.patches.size());
  out << " <!-- The displacement of the solve (strain energy " << exact(model.strain_energy)
      << "): a field on the patches' bases, Geometry " << first_id << " + i on patch i. -->\n";
  for (int i = 0; i < np; ++i) write_geometry(model.patches[static_cast<std::size_t>(i)], model.patches[static_cast<std::size_t>(i)].displacement, first_id + i, out);
  out << " <MultiPatch parDim=\"3\" id=\"" << first_id + np << "\">\n";
  out << "  <patches type=\"id_range\">" << first_id << " " << first_id + np - 1 << "</patches>\n";
  out << " </MultiPatch>\n";
}
}  // namespace

void write_gismo_xml(const spline::MultiPatch& model, std::ostream& out) {
  detail::check_model_for_writing(model, "G+Smo XML");
  const int np = static_cast<int>(model.patches.size());
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<xml>\n";
  out << " <!-- igaprep multipatch model: " << np << " patches. Materials (patch: name E nu):\n";
  for (int i = 0; i < np; ++i) {
    const spline::Material& m = model.materials[model.patches[i].material];
    out << "      " << i << ": " << comment_safe(m.name) << " " << exact(m.young_modulus) << " "
        << exact(m.poisson_ratio) << "\n";
  }
  out << " -->\n";
  for (int i = 0; i < np; ++i) write_geometry(model.patches[i], model.patches[i].control_points, i, out);

  out << " <MultiPatch parDim=\"3\" id=\"" << np << "\">\n";
  if (np > 0) out << "  <patches type=\"id_range\">0 " << np - 1 << "</patches>\n";
  // Interfaces grouped by the input surface they lie on (unnamed: none).
  std::map<int, std::vector<const spline::Interface*>> by_surface;
  for (const spline::Interface& f : model.interfaces) by_surface[f.surface].push_back(&f);
  for (const auto& [surface, list] : by_surface) {
    out << "  <interfaces";
    if (surface >= 0) out << " name=\"" << xml_escape(model.labels[surface]) << "\"";
    out << ">\n";
    for (const spline::Interface* f : list) write_interface(*f, out);
    out << "  </interfaces>\n";
  }
  std::map<int, std::vector<const spline::BoundarySide*>> by_label;
  for (const spline::BoundarySide& b : model.boundaries) by_label[b.label].push_back(&b);
  for (const auto& [label, list] : by_label) {
    out << "  <boundary name=\"" << xml_escape(model.labels[label]) << "\">\n";
    for (const spline::BoundarySide* b : list) out << b->patch << " " << b->side.index() << "\n";
    out << "  </boundary>\n";
  }
  out << " </MultiPatch>\n";
  // Ids: the geometries 0..np-1, the multipatch np, then these in turn.
  write_boundary_conditions(model, np, np + 1, out);
  const int materials = static_cast<int>(model.materials.size());
  for (int m = 0; m < materials; ++m) write_material(model, m, np + 2 + m, out);
  const bool displaced = std::all_of(model.patches.begin(), model.patches.end(),
                                     [](const spline::Patch& p) { return p.displacement.size() > 0; });
  if (model.has_solution && np > 0 && displaced) write_displacement(model, np + 2 + materials, out);
  out << "</xml>\n";
}

void write_gismo_xml(const spline::MultiPatch& model, const std::string& path) {
  detail::check_model_for_writing(model, "'" + path + "'");
  write_file_atomically(path, [&](std::ostream& out) { write_gismo_xml(model, out); });
}

}  // namespace igaprep::exporter
