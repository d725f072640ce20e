#include "igaprep/iga_check/report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <utility>

#include "igaprep/core/atomic_file.h"
#include "igaprep/core/error.h"
#include "igaprep/core/text.h"
#include "igaprep/iga_check/model_picture.h"
#include "igaprep/spline/evaluate.h"

namespace igaprep::iga_check {

using nlohmann::ordered_json;

namespace {

// JSON numbers must be finite: non-finite values (never expected) become null.
ordered_json num(double x) { return std::isfinite(x) ? ordered_json(x) : ordered_json(nullptr); }

ordered_json vec3(const Eigen::Vector3d& v) { return ordered_json::array({num(v[0]), num(v[1]), num(v[2])}); }

ordered_json stats_json(const MetricStats& s) {
  ordered_json h = {{"lo", num(s.histogram.lo)}, {"hi", num(s.histogram.hi)}, {"counts", s.histogram.counts}};
  return {{"min", num(s.min)}, {"max", num(s.max)}, {"mean", num(s.mean)}, {"count", s.count}, {"histogram", h}};
}

ordered_json distance_json(const DistanceStats& d) {
  return {{"samples", d.samples},           {"max", num(d.max)},
          {"mean", num(d.mean)},            {"p95", num(d.p95)},
          {"max_relative", num(d.max_relative)}, {"mean_relative", num(d.mean_relative)},
          {"p95_relative", num(d.p95_relative)}, {"max_location", vec3(d.max_location)}};
}

ordered_json element_json(const ElementCertificate& c) {
  return {{"patch", c.patch},
          {"element", {c.element[0], c.element[1], c.element[2]}},
          {"status", to_string(c.status)},
          {"lower_bound", num(c.lower_bound)},
          {"upper_bound", num(c.upper_bound)},
          {"location", vec3(c.location)},
          {"boxes", c.boxes}};
}

// Whole numbers (counts) as JSON integers, others as numbers.
ordered_json figure(double x) {
  if (std::isfinite(x) && x == std::floor(x) && std::abs(x) < 9.0e15) return ordered_json(static_cast<long long>(x));
  return num(x);
}

ordered_json pipeline_json(const PipelineSection& p) {
  ordered_json stages = ordered_json::array();
  double total = 0.0;
  for (const auto& s : p.stages) {
    stages.push_back({{"name", s.name}, {"seconds", num(s.seconds)}});
    total += s.seconds;
  }
  ordered_json figures = ordered_json::object();
  for (const auto& [name, value] : p.figures) figures[name] = figure(value);
  ordered_json j = {{"case", p.case_name},       {"case_file", p.case_file}, {"passed", p.passed},
                    {"verdict", p.verdict},      {"stages", stages},         {"total_seconds", num(total)},
                    {"figures", figures},        {"outputs", p.outputs}};
  if (p.validation) {
    const PipelineValidation& v = *p.validation;
    ordered_json levels = ordered_json::array();
    for (const auto& l : v.levels)
      levels.push_back({{"refine", l.refine},
                        {"elements", l.elements},
                        {"unknowns", l.unknowns},
                        {"h", num(l.h)},
                        {"l2_error", num(l.l2_error)},
                        {"l2_relative", num(l.l2_relative)},
                        {"energy_relative", num(l.energy_relative)},
                        {"seconds", num(l.seconds)}});
    j["validation"] = {{"ran", v.ran},
                       {"message", v.message},
                       {"degree", v.degree},
                       {"patches", v.patches},
                       {"model_patches", v.model_patches},
                       {"patch_list", v.patch_list},
                       {"solver", v.solver},
                       {"levels", levels},
                       {"l2_rate", num(v.l2_rate)},
                       {"energy_rate", num(v.energy_rate)},
                       {"required_rate", num(v.required_rate)},
                       {"met", v.met},
                       {"first_l2_rate", v.first_l2_rate < 0.0 ? ordered_json(nullptr) : ordered_json(num(v.first_l2_rate))}};
  } else {
    j["validation"] = nullptr;
  }
  return j;
}

ordered_json criteria_json(const std::vector<Criterion>& criteria) {
  ordered_json out = ordered_json::array();
  for (const Criterion& c : criteria)
    out.push_back({{"name", c.name},
                   {"checked", c.checked},
                   {"passed", c.passed},
                   {"value", num(c.value)},
                   {"limit", num(c.limit)},
                   {"summary", c.summary},
                   {"findings", c.findings}});
  return out;
}

std::string fmt(double x) {
  if (!std::isfinite(x)) return std::isnan(x) ? "n/a" : (x > 0 ? "inf" : "-inf");
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

std::string esc(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      default: o += c;
    }
  }
  return o;
}

// A histogram as an inline SVG bar chart, bar heights on a log scale (a
// tail of a few samples beside millions stays visible), with the check's
// threshold, 0, marked where it lies inside the range.
std::string svg_histogram(const Histogram& h, const std::string& title) {
  const int W = 520, H = 220, left = 50, right = 10, top = 28, bottom = 36;
  const int n = static_cast<int>(h.counts.size());
  long peak = 1;
  for (long c : h.counts) peak = std::max(peak, c);
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H << "\" viewBox=\"0 0 " << W
    << ' ' << H << "\" role=\"img\">\n";
  s << "<text x=\"" << W / 2 << "\" y=\"18\" text-anchor=\"middle\" class=\"t\">" << esc(title) << "</text>\n";
  const double pw = W - left - right, ph = H - top - bottom;
  s << "<line x1=\"" << left << "\" y1=\"" << top + ph << "\" x2=\"" << left + pw << "\" y2=\"" << top + ph
    << "\" stroke=\"#444\"/>\n";
  for (int b = 0; b < n; ++b) {
    const double bh = ph * std::log1p(static_cast<double>(h.counts[b])) / std::log1p(static_cast<double>(peak));
    const double x = left + pw * b / n;
    s << "<rect x=\"" << fmt(x + 1) << "\" y=\"" << fmt(top + ph - bh) << "\" width=\"" << fmt(pw / n - 2)
      << "\" height=\"" << fmt(bh) << "\" fill=\"#3b7dd8\"><title>[" << fmt(h.lo + (h.hi - h.lo) * b / n) << ", "
      << fmt(h.lo + (h.hi - h.lo) * (b + 1) / n) << "): " << h.counts[b] << "</title></rect>\n";
  }
  if (h.lo < 0.0 && h.hi > 0.0) {
    const double x0 = left + pw * (0.0 - h.lo) / (h.hi - h.lo);
    s << "<line class=\"threshold\" x1=\"" << fmt(x0) << "\" y1=\"" << top << "\" x2=\"" << fmt(x0) << "\" y2=\""
      << top + ph << "\" stroke=\"#c62828\" stroke-dasharray=\"4 3\"><title>0: below it an element folds</title></line>\n";
    s << "<text x=\"" << fmt(x0) << "\" y=\"" << H - 12 << "\" text-anchor=\"middle\" class=\"a\">0</text>\n";
  }
  s << "<text x=\"" << left << "\" y=\"" << H - 12 << "\" class=\"a\">" << fmt(h.lo) << "</text>\n";
  s << "<text x=\"" << left + pw << "\" y=\"" << H - 12 << "\" text-anchor=\"end\" class=\"a\">" << fmt(h.hi)
    << "</text>\n";
  s << "<text x=\"" << left - 4 << "\" y=\"" << top + 10 << "\" text-anchor=\"end\" class=\"a\">" << peak
    << "</text>\n";
  s << "<text x=\"" << left + pw << "\" y=\"" << top - 2 << "\" text-anchor=\"end\" class=\"a\">samples, log scale</text>\n";
  s << "<text x=\"" << left - 4 << "\" y=\"" << top + ph << "\" text-anchor=\"end\" class=\"a\">0</text>\n";
  s << "</svg>\n";
  return s.str();
}

// One row per criterion: result, summary and where it fails.
std::string criteria_html(const std::vector<Criterion>& criteria) {
  std::ostringstream h;
  h << "<table id=\"criteria\">\n<tr><th>criterion</th><th>result</th><th>figure</th><th>where</th></tr>\n";
  for (const Criterion& c : criteria) {
    const char* result = !c.checked ? "\">not checked" : c.passed ? "pass\">pass" : "fail\">FAIL";
    h << "<tr><td>" << esc(c.name) << "</td><td class=\"" << result << "</td><td style=\"text-align:left\">"
      << esc(c.summary) << "</td><td style=\"text-align:left\">";
    for (std::size_t i = 0; i < c.findings.size(); ++i) h << (i ? "<br>" : "") << esc(c.findings[i]);
    h << "</td></tr>\n";
  }
  h << "</table>\n";
  return h.str();
}

// A run's figure in words for report.html (report.json keeps the key, shown
// as the cell's tooltip; docs/check-report.md describes both).
std::string seconds_text(double s) { return text(s < 10.0 ? "%.2f" : "%.1f", s); }

std::string figure_label(const std::string& key) {
  static const std::map<std::string, std::string> words = {
      {"surfaces", "input surfaces"},
      {"materials", "materials"},
      {"tets", "tets of the tet mesh of the cut surfaces"},
      {"patches", "patches"},
      {"degree", "degree (patch 0, direction u)"},
      {"elements_per_direction", "elements per direction (patch 0, direction u)"},
      {"elements", "Bezier elements"},
      {"control_points", "control points, summed over patches"},
      {"interfaces", "interfaces"},
      {"boundary_sides", "labelled boundary sides"},
      {"unmatched_sides", "sides neither on an interface nor labelled"},
      {"stitched_control_points", "control points made identical where patches meet"},
      {"max_stitch", "largest move that made them identical"},
      {"fit_min_scaled_jacobian", "lowest sampled scaled Jacobian of the fit, before the repair"},
      {"optimized_min_scaled_jacobian", "lowest sampled scaled Jacobian after the repair"},
      {"optimized_control_points", "control points the repair moved"},
      {"reduce_tolerance_asked", "data reduction: tolerance asked"},
      {"reduce_tolerance", "data reduction: tolerance used"},
      {"reduce_bound", "data reduction: no point moved farther than"},
      {"reduce_measured_deviation", "data reduction: largest deviation measured"},
      {"reduce_control_points_before", "data reduction: control points before"},
      {"reduce_elements_before", "data reduction: elements before"},
      {"reduce_uncertified_elements_before", "data reduction: elements not certified before"},
      {"reduce_knots_removed", "data reduction: knots removed"},
      {"reduce_removals_undone", "data reduction: removals undone to keep certificates"},
      {"positive_elements", "elements certified positive"},
      {"negative_elements", "elements with a negative Jacobian"},
      {"degenerate_elements", "degenerate elements"},
      {"undecided_elements", "undecided elements"},
      {"min_scaled_jacobian", "smallest scaled Jacobian"},
      {"interface_gap_relative", "largest gap at an interface, relative to the diagonal"},
      {"load_case_unknowns", "load case: unknowns"},
      {"load_case_strain_energy", "load case: strain energy"},
      {"load_case_max_displacement", "load case: largest displacement"}};
  if (const auto it = words.find(key); it != words.end()) return it->second;
  for (const auto& [prefix, text] : {std::pair<std::string, std::string>{"fidelity_relative_", "fidelity, surface "},
                                     {"volume_difference_region_", "volume difference, region "}})
    if (key.rfind(prefix, 0) == 0) return text + key.substr(prefix.size()) + " (relative)";
  std::string out = key;
  std::replace(out.begin(), out.end(), '_', ' ');
  return out;
}

// The run's section of report.html: verdict, stage times, figures, validation.
std::string pipeline_html(const PipelineSection& p) {
  std::ostringstream h;
  h << "<h2 id=\"pipeline\">Pipeline run</h2>\n<p>Case <code>" << esc(p.case_name) << "</code> (<code>"
    << esc(p.case_file) << "</code>)</p>\n<p id=\"pipeline-verdict\" class=\"" << (p.passed ? "pass" : "fail")
    << "\">" << esc(p.verdict) << "</p>\n";
  h << "<table>\n<tr><th>stage</th><th>seconds</th></tr>\n";
  double total = 0.0;
  for (const auto& s : p.stages) {
    h << "<tr><td>" << esc(s.name) << "</td><td>" << seconds_text(s.seconds) << "</td></tr>\n";
    total += s.seconds;
  }
  h << "<tr><th>total</th><th>" << seconds_text(total) << "</th></tr>\n</table>\n";
  h << "<table>\n<tr><th>figure</th><th>value</th></tr>\n";
  for (const auto& [name, value] : p.figures)
    h << "<tr><td title=\"" << esc(name) << "\">" << esc(figure_label(name)) << "</td><td>" << fmt(value)
      << "</td></tr>\n";
  h << "</table>\n";
  if (p.validation) {
    const PipelineValidation& v = *p.validation;
    h << "<h3>Manufactured-solution validation</h3>\n";
    if (!v.ran) {
      h << "<p class=\"fail\">Not run: " << esc(v.message) << "</p>\n";
    } else {
      h << "<p>" << v.patches << " of " << v.model_patches << " patches, degree " << v.degree << ", solver "
        << esc(v.solver) << ". L2 rate <b>" << fmt(v.l2_rate) << "</b> (required &ge; " << fmt(v.required_rate)
        << "; optimal " << v.degree + 1 << "), energy rate " << fmt(v.energy_rate) << ": <span class=\""
        << (v.met ? "pass\">met" : "fail\">NOT met") << "</span></p>\n";
      if (v.first_l2_rate >= 0.0)
        h << "<p>At the case's levels the L2 rate was " << fmt(v.first_l2_rate)
          << ", below the rate asked: the study was made once more a level finer (the table).</p>\n";
      h << "<table>\n<tr><th>refine</th><th>elements</th><th>unknowns</th><th>h</th><th>L2 error</th><th>relative "
           "L2 error</th><th>relative energy error</th><th>seconds</th></tr>\n";
      for (const auto& l : v.levels)
        h << "<tr><td>" << l.refine << "</td><td>" << l.elements << "</td><td>" << l.unknowns << "</td><td>"
          << fmt(l.h) << "</td><td>" << fmt(l.l2_error) << "</td><td>" << fmt(l.l2_relative) << "</td><td>"
          << fmt(l.energy_relative) << "</td><td>" << fmt(l.seconds) << "</td></tr>\n";
      h << "</table>\n";
    }
  }
  if (!p.outputs.empty()) {
    h << "<p>Files written (beside this report):";
    for (const auto& o : p.outputs) h << " <a href=\"" << esc(o) << "\"><code>" << esc(o) << "</code></a>";
    h << "</p>\n";
  }
  return h.str();
}

}  // namespace

