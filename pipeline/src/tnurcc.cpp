#include "igaprep/pipeline/tnurcc.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

#include "igaprep/core/atomic_file.h"
#include "igaprep/core/error.h"
#include "igaprep/core/text.h"
#include "igaprep/export/tnurcc_files.h"
#include "igaprep/mesh/sharp_edges.h"
#include "igaprep/spline/label_sides.h"
#include "igaprep/spline/tnurcc_fit.h"

namespace igaprep::pipeline {
namespace {

std::vector<int> labels_to_build(const spline::MultiPatch& mp, const TnurccSettings& s) {
  return s.labels.empty() ? spline::labels_with_sides(mp) : s.labels;
}

double segment_distance(const Eigen::Vector3d& p, const std::array<Eigen::Vector3d, 2>& s) {
  const Eigen::Vector3d d = s[1] - s[0];
  const double t = d.squaredNorm() > 0 ? std::clamp((p - s[0]).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
  return (p - (s[0] + t * d)).norm();
}

// A crease of the model's cage stays a crease only where the input mesh is
// sharp too (within two of its edge lengths): the fitted model also turns
// at its layout's corners, where the input is smooth.
void keep_creases_of_the_input(spline::Cage& cage, const mesh::TriMesh& mesh, double angle) {
  const auto sharp = mesh::sharp_edges(mesh, angle);
  for (auto& e : cage.edges) {
    if (e.sharpness <= 0.0) continue;
    const Eigen::Vector3d a = cage.points.row(e.vertices[0]), b = cage.points.row(e.vertices[1]);
    const Eigen::Vector3d mid = 0.5 * (a + b);
    const double radius = 2.0 * (b - a).norm();
    bool near = false;
    for (const auto& s : sharp)
      if (segment_distance(mid, s) <= radius) {
        near = true;
        break;
      }
    if (!near) e.sharpness = 0.0;
  }
}

void fit_to_mesh(TnurccSurface& s, const spline::MultiPatch& mp, const mesh::TriMesh& mesh,
                 const TnurccSettings& settings) {
  iga_check::LimitFidelityOptions fo;
  fo.samples_per_face = settings.samples_per_face;
  keep_creases_of_the_input(s.cage, mesh, settings.crease_angle);
  if (settings.fit_iterations > 0) {
    spline::CageFitOptions options;
    options.iterations = settings.fit_iterations;
    options.smoothing = settings.smoothing;
    const spline::CageFitResult r = spline::fit_cage(
        s.cage, [&](const spline::Cage& c) { return iga_check::limit_mesh_pairs(c, mesh, fo); }, options);
    s.cage = r.cage;
    s.fit_rms = r.rms;
  }
  s.diagonal = iga_check::mesh_diagonal(mesh);
  s.limit_fidelity = iga_check::limit_fidelity(s.cage, mesh, s.diagonal, fo);
  std::vector<mesh::TriMesh> only(s.label + 1);
  only[s.label] = mesh;
  iga_check::FidelityOptions alone;
  alone.only_surface = s.label;
  for (auto& f : iga_check::fidelity(mp, only, s.diagonal, alone))
    if (f.surface == s.label) s.model_fidelity = std::move(f);
}

// Percentiles 1, 50 and 99 of the mean curvature over samples_per_face^2
// points per face (points where it is not defined, such as some
// extraordinary points, left out).
std::array<double, 3> curvature_percentiles(const spline::Cage& cage, int samples_per_face) {
  spline::LimitOptions o;
  o.second_derivatives = true;
  const auto at = spline::face_grid(cage, samples_per_face, false);
  const Eigen::VectorXd H = spline::limit_values(spline::limit_stencils(cage, at, o), cage.points).mean_curvature;
  std::vector<double> h;
  for (double x : H)
    if (std::isfinite(x)) h.push_back(x);
  if (h.empty()) return {{0.0, 0.0, 0.0}};
  std::sort(h.begin(), h.end());
  auto at_fraction = [&](double q) { return h[static_cast<size_t>(q * double(h.size() - 1))]; };
  return {{at_fraction(0.01), at_fraction(0.5), at_fraction(0.99)}};
}

StageSummary summary(const TnurccSurface& s, double seconds) {
  StageSummary out;
  out.stage = "tnurcc";
  out.seconds = seconds;
  out.headline = text("'%s': cage of %ld points, %zu faces, %d extraordinary vertices, %d crease edges",
                      s.name.c_str(), static_cast<long>(s.cage.points.rows()), s.cage.faces.size(),
                      s.extraordinary_vertices, s.crease_edges);
  if (!s.fit_rms.empty())
    out.details.push_back(text("fit: %zu iterations, rms distance %.3g -> %.3g", s.fit_rms.size() - 1,
                               s.fit_rms.front(), s.fit_rms.back()));
  if (s.limit_fidelity && s.model_fidelity)
    out.details.push_back(text("fidelity (max both ways, %% of the diagonal): limit surface %.3f %% / %.3f %%, "
                               "C0 model %.3f %% / %.3f %%",
                               100 * s.limit_fidelity->limit_to_mesh.max_relative,
                               100 * s.limit_fidelity->mesh_to_limit.max_relative,
                               100 * s.model_fidelity->spline_to_mesh.max_relative,
                               100 * s.model_fidelity->mesh_to_spline.max_relative));
  out.details.push_back(text("mean curvature of the limit surface (1st / 50th / 99th percentile): %.3g / %.3g / %.3g",
                             s.mean_curvature[0], s.mean_curvature[1], s.mean_curvature[2]));
  out.details.push_back(text("normal jump across patch edges (max, degrees): C0 model %.3g, limit surface %.3g "
                             "(%.3g over every cage edge)",
                             s.model_jumps.max, s.limit_jumps_patch_edges.max, s.limit_jumps.max));
  return out;
}

}  // namespace

std::vector<TnurccSurface> tnurcc_surfaces(const spline::MultiPatch& mp, const std::vector<mesh::TriMesh>& meshes,
                                           const TnurccSettings& settings, Observer& observer) {
  spline::CageOptions cage_options;
  cage_options.crease_angle = settings.crease_angle;
  cage_options.equal_intervals = settings.equal_intervals;
  std::vector<TnurccSurface> out;
  for (int label : labels_to_build(mp, settings)) {
    const auto start = std::chrono::steady_clock::now();
    TnurccSurface s;
    s.label = label;
    s.cage = spline::surface_cage(mp, label, cage_options);
    s.name = mp.labels[label];
    if (!spline::uniform_intervals(s.cage))
      throw bad_input("T-NURCC '" + s.name + "': the model's knot vectors are not uniform (a reduced model, for one), "
                      "and the limit surface of unequal knot intervals is not evaluated yet; with equal_intervals its cage is "
                      "taken "
                      "as a Catmull-Clark cage (docs/tnurcc.md)");
    for (int v : spline::vertex_valences(s.cage)) s.extraordinary_vertices += v != 4;
    if (label < static_cast<int>(meshes.size()) && meshes[label].F.rows() > 0)
      fit_to_mesh(s, mp, meshes[label], settings);
    s.model_jumps = spline::model_normal_jumps(mp, s.cage);  // the model's sides; the cage gives edges and creases
    for (const auto& e : s.cage.edges) s.crease_edges += e.sharpness > 0.0;
    s.limit_jumps_patch_edges = spline::limit_normal_jumps(s.cage, spline::JumpEdges::smooth_patch_edges);
    s.limit_jumps = spline::limit_normal_jumps(s.cage, spline::JumpEdges::smooth);
    s.mean_curvature = curvature_percentiles(s.cage, settings.samples_per_face);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    observer.stage_finished(summary(s, seconds));
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<std::string> write_tnurcc(const std::vector<TnurccSurface>& surfaces, const std::string& dir,
                                      const TnurccSettings& settings) {
  create_output_folder(dir);
  std::vector<std::string> written;
  for (const auto& s : surfaces) {
    const std::string stem = (std::filesystem::path(dir) / (s.name.empty() ? text("label%d", s.label) : s.name)).string();
    write_file_atomically(stem + "_cage.obj", [&](std::ostream& o) { exporter::write_cage_obj(s.cage, o); });
    write_file_atomically(stem + "_intervals.json", [&](std::ostream& o) { exporter::write_cage_intervals(s.cage, o); });
    write_file_atomically(
        stem + "_limit.vtu", [&](std::ostream& o) { exporter::write_limit_vtu(s.cage, settings.vtu_per_face, o); },
        true);
    for (const char* end : {"_cage.obj", "_intervals.json", "_limit.vtu"}) written.push_back(stem + end);
  }
  return written;
}

}  // namespace igaprep::pipeline
