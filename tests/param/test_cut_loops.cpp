// Cut loops on T1 (seed paper, section 4.1): automatic, plane and explicit
// sources, and the refusals of bad cuts.
#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <sstream>
#include <set>

#include "igaprep/core/error.h"
#include "igaprep/models/builtin_models.h"
#include "igaprep/param/cut_loops.h"
#include "igaprep/param/sheet_topology.h"

using namespace igaprep;
using namespace igaprep::param;

namespace {

// Every loop is a closed path along edges of the cut surface, loops share no vertex.
void expect_valid_loops(const CutLoops& cut) {
  std::set<std::pair<int, int>> edges;
  for (int f = 0; f < cut.surface.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = cut.surface.F(f, k), b = cut.surface.F(f, (k + 1) % 3);
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  std::set<int> seen;
  for (const auto& loop : cut.loops) {
    ASSERT_GE(loop.size(), 3u);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const int a = loop[i], b = loop[(i + 1) % loop.size()];
      EXPECT_TRUE(edges.count({std::min(a, b), std::max(a, b)})) << a << "-" << b;
      EXPECT_TRUE(seen.insert(a).second) << "vertex " << a << " twice";
      EXPECT_EQ(cut.vertex_side(a), 0);
    }
  }
  // R+ and R- are each one connected sheet whose boundary loops are the cut loops.
  for (int s : {1, -1}) {
    std::vector<int> rows;
    for (int f = 0; f < cut.face_side.size(); ++f)
      if (cut.face_side(f) == s) rows.push_back(f);
    Eigen::MatrixXi F(static_cast<Eigen::Index>(rows.size()), 3);
    for (std::size_t i = 0; i < rows.size(); ++i) F.row(static_cast<Eigen::Index>(i)) = cut.surface.F.row(rows[i]);
    const SheetTopology t = analyze_sheet(F, cut.surface.V.rows());
    EXPECT_EQ(describe_sheet_problem(t, cut.genus + 1, s > 0 ? "R+" : "R-"), "");
  }
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    return e.what();
  }
  return "";
}

}  // namespace

TEST(CutLoops, AutomaticGivesGPlusOneLoopsOnBuiltinModels) {
  for (const auto& [name, genus] : std::vector<std::pair<std::string, int>>{{"sphere2", 0}, {"ring2", 1}, {"torus3", 3}}) {
    SCOPED_TRACE(name);
    const auto model = models::make_builtin_model(name);
    const CutLoops cut = cut_automatic(model.surfaces[0]);
    EXPECT_EQ(cut.genus, genus);
    EXPECT_EQ(static_cast<int>(cut.loops.size()), genus + 1);
    // original vertices keep their positions and indices
    ASSERT_GE(cut.surface.V.rows(), model.surfaces[0].V.rows());
    EXPECT_EQ(cut.surface.V.topRows(model.surfaces[0].V.rows()), model.surfaces[0].V);
    expect_valid_loops(cut);
  }
}

TEST(CutLoops, PlaneLoopsLieOnThePlane) {
  const auto model = models::make_builtin_model("sphere2");
  CutPlane p;
  p.point = Eigen::Vector3d(0.1, 0.0, 0.05);
  p.normal = Eigen::Vector3d(0.2, 0.1, 1.0);
  const CutLoops cut = cut_by_plane(model.surfaces[0], p, "sphere2 outer", 0.0);
  ASSERT_EQ(cut.loops.size(), 1u);
  expect_valid_loops(cut);
  const Eigen::Vector3d n = p.normal.normalized();
  for (int v : cut.loops[0]) EXPECT_NEAR(n.dot(cut.surface.V.row(v).transpose() - p.point), 0.0, 1e-12);
  // R+ is on the normal's side.
  for (int f = 0; f < cut.surface.F.rows(); ++f) {
    const Eigen::Vector3d c = (cut.surface.V.row(cut.surface.F(f, 0)) + cut.surface.V.row(cut.surface.F(f, 1)) +
                               cut.surface.V.row(cut.surface.F(f, 2))) / 3.0;
    EXPECT_GT(cut.face_side(f) * n.dot(c - p.point), -1e-12);
  }
}

// A plate thinner than the snapping tolerance (5 % of its mean edge, 0.04
// here, against 0.001 from the midplane to either face): every vertex would
// count as on the plane. The tolerance shrinks until the plane parts them,
// and the loop runs round the rim at mid-height.
TEST(CutLoops, APlateThinnerThanTheSnappingToleranceIsCutAtItsMiddle) {
  mesh::TriMesh plate;
  plate.V.resize(8, 3);
  for (int i = 0; i < 8; ++i) plate.V.row(i) << (i & 1), (i >> 1 & 1), (i & 4 ? 0.002 : 0.0);
  plate.F.resize(12, 3);
  plate.F << 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5;
  CutPlane p;
  p.point = Eigen::Vector3d(0.5, 0.5, 0.001);
  p.normal = Eigen::Vector3d(0.0, 0.0, 1.0);
  const CutLoops cut = cut_by_plane(plate, p, "plate", 0.05);
  ASSERT_EQ(cut.loops.size(), 1u);
  expect_valid_loops(cut);
  EXPECT_GE(cut.loops[0].size(), 4u);
  for (int v : cut.loops[0]) EXPECT_NEAR(cut.surface.V(v, 2), 0.001, 1e-15);
  // A plane beside the plate is still refused.
  p.point.z() = 0.003;
  EXPECT_THROW(cut_by_plane(plate, p, "plate", 0.05), Error);
}

