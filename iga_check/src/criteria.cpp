#include "igaprep/iga_check/criteria.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "igaprep/core/text.h"

namespace igaprep::iga_check {

namespace {

std::string label_of(const std::vector<std::string>& labels, int i) {
  return i >= 0 && i < static_cast<int>(labels.size()) && !labels[i].empty() ? "'" + labels[i] + "'"
                                                                             : "surface " + std::to_string(i);
}

// Appends at most kMaxFindings lines of `lines`, then how many were left out.
void add_findings(Criterion& c, const std::vector<std::string>& lines) {
  for (const std::string& l : lines) {
    if (static_cast<int>(c.findings.size()) == kMaxFindings - 1 &&
        lines.size() > static_cast<std::size_t>(kMaxFindings)) {
      c.findings.push_back(text("... and %zu more", lines.size() - c.findings.size()));
      return;
    }
    c.findings.push_back(l);
  }
}

Criterion not_checked(const std::string& name, const std::string& why) {
  Criterion c;
  c.name = name;
  c.checked = false;
  c.summary = "not checked: " + why;
  return c;
}

constexpr std::size_t kRegionsNamed = 4, kFacesNamed = 3;  // per surface

// Where one surface is not met: the parts of it no spline face comes near,
// then the spline faces farthest off it.
std::vector<std::string> fidelity_findings(const SurfaceFidelity& f, const mesh::TriMesh& surface,
                                           const std::string& label, double diagonal, double limit) {
  std::vector<std::string> out;
  const std::vector<UncoveredRegion> regions = uncovered_regions(surface, f.vertex_distance, limit * diagonal);
  for (std::size_t i = 0; i < regions.size() && i < kRegionsNamed; ++i) {
    const UncoveredRegion& r = regions[i];
    out.push_back(text("%s: %d input %s around %s not covered, the farthest %.3f %% of the diagonal away at %s",
                       label.c_str(), r.vertices, r.vertices == 1 ? "vertex" : "vertices", point_text(r.centroid).c_str(),
                       100.0 * r.max / diagonal, point_text(r.farthest).c_str()));
  }
  if (regions.size() > kRegionsNamed)
    out.push_back(text("%s: %zu more uncovered regions", label.c_str(), regions.size() - kRegionsNamed));
  std::vector<FaceDistance> faces;
  for (const FaceDistance& fd : f.faces)
    if (fd.max > limit * diagonal) faces.push_back(fd);
  std::stable_sort(faces.begin(), faces.end(), [](const FaceDistance& a, const FaceDistance& b) { return a.max > b.max; });
  for (std::size_t i = 0; i < faces.size() && i < kFacesNamed; ++i)
    out.push_back(text("%s: patch %d side %d (%s) lies up to %.3f %% of the diagonal off it, at %s", label.c_str(),
                       faces[i].patch, faces[i].side.index(), faces[i].interface ? "interface" : "boundary",
                       100.0 * faces[i].max / diagonal, point_text(faces[i].max_location).c_str()));
  if (faces.size() > kFacesNamed)
    out.push_back(text("%s: %zu more spline faces beyond the limit", label.c_str(), faces.size() - kFacesNamed));
  return out;
}

}  // namespace

Criterion conformity_criterion(const TopologyReport& t, double tolerance) {
  Criterion c;
  c.name = "conformity";
  c.value = t.interface_max_gap_relative;
  c.limit = tolerance;
  c.passed = t.conforming;
  c.summary = text("largest interface control-point gap %.2e of the diagonal (limit %.1e)", c.value, tolerance);
  add_findings(c, t.conformity_problems);
  return c;
}

Criterion watertight_criterion(const TopologyReport& t) {
  Criterion c;
  c.name = "watertight";
  c.passed = t.watertight;
  c.value = static_cast<double>(t.watertight_problems.size());
  c.summary = t.watertight ? "every side an interface, a labelled boundary or collapsed"
                           : text("%zu sides neither an interface, a labelled boundary nor collapsed",
                                  t.watertight_problems.size());
  add_findings(c, t.watertight_problems);
  return c;
}

Criterion fidelity_criterion(const std::vector<SurfaceFidelity>& fidelity, const std::vector<mesh::TriMesh>& surfaces,
                             const std::vector<std::string>& labels, double input_diagonal, double limit) {
  if (surfaces.empty()) return not_checked("fidelity", "no input surfaces");
  Criterion c;
  c.name = "fidelity";
  c.limit = limit;
  std::vector<std::string> lines;
  std::vector<bool> measured(surfaces.size(), false);
  for (const SurfaceFidelity& f : fidelity) {
    measured[static_cast<std::size_t>(f.surface)] = true;
    const double worst = std::max(f.spline_to_mesh.max, f.mesh_to_spline.max) / input_diagonal;
    c.value = std::max(c.value, worst);
    if (worst > limit) {
      const std::string label = label_of(labels, f.surface);
      for (std::string& l :
           fidelity_findings(f, surfaces[static_cast<std::size_t>(f.surface)], label, input_diagonal, limit))
        lines.push_back(std::move(l));
    }
  }
  for (std::size_t i = 0; i < surfaces.size(); ++i)
    if (!measured[i]) {
      lines.insert(lines.begin(), label_of(labels, static_cast<int>(i)) + ": no spline face stands for it");
      c.value = std::numeric_limits<double>::infinity();
    }
  c.passed = c.value <= limit;
  c.summary = std::isfinite(c.value)
                  ? text("largest distance between an input surface and the model %.3f %% of the diagonal (limit %.3g %%)",
                         100.0 * c.value, 100.0 * limit)
                  : "an input surface has no spline face";
  add_findings(c, lines);
  return c;
}

Criterion volume_criterion(const TopologyReport& t, const std::vector<std::string>& labels, int materials,
                           double limit) {
  if (t.regions.empty()) return not_checked("volume", "no input surfaces");
  Criterion c;
  c.name = "volume";
  c.limit = limit;
  std::vector<std::string> lines;
  for (const RegionVolume& rv : t.regions) {
    // A region without a material (a void) must stay empty.
    const bool void_region = rv.region >= materials;
    const double d = void_region ? (rv.input_volume > 0.0 ? rv.spline_volume / rv.input_volume : 0.0)
                                 : rv.relative_difference;
    if (std::abs(d) > std::abs(c.value)) c.value = d;
    if (std::abs(d) <= limit) continue;
    const std::string where = text("region %d (inside %s)", rv.region, label_of(labels, rv.region).c_str());
    if (void_region)
      lines.push_back(text("%s has no material, but %d patches fill %.3f %% of it", where.c_str(), rv.patches, 100.0 * d));
    else
      lines.push_back(text("%s: %d patches, volume %.6g against the input's %.6g (%+.3f %%)", where.c_str(),
                           rv.patches, rv.spline_volume, rv.input_volume, 100.0 * d));
  }
  std::string outside;
  for (std::size_t p = 0; p < t.patch_region.size(); ++p)
    if (t.patch_region[p] < 0) outside += " " + std::to_string(p);
  if (!outside.empty()) lines.push_back("patches" + outside + " lie outside every input surface");
  c.passed = std::abs(c.value) <= limit;
  c.summary = text("largest material volume difference %+.3f %% (limit %.3g %%)", 100.0 * c.value, 100.0 * limit);
  add_findings(c, lines);
  return c;
}

std::string failed_criterion_names(const std::vector<Criterion>& criteria) {
  std::string names;
  for (const Criterion& c : criteria)
    if (!c.passed) names += (names.empty() ? "" : ", ") + c.name;
  return names;
}

}  // namespace igaprep::iga_check
