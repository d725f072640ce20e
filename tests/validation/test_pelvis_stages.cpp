// The pelvis validation case (models/pelvis, the surface from
// ../shared/models) through the stages before the fit, asserting what they
// make: the cut from the case's waypoint loops (the outline, the obturator
// foramen and the small second hole), M0trim with the two holes, and the
// decomposition into blocks. The fitted model does not pass its check yet
// (docs/validation.md); this keeps the stages before it from going back.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "igaprep/mesh/tet_volume.h"
#include "igaprep/param/blocks_tet_mesh.h"
#include "igaprep/pipeline/case.h"
#include "igaprep/pipeline/midsurface.h"
#include "igaprep/pipeline/surfaces.h"
#include "igaprep/pipeline/volume.h"
#include "pipeline/pipeline_runs.h"

namespace {

using igaprep::pipeline::Case;

TEST(PelvisStages, WaypointCutAndBlocks) {
  const std::string stl = std::string(IGAPREP_SHARED_MODELS_DIR) + "/pelvis_hip.stl";
  if (!std::filesystem::exists(stl)) GTEST_SKIP() << "shared model " << stl << " is absent";
  Case c = igaprep::pipeline::read_case(pipeline_test::models_dir() + "/pelvis/case.json");
  igaprep::pipeline::Observer quiet;
  const igaprep::pipeline::Surfaces s = igaprep::pipeline::load_surfaces(c);
  ASSERT_EQ(s.inputs.size(), 2u);  // the bone and its 0.8 mm inward offset
  EXPECT_EQ(s.remeshed_to, std::vector<double>(2, 0.0));  // no slivers: kept as given

  const auto mid = igaprep::pipeline::midsurface_stage(c, s, quiet);
  EXPECT_EQ(mid.cut.source.rfind("waypoint loops", 0), 0u) << mid.cut.source;
  EXPECT_EQ(mid.cut.genus, 2);
  ASSERT_EQ(mid.cut.loops.size(), 3u);
  // M0trim: one sheet bounded by the outline and the two holes.
  EXPECT_EQ(mid.m0trim.boundary_loops.size(), 3u);
  EXPECT_EQ(mid.polycube.domain.holes.size(), 2u);
  EXPECT_GT(mid.polycube.min_jacobian, 0.0);

  const auto base = igaprep::pipeline::base_stage(c, s, mid, quiet);
  const auto d = igaprep::pipeline::decompose_stage(c, s, base, quiet);
  EXPECT_EQ(d.layout.rectangles.size(), 31u);
  const auto v = igaprep::pipeline::param_stage(c, s, d, quiet);
  EXPECT_EQ(v.blocks.size(), 366u);
  // The blocks' signed volume (folded cells counting negative) against the
  // tet mesh's 175,711 mm^3: 166,730 (-5.1 %) with 31,215 folded sample cells
  // on 2026-12-02, mostly in the 0.8 mm cortical shell (docs/validation.md).
  // Bounds a few per cent beyond that, so that the stages do not go back.
  const auto blocks = igaprep::param::blocks_tet_mesh(v.blocks, 1e-9 * 250.0);
  const double volume = igaprep::mesh::tet_volumes(blocks.tets, 1).total;
  const double tets = igaprep::mesh::tet_volumes(mid.tets, 1).total;
  EXPECT_NEAR(tets, 175711.0, 10.0);
  EXPECT_GT(volume, 0.92 * tets);
  EXPECT_LT(volume, tets);
  EXPECT_LT(v.folded_cells, 33000);
}

}  // namespace