namespace {

// Per-patch counts of the certificates and the patches that fail.
void summarize_patches(CheckReport& r, const spline::MultiPatch& mp, bool allow_degenerate) {
  r.patches.resize(mp.patches.size());
  for (size_t p = 0; p < mp.patches.size(); ++p) {
    r.patches[p].patch = static_cast<int>(p);
    r.patches[p].material = mp.patches[p].material;
    r.patches[p].det_j_lower_bound = std::numeric_limits<double>::infinity();
  }
  for (const auto& c : r.certificates) {
    PatchSummary& s = r.patches[c.patch];
    ++s.elements;
    switch (c.status) {
      case ElementStatus::Positive: ++s.positive; break;
      case ElementStatus::Negative: ++s.negative; break;
      case ElementStatus::Degenerate: ++s.degenerate; break;
      case ElementStatus::Undecided: ++s.undecided; break;
    }
    s.det_j_lower_bound = std::min(s.det_j_lower_bound, c.lower_bound);
    if (!element_certified(c, allow_degenerate)) s.passed = false;
  }
  for (const auto& s : r.patches)
    if (!s.passed) r.failed_patches.push_back(s.patch);
}

// Failing elements first, then by certified lower bound.
std::vector<ElementCertificate> worst_elements_of(const CheckReport& r, const CheckOptions& options) {
  std::vector<ElementCertificate> sorted = r.certificates;
  std::stable_sort(sorted.begin(), sorted.end(), [&](const ElementCertificate& a, const ElementCertificate& b) {
    const bool pa = element_certified(a, options.allow_degenerate), pb = element_certified(b, options.allow_degenerate);
    if (pa != pb) return !pa;
    return a.lower_bound < b.lower_bound;
  });
  if (static_cast<int>(sorted.size()) > options.worst_elements) sorted.resize(options.worst_elements);
  return sorted;
}

Criterion jacobian_criterion(const CheckReport& r, std::size_t patches, bool allow_degenerate) {
  const ElementTotals t = element_totals(r);
  Criterion c;
  c.name = "jacobian";
  c.passed = r.failed_patches.empty();
  c.value = static_cast<double>(t.negative + t.undecided + (allow_degenerate ? 0 : t.degenerate));
  std::ostringstream v;
  if (c.passed) {
    v << "all " << t.elements << " elements of " << patches << " patches certified: " << t.positive << " positive";
    if (t.degenerate > 0) v << ", " << t.degenerate << " degenerate (det J = 0 only on the element boundary, allowed)";
  } else {
    v << "patches";
    for (int p : r.failed_patches) v << ' ' << p;
    v << " not certified positive (" << t.negative << " negative, " << t.degenerate << " degenerate"
      << (allow_degenerate ? " allowed" : "") << ", " << t.undecided << " undecided elements)";
    if (!allow_degenerate && t.negative == 0 && t.undecided == 0)
      v << "; only degenerate elements fail: a check that allows degenerate elements "
           "(CheckOptions::allow_degenerate) accepts them";
  }
  c.summary = v.str();
  return c;
}

// One line: PASS with the certified elements, fidelity and volume, or FAIL
// and every failed criterion.
std::string verdict_of(const CheckReport& r) {
  std::string v;
  for (const Criterion& c : r.criteria) {
    const bool shown = r.passed ? c.name == "jacobian" || c.name == "fidelity" || c.name == "volume" : !c.passed;
    if (!shown) continue;
    if (!v.empty()) v += "; ";
    v += r.passed && c.name == "jacobian" ? c.summary : c.name + ": " + c.summary;
  }
  return (r.passed ? "PASS: " : "FAIL: ") + v;
}

}  // namespace

