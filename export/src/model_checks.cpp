#include "model_checks.h"

#include <algorithm>
#include <cmath>

#include "igaprep/core/error.h"
#include "igaprep/core/text.h"
#include "igaprep/spline/multipatch_topology.h"

namespace igaprep::exporter::detail {

void check_model_for_writing(const spline::MultiPatch& model, const std::string& what) {
  if (model.patches.empty()) throw bad_input("cannot write " + what + ": the model has no patches");
  // Names go into XML and text formats: well-formed UTF-8 only.
  auto check_name = [&](const std::string& name, const std::string& kind) {
    const std::size_t at = invalid_text_at(name);
    if (at != std::string::npos)
      throw bad_input("cannot write " + what + ": " + kind + " is not UTF-8 text (byte " + std::to_string(at) + ")");
  };
  for (std::size_t i = 0; i < model.labels.size(); ++i) check_name(model.labels[i], "label " + std::to_string(i));
  for (std::size_t i = 0; i < model.materials.size(); ++i)
    check_name(model.materials[i].name, "material " + std::to_string(i) + "'s name");
  // Structure (knots, counts, weights, indices, sides, dirmaps): the spline
  // module's validation; the message gains the output file's name.
  try {
    spline::validate_multipatch(model);
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::BadInput) throw;
    throw bad_input("cannot write " + what + ": " + e.what());
  }
  // Sizes the writers rely on for memory safety (cheap, repeated on purpose),
  // then what only files carry: solve results and material constants.
  for (size_t i = 0; i < model.patches.size(); ++i) {
    const spline::Patch& p = model.patches[i];
    long long n = 1;
    for (int d = 0; d < 3; ++d) n *= std::max(0, p.count(d));
    if (p.control_points.rows() != n || p.control_points.cols() != 3 || (p.rational() && p.weights.size() != n))
      throw bad_input("cannot write " + what + ": patch " + std::to_string(i) +
                      ": control point or weight count does not match the knot vectors");
    if (p.displacement.size() == 0) continue;
    const std::string name = "cannot write " + what + ": patch " + std::to_string(i);
    if (p.displacement.rows() != p.control_points.rows() || p.displacement.cols() != 3)
      throw bad_input(name + ": displacement is " + std::to_string(p.displacement.rows()) + " x " +
                      std::to_string(p.displacement.cols()) + ", expected " +
                      std::to_string(p.control_points.rows()) + " x 3 (one row per control point)");
    if (!p.displacement.allFinite()) throw bad_input(name + ": non-finite displacement");
  }
  for (size_t m = 0; m < model.materials.size(); ++m) {
    const spline::Material& mat = model.materials[m];
    if (!std::isfinite(mat.young_modulus) || !std::isfinite(mat.poisson_ratio))
      throw bad_input("cannot write " + what + ": material " + std::to_string(m) + " has a non-finite constant");
  }
  if (model.has_solution && (!std::isfinite(model.strain_energy) || !std::isfinite(model.max_displacement)))
    throw bad_input("cannot write " + what + ": non-finite strain energy or max displacement");
}

}  // namespace igaprep::exporter::detail
