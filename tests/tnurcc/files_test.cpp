// The cage's files read back: OBJ with its crease tags, the intervals' JSON.
#include <gtest/gtest.h>

#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "igaprep/export/tnurcc_files.h"
#include "tnurcc/tnurcc_models.h"

namespace {

using namespace igaprep::spline;

TEST(TnurccFiles, CageObjReadsBackWithItsCreases) {
  const Cage c = surface_cage(tnurcc_test::boxes(2, 2), 0);
  std::stringstream obj;
  igaprep::exporter::write_cage_obj(c, obj);
  const Cage back = igaprep::exporter::read_cage_obj(obj);
  ASSERT_EQ(back.points.rows(), c.points.rows());
  EXPECT_EQ((back.points - c.points).cwiseAbs().maxCoeff(), 0.0);  // 17 digits: exact
  ASSERT_EQ(back.faces, c.faces);
  ASSERT_EQ(back.edges.size(), c.edges.size());
  std::map<std::pair<int, int>, double> sharpness;
  for (const auto& e : c.edges)
    sharpness[std::minmax(e.vertices[0], e.vertices[1])] = e.sharpness;
  long creases = 0;
  for (const auto& e : back.edges) {
    const auto it = sharpness.find(std::minmax(e.vertices[0], e.vertices[1]));
    ASSERT_NE(it, sharpness.end());
    EXPECT_EQ(e.sharpness, it->second);
    creases += e.sharpness == kInfiniteSharpness;
  }
  EXPECT_EQ(creases, 4 * 8 + 8 * 4);
}

TEST(TnurccFiles, BadObjLinesAreNamed) {
  std::stringstream tri("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  try {
    igaprep::exporter::read_cage_obj(tri);
    FAIL() << "a triangle was accepted";
  } catch (const igaprep::Error& e) {
    EXPECT_NE(std::string(e.what()).find("line 4"), std::string::npos) << e.what();
  }
  std::stringstream crease("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\nt crease 2/1/0 0 2 10\n");
  EXPECT_THROW(igaprep::exporter::read_cage_obj(crease), igaprep::Error);  // a diagonal is no edge
}

TEST(TnurccFiles, IntervalsJsonListsEveryEdge) {
  const Cage c = surface_cage(tnurcc_test::boxes(1, 4), 0);
  std::stringstream out;
  igaprep::exporter::write_cage_intervals(c, out);
  const nlohmann::json j = nlohmann::json::parse(out.str());
  EXPECT_EQ(j["format"], "igaprep-tnurcc-intervals");
  ASSERT_EQ(j["edges"].size(), c.edges.size());
  EXPECT_EQ(j["edges"][0][0].get<int>(), c.edges[0].vertices[0]);
  EXPECT_DOUBLE_EQ(j["edges"][5][2].get<double>(), 0.25);
}

}  // namespace