CheckReport build_check_report(const spline::MultiPatch& mp, const std::vector<mesh::TriMesh>& surfaces,
                               const std::vector<std::string>& surface_labels, const CheckOptions& options,
                               const std::string& model) {
  CheckReport r;
  r.model = model;
  r.allow_degenerate = options.allow_degenerate;
  r.surface_labels = surface_labels;
  for (size_t i = r.surface_labels.size(); i < surfaces.size(); ++i)
    r.surface_labels.push_back(i < mp.labels.size() ? mp.labels[i] : "surface " + std::to_string(i));
  for (const auto& m : mp.materials) r.material_names.push_back(m.name);
  if (mp.patches.empty()) throw bad_input("check: the model has no patches");
  if (!(options.fidelity_limit > 0.0) || !(options.volume_limit > 0.0))
    throw bad_input("check: the fidelity and volume limits must be positive");
  r.diagonal = model_diagonal(mp);
  r.input_diagonal = surfaces.empty() ? 0.0 : mesh_diagonal(surfaces.front());
  if (!surfaces.empty() && !(r.input_diagonal > 0.0)) throw bad_input("check: the outer input surface has no extent");
  r.certificates = certify_model(mp, options.certify);
  r.quality = quality_metrics(mp, options.quality);
  r.fidelity = fidelity(mp, surfaces, surfaces.empty() ? r.diagonal : r.input_diagonal, options.fidelity);
  r.topology = topology_checks(mp, surfaces, r.diagonal, options.conformity_tolerance);
  summarize_patches(r, mp, options.allow_degenerate);
  r.worst_elements = worst_elements_of(r, options);

  r.criteria = {jacobian_criterion(r, mp.patches.size(), options.allow_degenerate),
                conformity_criterion(r.topology, options.conformity_tolerance), watertight_criterion(r.topology),
                fidelity_criterion(r.fidelity, surfaces, r.surface_labels, r.input_diagonal, options.fidelity_limit),
                volume_criterion(r.topology, r.surface_labels, std::max(1, static_cast<int>(mp.materials.size())),
                                 options.volume_limit)};
  std::vector<double> patch_min;
  std::vector<bool> patch_failed;
  for (std::size_t p = 0; p < r.patches.size() && p < r.quality.patches.size(); ++p) {
    patch_min.push_back(r.quality.patches[p].scaled_jacobian.min);
    patch_failed.push_back(!r.patches[p].passed);
  }
  std::vector<PictureMark> marks;
  for (std::size_t i = 0; i < r.worst_elements.size() && i < 5; ++i) {
    const ElementCertificate& c = r.worst_elements[i];
    marks.push_back({spline::evaluate_point(mp.patches[static_cast<std::size_t>(c.patch)], c.location), std::to_string(i + 1)});
  }
  r.picture_svg = model_picture_svg(mp, patch_min, patch_failed, PictureColour::quality, marks);
  r.picture_by_patch_svg = model_picture_svg(mp, patch_min, patch_failed, PictureColour::patch);
  r.picture_by_material_svg = model_picture_svg(mp, patch_min, patch_failed, PictureColour::material);
  r.passed = std::all_of(r.criteria.begin(), r.criteria.end(), [](const Criterion& c) { return c.passed; });
  for (const Criterion& c : r.criteria)
    if (!c.checked) r.warnings.push_back(c.name + " " + c.summary);
  r.verdict = verdict_of(r);
  return r;
}

