// G+Smo XML writer. Conventions follow G+Smo's reader (src/gsIO/gsXml.cpp
// getInterfaces / getBoundaries, gsXmlUtils.hpp gsXml<gsMultiPatch>):
// patch numbers in <interfaces> and <boundary> are Geometry ids, mapped
// through <patches>; sides are 1..6 (u0 u1 v0 v1 w0 w1); for the normal
// direction G+Smo itself sets dirmap = normal of patch b and orient =
// (both sides at the same end), so we write exactly those values there.
#include "igaprep/export/gismo_xml.h"

#include <map>
#include <vector>

#include "igaprep/core/atomic_file.h"
#include "igaprep/spline/curve_surface.h"
#include "model_checks.h"
#include "number_text.h"

namespace igaprep::exporter {

namespace {
using detail::exact;

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

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

void write_geometry(const spline::Patch& p, int id, std::ostream& out) {
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
  for (Eigen::Index r = 0; r < p.control_points.rows(); ++r)
    out << exact(p.control_points(r, 0)) << " " << exact(p.control_points(r, 1)) << " "
        << exact(p.control_points(r, 2)) << "\n";
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
  for (int i = 0; i < np; ++i) write_geometry(model.patches[i], i, out);

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
  out << " </MultiPatch>\n</xml>\n";
}

void write_gismo_xml(const spline::MultiPatch& model, const std::string& path) {
  detail::check_model_for_writing(model, "'" + path + "'");
  write_file_atomically(path, [&](std::ostream& out) { write_gismo_xml(model, out); });
}

}  // namespace igaprep::exporter
