// A run says where the method lost part of the input, at the stage that lost
// it: the hand (../shared/models, genus 0), cut by the plane through its palm
// that the automatic cut took until 2026-12-07 (it now cuts between the
// hand's two sides and loses no finger). The plane misses the thumb and the
// little finger; the three fingers on M0trim are arms of the domain
// (sheet_lobes.h). The param stage names the material's missing volume and
// the uncovered parts of T1.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>

#include "igaprep/mesh/write_surface.h"
#include "igaprep/pipeline/case.h"
#include "igaprep/pipeline/midsurface.h"
#include "igaprep/pipeline/surfaces.h"
#include "igaprep/pipeline/volume.h"
#include "pipeline_runs.h"

namespace {

// A run of a shared model (one material, every key at its default, no
// validation) up to the param stage; rec holds the stages' summaries.
igaprep::param::VolumeParam run_to_param(const std::string& surface, const std::string& name,
                                         pipeline_test::Recorder& rec, const std::string& extra_keys = "") {
  const igaprep::pipeline::Case c = igaprep::pipeline::parse_case(
      R"({"surfaces": [")" + surface + R"("], "validation": {"enabled": false})" + extra_keys + "}",
      pipeline_test::scratch_dir(name), name + "/case.json");
  const igaprep::pipeline::Surfaces s = igaprep::pipeline::load_surfaces(c);
  const auto mid = igaprep::pipeline::midsurface_stage(c, s, rec);
  const auto base = igaprep::pipeline::base_stage(c, s, mid, rec);
  const auto d = igaprep::pipeline::decompose_stage(c, s, base, rec);
  return igaprep::pipeline::param_stage(c, s, d, rec);
}

TEST(LostParts, TheParamStageNamesTheHandsFingers) {
  const std::string obj = std::string(IGAPREP_SHARED_MODELS_DIR) + "/hand.obj";
  if (!std::filesystem::exists(obj)) GTEST_SKIP() << "shared model " << obj << " is absent";
  pipeline_test::Recorder rec;
  // The layout as cut (cover_rounds 0): the fingers this plane misses are
  // lost whatever the rectangles, and halving them costs a minute.
  run_to_param(obj, "hand", rec,
               R"(, "midsurface": {"cut": {"plane": {"point": [-0.03004, 0.4103, 0.0666],)"
               R"( "normal": [0.07653, -0.04501, 0.9961]}}}, "decomposition": {"cover_rounds": 0})");
  ASSERT_EQ(rec.stages.back().stage, "param");
  const std::vector<std::string>& lines = rec.stages.back().details;

  // 2026-12-02, one rectangle: -19.5 % of the volume; 8 uncovered regions,
  // the largest 775 vertices up to 28.4 % of the diagonal away (a finger's
  // tip). 2026-12-05, with arms: -4.2 %; 4 regions, the farthest 10.4 %.
  const std::regex volume(R"(the blocks of material 0 differ from the input's volume there by (-[0-9.]+) %)");
  const std::regex region(
      R"(blocks leave 'hand' uncovered: ([0-9]+) vertices around \(.*\), the farthest ([0-9.]+) % of the diagonal)");
  std::smatch m;
  int regions = 0;
  double lost_volume = 0.0, farthest = 0.0;
  for (const std::string& line : lines) {
    if (std::regex_search(line, m, volume)) lost_volume = std::stod(m[1]);
    if (std::regex_search(line, m, region)) {
      ++regions;
      if (regions == 1) farthest = std::stod(m[2]);
      EXPECT_GT(std::stoi(m[1]), 0) << line;
    }
  }
  EXPECT_LT(lost_volume, -2.0);
  EXPECT_GT(lost_volume, -7.0);
  EXPECT_EQ(regions, 3) << "the three farthest regions, then how many more";
  EXPECT_GT(farthest, 5.0);
  EXPECT_LT(farthest, 15.0);
  EXPECT_NE(lines.back().find("more uncovered regions of 'hand'"), std::string::npos) << lines.back();
}

// torus_genus3 (../shared/models): the lid shells' sides on T1 span up to a
// fifth of the plate; between their samples T1 bulges out by more than the
// check's fidelity limit, so no fit of those samples can pass. With
// "spread_deviation": "auto" (the default) the param stage says so and
// spreads the faces where T1 bulges between samples.
TEST(LostParts, TheParamStageSpreadsTheFacesWhereT1BulgesBetweenSamples) {
  const std::string off = std::string(IGAPREP_SHARED_MODELS_DIR) + "/torus_genus3.off";
  if (!std::filesystem::exists(off)) GTEST_SKIP() << "shared model " << off << " is absent";
  pipeline_test::Recorder rec;
  const igaprep::param::VolumeParam vp = run_to_param(off, "torus_genus3", rec);
  ASSERT_EQ(rec.stages.back().stage, "param");
  // 2026-12-06: 0.845 % before, 0.531 % after (the samples' grids cut into
  // triangles; the fit follows T1 between them more closely: 1.232 ->
  // 0.695 % with the Jacobian repair off).
  const std::regex spread(
      R"(the samples missed T1 by ([0-9.]+) % of the diagonal \(fidelity limit 0.500 %\): spread where T1 bulges between )"
      R"(samples by more than 0.200 % \('decomposition.spread_deviation' 0.002\): ([0-9.]+) %, kept)");
  std::smatch m;
  bool found = false;
  for (const std::string& line : rec.stages.back().details)
    if (std::regex_search(line, m, spread)) {
      found = true;
      EXPECT_GT(std::stod(m[1]), 0.7) << line;
      EXPECT_LT(std::stod(m[1]), 1.0) << line;
      EXPECT_LT(std::stod(m[2]), 0.6) << line;
    }
  EXPECT_TRUE(found) << "the param stage's summary names the second spreading";
  // Still over the limit: the rectangles under the two shell faces nearest
  // the missed vertices are halved (2026-12-07: 18 -> 26 rectangles, the
  // samples 0.531 -> 0.378 %; decomposition.cover_rounds).
  const std::regex halved(
      R"(the samples missed T1 by ([0-9.]+) % of the diagonal next to ([0-9]+) shell faces: their rectangles halved )"
      R"(\('decomposition.cover_rounds' 2\), 18 -> ([0-9]+) rectangles, ([0-9.]+) %, [0-9]+ folded sample cells, kept)");
  found = false;
  for (const std::string& line : rec.stages.back().details)
    if (std::regex_search(line, m, halved)) {
      found = true;
      EXPECT_GT(std::stoi(m[3]), 18) << line;
      EXPECT_LT(std::stod(m[4]), 0.5) << line;  // within the check's fidelity limit
    }
  EXPECT_TRUE(found) << "the param stage's summary names the halved rectangles";
  EXPECT_EQ(vp.rectangles, 26);
  EXPECT_GT(vp.spread_faces, 32);  // 32 without it (the fans' uneven rows only)
  // The spread faces' sides on T1, relaxed on T1 where they fold
  // (surface_grid_relax.h): 48 folded cells -> 12 (2026-12-06).
  EXPECT_GT(vp.t1_folded_before, 30);
  EXPECT_LE(3 * vp.t1_folded_after, vp.t1_folded_before);
}

// A plate 1 x 1 x `thickness` with a flat rim, its faces cut into squares of
// side about h (two triangles each), outward.
igaprep::mesh::TriMesh flat_plate(double thickness, double h) {
  std::vector<Eigen::Vector3d> V;
  std::vector<Eigen::Vector3i> F;
  const Eigen::Vector3d size(1.0, 1.0, thickness);
  // Each face: origin, two edge axes (their cross product points out).
  const int faces[6][3] = {{-1, 1, 0}, {3, 0, 1}, {-2, 0, 2}, {2, 2, 0}, {-1, 2, 1}, {1, 1, 2}};
  for (const auto& face : faces) {
    const int normal = std::abs(face[0]) - 1, a = face[1], b = face[2];
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();
    if (face[0] > 0) origin(normal) = size(normal);
    const int na = std::max(1, static_cast<int>(std::lround(size(a) / h)));
    const int nb = std::max(1, static_cast<int>(std::lround(size(b) / h)));
    const int first = static_cast<int>(V.size());
    for (int j = 0; j <= nb; ++j)
      for (int i = 0; i <= na; ++i) {
        Eigen::Vector3d p = origin;
        p(a) = size(a) * i / na;
        p(b) = size(b) * j / nb;
        V.push_back(p);
      }
    auto id = [&](int i, int j) { return first + i + (na + 1) * j; };
    for (int j = 0; j < nb; ++j)
      for (int i = 0; i < na; ++i) {
        F.emplace_back(id(i, j), id(i + 1, j), id(i + 1, j + 1));
        F.emplace_back(id(i, j), id(i + 1, j + 1), id(i, j + 1));
      }
  }
  // The faces share their edges' points: merge them.
  igaprep::mesh::TriMesh m;
  std::vector<int> index(V.size());
  std::vector<Eigen::Vector3d> kept;
  for (std::size_t v = 0; v < V.size(); ++v) {
    std::size_t k = 0;
    while (k < kept.size() && (kept[k] - V[v]).norm() > 1e-12) ++k;
    if (k == kept.size()) kept.push_back(V[v]);
    index[v] = static_cast<int>(k);
  }
  m.V.resize(static_cast<Eigen::Index>(kept.size()), 3);
  for (std::size_t k = 0; k < kept.size(); ++k) m.V.row(static_cast<Eigen::Index>(k)) = kept[k].transpose();
  m.F.resize(static_cast<Eigen::Index>(F.size()), 3);
  for (std::size_t f = 0; f < F.size(); ++f)
    for (int k = 0; k < 3; ++k) m.F(static_cast<Eigen::Index>(f), k) = index[static_cast<std::size_t>(F[f](k))];
  return m;
}

// A thin plate with a flat rim: M inset by its default share of the plate's
// width (0.15) leaves a gap 7.5 times as long as the plate is thick, across
// which the crest's streamlines reach almost none of the rim (the samples
// missed T1 by 11.4 % of the diagonal, 2026-12-06). The base stage caps the
// inset at 2 half-thicknesses (rim_reach.h) and says so.
TEST(LostParts, AThinPlatesInsetIsCappedSoItsRimIsCovered) {
  const std::string off = pipeline_test::scratch_dir("thin_plate_surface") + "/plate.off";
  igaprep::mesh::write_surface(off, flat_plate(0.02, 0.05));
  pipeline_test::Recorder rec;
  run_to_param(off, "thin_plate", rec);
  const std::string* base = nullptr;
  for (const auto& stage : rec.stages)
    if (stage.stage == "base" && !stage.details.empty()) base = &stage.details.front();
  ASSERT_NE(base, nullptr) << "the base stage names the capped inset";
  EXPECT_NE(base->find("inset 0.04, not 0.3 ('decomposition.inset'): the solid is thin at M0trim's rim"), std::string::npos)
      << *base;
  EXPECT_NE(base->find("half-thickness 0.01 there"), std::string::npos) << *base;
  // The samples miss T1 by 1.04 % (the plate's sharp edges inside the crest
  // blocks' sides), not 11.4 %; within the limit the line is not written.
  const std::regex missed(R"(the samples missed T1 by ([0-9.]+) % of the diagonal)");
  std::smatch m;
  for (const std::string& line : rec.stages.back().details)
    if (std::regex_search(line, m, missed)) EXPECT_LT(std::stod(m[1]), 1.5) << line;
  for (const std::string& line : rec.stages.back().details)
    EXPECT_EQ(line.find("blocks leave 'plate' uncovered"), std::string::npos) << line;
}

}  // namespace