ElementTotals element_totals(const CheckReport& r) {
  ElementTotals t;
  for (const PatchSummary& p : r.patches) {
    t.elements += p.elements;
    t.positive += p.positive;
    t.negative += p.negative;
    t.degenerate += p.degenerate;
    t.undecided += p.undecided;
  }
  return t;
}

std::vector<std::string> failure_lines(const CheckReport& r) {
  std::vector<std::string> out;
  for (const Criterion& c : r.criteria) {
    if (c.passed) continue;
    out.push_back(c.name + " FAILED: " + c.summary);
    for (const std::string& f : c.findings) out.push_back("  " + f);
  }
  return out;
}

std::string report_json(const CheckReport& r) {
  ordered_json j;
  j["format"] = "igaprep-check-report";
  j["format_version"] = 1;
  j["model"] = r.model;
  j["generator"] = r.generator;
  j["date"] = r.date;
  const ElementTotals totals = element_totals(r);
  double min_lower = std::numeric_limits<double>::infinity();
  for (const auto& c : r.certificates) min_lower = std::min(min_lower, c.lower_bound);
  j["summary"] = {{"passed", r.passed},
                  {"verdict", r.verdict},
                  {"allow_degenerate", r.allow_degenerate},
                  {"patches", r.patches.size()},
                  {"elements", totals.elements},
                  {"positive", totals.positive},
                  {"negative", totals.negative},
                  {"degenerate", totals.degenerate},
                  {"undecided", totals.undecided},
                  {"failed_patches", r.failed_patches},
                  {"min_det_j_lower_bound", num(min_lower)},
                  {"min_scaled_jacobian", num(r.quality.overall.scaled_jacobian.min)},
                  {"warnings", r.warnings},
                  {"criteria", criteria_json(r.criteria)}};
  j["bounding_box_diagonal"] = num(r.diagonal);
  j["input_diagonal"] = num(r.input_diagonal);
  ordered_json patches = ordered_json::array();
  for (size_t p = 0; p < r.patches.size(); ++p) {
    const PatchSummary& s = r.patches[p];
    const PatchQuality& q = r.quality.patches[p];
    patches.push_back({{"index", s.patch},
                       {"material", s.material},
                       {"passed", s.passed},
                       {"elements", s.elements},
                       {"positive", s.positive},
                       {"negative", s.negative},
                       {"degenerate", s.degenerate},
                       {"undecided", s.undecided},
                       {"det_j_lower_bound", num(s.det_j_lower_bound)},
                       {"volume", num(r.topology.patch_volumes[p])},
                       {"region", p < r.topology.patch_region.size() ? r.topology.patch_region[p] : -1},
                       {"points", q.points},
                       {"singular_points", q.singular_points},
                       {"det_j", stats_json(q.det_j)},
                       {"scaled_jacobian", stats_json(q.scaled_jacobian)},
                       {"condition", stats_json(q.condition)}});
  }
  j["patches"] = patches;
  j["quality"] = {{"points", r.quality.overall.points},
                  {"singular_points", r.quality.overall.singular_points},
                  {"det_j", stats_json(r.quality.overall.det_j)},
                  {"scaled_jacobian", stats_json(r.quality.overall.scaled_jacobian)},
                  {"condition", stats_json(r.quality.overall.condition)}};
  ordered_json failing = ordered_json::array();
  for (const auto& c : r.certificates)
    if (c.status != ElementStatus::Positive) failing.push_back(element_json(c));
  j["non_positive_elements"] = failing;
  ordered_json worst = ordered_json::array();
  for (const auto& c : r.worst_elements) worst.push_back(element_json(c));
  j["worst_elements"] = worst;
  ordered_json points = ordered_json::array();
  for (const auto& q : r.quality.worst)
    points.push_back({{"patch", q.patch},
                      {"element", {q.element[0], q.element[1], q.element[2]}},
                      {"uvw", vec3(q.uvw)},
                      {"x", vec3(q.x)},
                      {"det_j", num(q.det_j)},
                      {"scaled_jacobian", num(q.scaled_jacobian)},
                      {"condition", num(q.condition)}});
  j["worst_points"] = points;
  ordered_json fid = ordered_json::array();
  for (const auto& f : r.fidelity)
    fid.push_back({{"surface", f.surface},
                   {"label", f.surface < static_cast<int>(r.surface_labels.size()) ? r.surface_labels[f.surface] : f.label},
                   {"boundary_faces", f.boundary_faces},
                   {"interface_faces", f.interface_faces},
                   {"spline_to_mesh", distance_json(f.spline_to_mesh)},
                   {"mesh_to_spline", distance_json(f.mesh_to_spline)}});
  j["fidelity"] = fid;
  const TopologyReport& t = r.topology;
  ordered_json collapsed = ordered_json::array();
  for (const auto& s : t.sides)
    if (s.kind == "collapsed") collapsed.push_back({s.patch, s.side.index()});
  ordered_json mats = ordered_json::array();
  for (size_t m = 0; m < t.material_volumes.size(); ++m)
    mats.push_back({{"index", m},
                    {"name", m < r.material_names.size() ? r.material_names[m] : ""},
                    {"volume", num(t.material_volumes[m])}});
  ordered_json regions = ordered_json::array();
  for (const auto& rv : t.regions)
    regions.push_back({{"region", rv.region},
                       {"outer_surface", rv.region < static_cast<int>(r.surface_labels.size()) ? r.surface_labels[rv.region] : ""},
                       {"input_volume", num(rv.input_volume)},
                       {"spline_volume", num(rv.spline_volume)},
                       {"patches", rv.patches},
                       {"relative_difference", num(rv.relative_difference)}});
  j["topology"] = {{"conforming", t.conforming},
                   {"interface_max_gap", num(t.interface_max_gap)},
                   {"interface_max_gap_relative", num(t.interface_max_gap_relative)},
                   {"conformity_problems", t.conformity_problems},
                   {"watertight", t.watertight},
                   {"watertight_problems", t.watertight_problems},
                   {"collapsed_sides", collapsed},
                   {"material_volumes", mats},
                   {"regions", regions}};
  if (r.pipeline) j["pipeline"] = pipeline_json(*r.pipeline);
  return j.dump(2) + "\n";
}