TEST(CutLoops, ExplicitLoopsAreKept) {
  const auto model = models::make_builtin_model("sphere2");
  const mesh::TriMesh& T1 = model.surfaces[0];
  // The boundary of the faces above z = 0.1 is a closed edge path.
  Eigen::VectorXi side(T1.F.rows());
  for (int f = 0; f < T1.F.rows(); ++f)
    side(f) = (T1.V(T1.F(f, 0), 2) + T1.V(T1.F(f, 1), 2) + T1.V(T1.F(f, 2), 2)) / 3.0 > 0.1 ? 1 : -1;
  const CutLoops ref = validate_cut(T1, side, "sphere2", "test");
  ASSERT_EQ(ref.loops.size(), 1u);
  const CutLoops cut = cut_by_loops(T1, ref.loops, "sphere2");
  EXPECT_EQ(cut.loops.size(), 1u);
  EXPECT_EQ(cut.face_side, ref.face_side);
  std::vector<int> reversed(ref.loops[0].rbegin(), ref.loops[0].rend());
  const CutLoops flipped = cut_by_loops(T1, {reversed}, "sphere2");
  EXPECT_EQ(flipped.face_side, -ref.face_side);
}

TEST(CutLoops, WrongCutsAreRefusedWithTheirReason) {
  const auto ring = models::make_builtin_model("ring2");
  // The plane x = 1 cuts the tube once: one loop where genus 1 needs two.
  CutPlane p;
  p.point = Eigen::Vector3d(1.0, 0.0, 0.0);
  p.normal = Eigen::Vector3d::UnitX();
  std::string msg = error_of([&] { cut_by_plane(ring.surfaces[0], p, "ring2 outer"); });
  EXPECT_NE(msg.find("gives 1 loop"), std::string::npos) << msg;
  EXPECT_NE(msg.find("needs 2 (g + 1) loops"), std::string::npos) << msg;
  // A plane that misses the surface.
  p.point = Eigen::Vector3d(0.0, 0.0, 5.0);
  p.normal = Eigen::Vector3d::UnitZ();
  msg = error_of([&] { cut_by_plane(ring.surfaces[0], p, "ring2 outer"); });
  EXPECT_NE(msg.find("does not cut the surface"), std::string::npos) << msg;

  // Two small loops around two vertices of the torus: right count, three regions.
  const mesh::TriMesh& T1 = ring.surfaces[0];
  auto ring_around = [&](int v) {
    // the one-ring of v in order (closed torus grid)
    std::map<int, int> next;
    for (int f = 0; f < T1.F.rows(); ++f)
      for (int k = 0; k < 3; ++k)
        if (T1.F(f, k) == v) next[T1.F(f, (k + 1) % 3)] = T1.F(f, (k + 2) % 3);
    std::vector<int> loop{next.begin()->first};
    while (static_cast<int>(loop.size()) < static_cast<int>(next.size())) loop.push_back(next[loop.back()]);
    return loop;
  };
  msg = error_of([&] { cut_by_loops(T1, {ring_around(0), ring_around(1000)}, "ring2 outer"); });
  EXPECT_NE(msg.find("into 3 regions"), std::string::npos) << msg;
  // A loop with a repeated vertex, and one that jumps between vertices.
  std::vector<int> bad = ring_around(0);
  const std::vector<int> once = bad;
  bad.insert(bad.end(), once.begin(), once.end());  // around twice
  msg = error_of([&] { cut_by_loops(T1, {bad}, "ring2 outer"); });
  EXPECT_NE(msg.find("cut loop 0 is not simple: it passes vertex " + std::to_string(once[0]) + " ("),
            std::string::npos) << msg;
  // Two loops through one vertex (the same loop twice): they touch, and where.
  msg = error_of([&] { cut_by_loops(T1, {once, once}, "ring2 outer"); });
  std::ostringstream where;
  where << "vertex " << once[0] << " (" << T1.V.row(once[0]) << ")";
  EXPECT_NE(msg.find("cut loops 0 and 1 touch at " + where.str()), std::string::npos) << msg;
  msg = error_of([&] { cut_by_loops(T1, {{0, 1000, 2000}}, "ring2 outer"); });
  EXPECT_NE(msg.find("not joined by an edge"), std::string::npos) << msg;
  // One loop on the genus-1 surface: too few.
  msg = error_of([&] { cut_by_loops(T1, {ring_around(0)}, "ring2 outer"); });
  EXPECT_NE(msg.find("needs 2 (g + 1) loops"), std::string::npos) << msg;
}

// The plane family on the genus-3 frame: every valid cut has g + 1 = 4 valid
// loops, shortest total length first; the refusals account for every other
// plane, grouped by kind ("N x reason").
TEST(CutLoops, PlaneFamilyGivesValidCutsShortestFirst) {
  const auto model = models::make_builtin_model("torus3");
  const PlaneFamily family = cut_plane_family(model.surfaces[0], 12, 5);
  EXPECT_EQ(family.tried, 60);
  ASSERT_GT(family.valid.size(), 0u);
  int refused = 0;
  for (const auto& line : family.refusals) {
    refused += std::stoi(line.substr(0, line.find(" x ")));
    EXPECT_EQ(line.find_first_of("0123456789", line.find(" x ")), std::string::npos) << "numbers taken out: " << line;
  }
  EXPECT_EQ(refused + static_cast<int>(family.valid.size()), family.tried);
  double previous = 0.0;
  for (const auto& cut : family.valid) {
    EXPECT_EQ(cut.loops.size(), 4u);
    EXPECT_GE(loops_length(cut), previous);
    previous = loops_length(cut);
    expect_valid_loops(cut);
  }
}
