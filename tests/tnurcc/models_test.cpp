// T-NURCC surfaces of the built-in models, fitted to their input meshes:
// the limit surface follows the input within 0.2 % of its diagonal both
// ways, and is smooth where the C0 multipatch kinks.
#include <gtest/gtest.h>

#include "igaprep/mesh/read_surface.h"
#include "igaprep/pipeline/tnurcc.h"
#include "pipeline/pipeline_runs.h"

namespace {

using namespace igaprep;

struct Built {
  std::vector<pipeline::TnurccSurface> surfaces;
};

Built tnurcc_of(const std::string& model, const std::vector<std::string>& files) {
  pipeline_test::Recorder rec;
  pipeline::RunOptions ro;
  ro.write_outputs = false;
  const pipeline::RunResult r =
      pipeline::run(pipeline_test::model_case(model, R"({"validation": {"enabled": false}})", "tnurcc_" + model), rec, ro);
  EXPECT_TRUE(r.report.passed) << r.report.verdict;
  std::vector<mesh::TriMesh> meshes;
  for (const auto& f : files) meshes.push_back(mesh::read_surface(pipeline_test::models_dir() + "/" + model + "/" + f));
  return {pipeline::tnurcc_surfaces(r.model, meshes, {}, rec)};
}

void expect_follows_and_smooth(const pipeline::TnurccSurface& s) {
  SCOPED_TRACE(s.name);
  ASSERT_TRUE(s.limit_fidelity && s.model_fidelity);
  EXPECT_LT(s.limit_fidelity->limit_to_mesh.max_relative, 0.002);
  EXPECT_LT(s.limit_fidelity->mesh_to_limit.max_relative, 0.002);
  EXPECT_GT(s.fit_rms.size(), 1u);
  EXPECT_LT(s.fit_rms.back(), s.fit_rms.front());
  EXPECT_EQ(s.crease_edges, 0);  // the inputs are smooth
  EXPECT_GT(s.extraordinary_vertices, 0);
  EXPECT_TRUE(spline::opposite_edge_violations(s.cage).empty());
  // The C0 model kinks at its patch edges; the limit surface does not.
  EXPECT_GT(s.model_jumps.max, 1.0);
  EXPECT_LT(s.limit_jumps.max, 1e-6);
  EXPECT_LT(s.limit_jumps.max_gap, 1e-9 * s.diagonal);
  EXPECT_LT(s.model_jumps.max_gap, 1e-9 * s.diagonal);
}

TEST(TnurccModels, Ring2BothSurfacesFollowTheirInputs) {
  const Built b = tnurcc_of("ring2", {"outer.off", "inner.off"});
  ASSERT_EQ(b.surfaces.size(), 2u);
  for (const auto& s : b.surfaces) expect_follows_and_smooth(s);
  // The limit surface follows the outer input closer than the C0 model does.
  EXPECT_LT(b.surfaces[0].limit_fidelity->limit_to_mesh.max, b.surfaces[0].model_fidelity->spline_to_mesh.max);
}

TEST(TnurccModels, Torus3FollowsItsInput) {
  const Built b = tnurcc_of("torus3", {"outer.off"});
  ASSERT_EQ(b.surfaces.size(), 1u);
  expect_follows_and_smooth(b.surfaces[0]);
}

}  // namespace