namespace {
// ParaView steps for the VTU files a run writes beside this report.
std::string how_to_view_html() {
  return "<h2>How to view the model</h2>\n<ol>\n<li>Open <code>model.vtu</code> (or <code>run.pvd</code>, which "
         "groups the model, its boundary and the solve's result) in ParaView and press Apply.</li>\n<li>The cells are "
         "curved Bezier hexahedra: in the Properties panel set <em>Nonlinear Subdivision Level</em> to 2.</li>\n"
         "<li>Choose <em>Surface With Edges</em> and colour by <code>patch</code>, <code>material</code> or "
         "<code>min_scaled_jacobian</code> (cell data; 1 is a perfect cube, below 0 folded).</li>\n<li>"
         "<code>model_boundary.vtu</code> is the labelled outer surface alone (colour by <code>label</code>). To see "
         "inside, <em>Slice</em> and colour the slice by the point array <code>material</code>.</li>\n</ol>\n";
}
}  // namespace

std::string report_html(const CheckReport& r) {
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>igaprep check: "
    << esc(r.model) << "</title>\n<style>\n"
    << "body{font-family:sans-serif;margin:2em;max-width:70em;color:#222}\n"
    << "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #bbb;padding:3px 8px;text-align:right}\n"
    << "th{background:#eee}.pass{color:#1a7f37;font-weight:bold}.fail{color:#c62828;font-weight:bold}\n"
    << "svg .t{font-size:14px}svg .a{font-size:11px}\n"
    << ".pair{display:flex;gap:1em}.pair figure{margin:0;flex:1}.pair svg{width:100%;height:auto}\n"
    << "</style>\n</head>\n<body>\n";
  h << "<h1>Analysis-suitability report</h1>\n<p>Model: <code>" << esc(r.model) << "</code>; bounding-box diagonal "
    << fmt(r.diagonal) << "</p>\n";
  if (!r.generator.empty() || !r.date.empty())
    h << "<p id=\"made\">Made by " << esc(r.generator.empty() ? "igaprep" : r.generator)
      << (r.date.empty() ? "" : " on " + esc(r.date)) << ".</p>\n";
  h << "<p id=\"verdict\" class=\"" << (r.passed ? "pass" : "fail") << "\">" << esc(r.verdict) << "</p>\n";
  h << criteria_html(r.criteria);
  if (!r.picture_svg.empty())
    h << "<h2>Model</h2>\n<figure>\n" << r.picture_svg
      << "<figcaption>The labelled boundary, one face per element, coloured by its patch's smallest sampled scaled "
         "Jacobian (red 0 or less, yellow 0.5, blue 1); patches that fail are outlined in red; the rings 1 to 5 mark "
         "the worst elements of the table below (seen through the model).</figcaption>\n</figure>\n<div class=\"pair\">\n<figure>\n"
      << r.picture_by_patch_svg << "<figcaption>The same view coloured by patch.</figcaption>\n</figure>\n<figure>\n"
      << r.picture_by_material_svg << "<figcaption>The same view coloured by material.</figcaption>\n</figure>\n</div>\n"
      << how_to_view_html();
  if (r.pipeline) h << pipeline_html(*r.pipeline);
  h << "<h2>Patches</h2>\n<table>\n<tr><th>patch</th><th>material</th><th>elements</th><th>positive</th>"
       "<th>negative</th><th>degenerate</th><th>undecided</th><th>certified min det J &ge;</th><th>min det J "
       "(sampled)</th><th>min scaled J</th><th>mean scaled J</th><th>max condition</th><th>volume</th><th>result</th></tr>\n";
  for (size_t p = 0; p < r.patches.size(); ++p) {
    const auto& s = r.patches[p];
    const auto& q = r.quality.patches[p];
    h << "<tr><td>" << s.patch << "</td><td>" << s.material << "</td><td>" << s.elements << "</td><td>" << s.positive
      << "</td><td>" << s.negative << "</td><td>" << s.degenerate << "</td><td>" << s.undecided << "</td><td>"
      << fmt(s.det_j_lower_bound) << "</td><td>" << fmt(q.det_j.min) << "</td><td>" << fmt(q.scaled_jacobian.min)
      << "</td><td>" << fmt(q.scaled_jacobian.mean) << "</td><td>" << fmt(q.condition.max) << "</td><td>"
      << fmt(r.topology.patch_volumes[p]) << "</td><td class=\"" << (s.passed ? "pass\">pass" : "fail\">FAIL")
      << "</td></tr>\n";
  }
  h << "</table>\n<h2>Histograms (all sample points)</h2>\n";
  h << svg_histogram(r.quality.overall.scaled_jacobian.histogram, "scaled Jacobian");
  h << svg_histogram(r.quality.overall.det_j.histogram, "det J");
  h << "<h2>Worst elements (certified lower bound of det J)</h2>\n<table>\n<tr><th>#</th><th>patch</th><th>element</th>"
       "<th>status</th><th>lower bound</th><th>upper bound</th><th>at (u, v, w)</th></tr>\n";
  for (std::size_t i = 0; i < r.worst_elements.size(); ++i) {
    const ElementCertificate& c = r.worst_elements[i];
    h << "<tr><td>" << i + 1 << "</td><td>" << c.patch << "</td><td>" << c.element[0] << ", " << c.element[1] << ", " << c.element[2]
      << "</td><td>" << to_string(c.status) << "</td><td>" << fmt(c.lower_bound) << "</td><td>" << fmt(c.upper_bound)
      << "</td><td>" << fmt(c.location[0]) << ", " << fmt(c.location[1]) << ", " << fmt(c.location[2]) << "</td></tr>\n";
  }
  h << "</table>\n<h2>Worst points (scaled Jacobian)</h2>\n<table>\n<tr><th>patch</th><th>element</th><th>(u, v, "
       "w)</th><th>scaled J</th><th>det J</th><th>condition</th></tr>\n";
  for (const auto& q : r.quality.worst)
    h << "<tr><td>" << q.patch << "</td><td>" << q.element[0] << ", " << q.element[1] << ", " << q.element[2]
      << "</td><td>" << fmt(q.uvw[0]) << ", " << fmt(q.uvw[1]) << ", " << fmt(q.uvw[2]) << "</td><td>"
      << fmt(q.scaled_jacobian) << "</td><td>" << fmt(q.det_j) << "</td><td>" << fmt(q.condition) << "</td></tr>\n";
  h << "</table>\n";
  if (!r.fidelity.empty()) {
    h << "<h2>Fidelity to the input surfaces (relative to the diagonal)</h2>\n<table>\n<tr><th>surface</th>"
         "<th>faces</th><th>spline&rarr;mesh max</th><th>mean</th><th>95%</th><th>mesh&rarr;spline "
         "max</th><th>mean</th><th>95%</th></tr>\n";
    for (const auto& f : r.fidelity)
      h << "<tr><td>" << esc(f.surface < static_cast<int>(r.surface_labels.size()) ? r.surface_labels[f.surface] : f.label)
        << "</td><td>" << f.boundary_faces + f.interface_faces << "</td><td>" << fmt(f.spline_to_mesh.max_relative)
        << "</td><td>" << fmt(f.spline_to_mesh.mean_relative) << "</td><td>" << fmt(f.spline_to_mesh.p95_relative)
        << "</td><td>" << fmt(f.mesh_to_spline.max_relative) << "</td><td>" << fmt(f.mesh_to_spline.mean_relative)
        << "</td><td>" << fmt(f.mesh_to_spline.p95_relative) << "</td></tr>\n";
    h << "</table>\n";
  }
  const TopologyReport& t = r.topology;
  h << "<h2>Topology and volumes</h2>\n<p>Interfaces: " << (t.conforming ? "conforming" : "NOT conforming")
    << ", largest control-point gap " << fmt(t.interface_max_gap) << ". Outer boundary: "
    << (t.watertight ? "watertight" : "NOT watertight") << ".</p>\n";
  if (!t.regions.empty()) {
    h << "<table>\n<tr><th>region</th><th>inside</th><th>patches</th><th>input volume</th><th>spline "
         "volume</th><th>difference</th></tr>\n";
    for (const auto& rv : t.regions)
      h << "<tr><td>" << rv.region << "</td><td>"
        << esc(rv.region < static_cast<int>(r.surface_labels.size()) ? r.surface_labels[rv.region] : "") << "</td><td>"
        << rv.patches << "</td><td>" << fmt(rv.input_volume) << "</td><td>" << fmt(rv.spline_volume) << "</td><td>"
        << (rv.patches > 0 ? fmt(100 * rv.relative_difference) + " %" : "void") << "</td></tr>\n";
    h << "</table>\n";
  }
  h << "<table>\n<tr><th>material</th><th>volume</th></tr>\n";
  for (size_t m = 0; m < t.material_volumes.size(); ++m)
    h << "<tr><td>" << esc(m < r.material_names.size() ? r.material_names[m] : std::to_string(m)) << "</td><td>"
      << fmt(t.material_volumes[m]) << "</td></tr>\n";
  h << "</table>\n</body>\n</html>\n";
  return h.str();
}

void write_report(const CheckReport& r, const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw bad_input("check: cannot create the report folder " + dir + ": " + ec.message());
  const std::string json = report_json(r), html = report_html(r);
  write_file_atomically((std::filesystem::path(dir) / "report.json").string(), [&](std::ostream& o) { o << json; });
  write_file_atomically((std::filesystem::path(dir) / "report.html").string(), [&](std::ostream& o) { o << html; });
}

}  // namespace igaprep::iga_check
