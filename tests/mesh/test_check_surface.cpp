// Validation: every defect on a small bad file gives its own message naming
// the file; reports (genus, volume, flags) on good and real surfaces.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <utility>

#include "igaprep/core/error.h"
#include "igaprep/mesh/check_surface.h"
#include "igaprep/mesh/orient_outward.h"
#include "igaprep/mesh/read_surface.h"
#include "igaprep/mesh/remove_unused_vertices.h"

using igaprep::mesh::check_and_repair_surface;
using igaprep::mesh::check_surface;
using igaprep::mesh::load_checked_surface;
using igaprep::mesh::read_surface;
using igaprep::mesh::SurfaceReport;
using igaprep::mesh::TriMesh;

namespace {

std::string data(const std::string& name) { return std::string(IGAPREP_TEST_DATA_DIR) + "/mesh/" + name; }

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// Checks `name`: exactly one error, containing every word in `words` and the
// file's name; load_checked_surface throws it as bad input.
SurfaceReport expect_defect(const std::string& name, const std::vector<std::string>& words, size_t errors = 1) {
  const TriMesh m = read_surface(data(name));
  SurfaceReport r = check_surface(m, data(name));
  EXPECT_FALSE(r.ok()) << name;
  EXPECT_EQ(r.errors.size(), errors) << name << ":\n" << igaprep::mesh::format_report(r);
  std::string all;
  for (const auto& e : r.errors) all += e + "\n";
  for (const auto& w : words) EXPECT_TRUE(contains(all, w)) << "no '" << w << "' in:\n" << all;
  try {
    load_checked_surface(data(name));
    ADD_FAILURE() << name << " passed load_checked_surface";
  } catch (const igaprep::Error& e) {
    EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput);
    for (const auto& w : words) EXPECT_TRUE(contains(e.what(), w)) << e.what();
    EXPECT_TRUE(contains(e.what(), name)) << e.what();
  }
  return r;
}

// Torus of revolution as a grid: genus 1 by construction.
TriMesh grid_torus(int n, int m) {
  TriMesh t;
  t.V.resize(n * m, 3);
  t.F.resize(2 * n * m, 3);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double u = 2 * M_PI * i / n, v = 2 * M_PI * j / m;
      t.V.row(i * m + j) << (2 + 0.5 * std::cos(v)) * std::cos(u), (2 + 0.5 * std::cos(v)) * std::sin(u), 0.5 * std::sin(v);
      const int a = i * m + j, b = ((i + 1) % n) * m + j, c = ((i + 1) % n) * m + (j + 1) % m, d = i * m + (j + 1) % m;
      t.F.row(2 * (i * m + j)) << a, b, c;
      t.F.row(2 * (i * m + j) + 1) << a, c, d;
    }
  return t;
}

}  // namespace

TEST(CheckSurface, TetrahedronReport) {
  SurfaceReport r;
  const TriMesh m = load_checked_surface(data("tetra_binary.stl"), &r);
  EXPECT_TRUE(r.ok());
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
  EXPECT_EQ(r.vertices, 4);
  EXPECT_EQ(r.faces, 4);
  EXPECT_EQ(r.components, 1);
  EXPECT_EQ(r.genus, 0);
  EXPECT_TRUE(r.closed && r.manifold && r.oriented);
  EXPECT_EQ(r.self_intersections, 0);
  EXPECT_NEAR(r.volume, 1.0 / 6.0, 1e-15);
  EXPECT_EQ(r.bbox_min, Eigen::Vector3d(0, 0, 0));
  EXPECT_EQ(r.bbox_max, Eigen::Vector3d(1, 1, 1));
  EXPECT_EQ(m.F.rows(), 4);
}

TEST(CheckSurface, CubeFromQuads) {
  SurfaceReport r;
  load_checked_surface(data("cube_quads.obj"), &r);
  EXPECT_EQ(r.genus, 0);
  EXPECT_NEAR(r.volume, 1.0, 1e-14);
  EXPECT_EQ(r.self_intersections, 0);
}

TEST(CheckSurface, TorusHasGenusOne) {
  const TriMesh t = grid_torus(24, 12);
  const SurfaceReport r = check_surface(t, "torus");
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(r.genus, 1);
  EXPECT_EQ(r.self_intersections, 0);
  // Polyhedral torus: a little below 2 pi^2 R r^2 = 9.87 from the inscribed grid.
  EXPECT_GT(r.volume, 0.9 * 2 * M_PI * M_PI * 2 * 0.25);
  EXPECT_LT(r.volume, 2 * M_PI * M_PI * 2 * 0.25);
}

TEST(CheckSurfaceDefects, BoundaryEdges) {
  const auto r = expect_defect("open_box.obj", {"open_box.obj: 4 boundary edges (not closed)", "e.g. edge between vertices"});
  EXPECT_FALSE(r.closed);
  EXPECT_EQ(r.genus, -1);
}

TEST(CheckSurfaceDefects, NonManifoldEdge) {
  const auto r = expect_defect("nonmanifold_edge.off", {"1 non-manifold edges", "between vertices 0 and 1", "shared by 4 faces"});
  EXPECT_FALSE(r.manifold);
}

TEST(CheckSurfaceDefects, NonManifoldVertex) {
  const auto r = expect_defect("nonmanifold_vertex.off", {"1 non-manifold vertices", "vertex 0 at (0, 0, 0)"});
  EXPECT_FALSE(r.manifold);
  EXPECT_TRUE(r.closed);
}

TEST(CheckSurfaceDefects, InconsistentOrientation) {
  const auto r = expect_defect("flipped_face.off", {"inconsistent orientation", "3 edges"});
  EXPECT_FALSE(r.oriented);
}

TEST(CheckSurfaceDefects, ZeroAreaFace) {
  const auto r = expect_defect("degenerate.off", {"1 degenerate faces", "1 with zero area", "face 5 (vertices 4, 1, 2)"});
  EXPECT_TRUE(r.closed && r.manifold && r.oriented);
  EXPECT_EQ(r.genus, 0);
}

TEST(CheckSurfaceDefects, RepeatedVertex) {
  // The extra face (0, 0, 1) also puts edge 0-1 into four faces.
  expect_defect("repeated_vertex.off", {"degenerate faces", "1 with a repeated vertex", "face 4 (vertices 0, 0, 1)",
                                        "non-manifold edges"}, 2);
}

TEST(CheckSurfaceDefects, SelfIntersection) {
  const auto r = expect_defect("self_intersecting.off", {"pairs of self-intersecting faces", "e.g. faces"});
  EXPECT_GT(r.self_intersections, 0);
  EXPECT_TRUE(r.closed && r.manifold && r.oriented);
}

TEST(CheckSurfaceDefects, MoreThanOneComponent) {
  const auto r = expect_defect("two_components.off", {"more than one component: 2 separate pieces"});
  EXPECT_EQ(r.components, 2);
  EXPECT_EQ(r.genus, 0);  // total genus of two spheres
}

TEST(CheckSurfaceDefects, NaNInMemoryMesh) {
  TriMesh m = read_surface(data("tetra_ascii.ply"));
  m.V(2, 1) = std::nan("");
  const SurfaceReport r = check_surface(std::as_const(m), "made.ply");
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_TRUE(contains(r.errors[0], "made.ply: 1 vertices with NaN or infinite coordinates, e.g. vertex 2"));
  EXPECT_TRUE(contains(check_surface(TriMesh{}, "e.obj").errors.at(0), "e.obj: no faces"));
}

// The check only reports an inward surface; the repair turns it.
TEST(CheckSurface, InwardSurfaceIsReportedNotChanged) {
  const TriMesh m = read_surface(data("inward.off"));
  const SurfaceReport r = check_surface(m, "inward.off");
  EXPECT_TRUE(r.ok());
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0], "inward.off: surface is oriented inward (normals point into the solid)");
  EXPECT_EQ(r.inward_pieces, std::vector<int>{0});
  EXPECT_NEAR(r.volume, 1.0 / 6.0, 1e-15);  // counted outward
  TriMesh turned = m;
  EXPECT_EQ(igaprep::mesh::orient_outward(turned), std::vector<int>{0});
  for (int f = 0; f < m.F.rows(); ++f) EXPECT_EQ(turned.F.row(f), Eigen::RowVector3i(m.F(f, 0), m.F(f, 2), m.F(f, 1)));
  EXPECT_TRUE(igaprep::mesh::orient_outward(turned).empty());  // nothing left to turn
}

TEST(CheckSurface, InwardSurfaceIsReoriented) {
  TriMesh m = read_surface(data("inward.off"));
  const TriMesh before = m;
  const SurfaceReport r = check_and_repair_surface(m, "inward.off");
  EXPECT_TRUE(r.ok());
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_TRUE(contains(r.warnings[0], "inward.off: surface is oriented inward")) << r.warnings[0];
  EXPECT_TRUE(contains(r.warnings[0], "re-oriented outward"));
  EXPECT_NEAR(r.volume, 1.0 / 6.0, 1e-15);
  for (int f = 0; f < m.F.rows(); ++f) EXPECT_EQ(m.F.row(f), Eigen::RowVector3i(before.F(f, 0), before.F(f, 2), before.F(f, 1)));
  // Checking again: nothing left to fix.
  const SurfaceReport again = check_surface(std::as_const(m), "inward.off");
  EXPECT_TRUE(again.warnings.empty());
  EXPECT_NEAR(again.volume, 1.0 / 6.0, 1e-15);
}

TEST(CheckSurface, UnreferencedVerticesAreReportedNotRemoved) {
  const TriMesh m = read_surface(data("unreferenced_vertex.off"));
  const SurfaceReport r = check_surface(m, "u.off");
  EXPECT_TRUE(r.ok());
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0], "u.off: 1 vertices are used by no face");
  EXPECT_EQ(r.unused_vertices, 1);
  EXPECT_EQ(r.vertices, 4);
  TriMesh pruned = m;
  EXPECT_EQ(igaprep::mesh::remove_unused_vertices(pruned), 1);
  EXPECT_EQ(pruned.V.rows(), 4);
  EXPECT_EQ(check_surface(std::as_const(pruned), "u.off").warnings.size(), 0u);
  EXPECT_EQ(igaprep::mesh::remove_unused_vertices(pruned), 0);
}

TEST(CheckSurface, UnreferencedVerticesAreRemoved) {
  TriMesh m = read_surface(data("unreferenced_vertex.off"));
  ASSERT_EQ(m.V.rows(), 5);
  const SurfaceReport r = check_and_repair_surface(m, "u.off");
  EXPECT_TRUE(r.ok());
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_TRUE(contains(r.warnings[0], "1 vertices used by no face were removed"));
  EXPECT_EQ(m.V.rows(), 4);
  EXPECT_EQ(r.vertices, 4);
  EXPECT_NEAR(r.volume, 1.0 / 6.0, 1e-15);
}

struct SharedModel {
  const char* file;
  int genus;
};
std::ostream& operator<<(std::ostream& out, const SharedModel& m) { return out << m.file; }
class CheckSharedModel : public ::testing::TestWithParam<SharedModel> {};

TEST_P(CheckSharedModel, GenusAndValidity) {
  const std::string path = std::string(IGAPREP_SHARED_MODELS_DIR) + "/" + GetParam().file;
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared models not found at " << IGAPREP_SHARED_MODELS_DIR;
  SurfaceReport r;
  const TriMesh m = load_checked_surface(path, &r);
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(r.genus, GetParam().genus);
  EXPECT_EQ(r.components, 1);
  EXPECT_TRUE(r.closed && r.manifold && r.oriented);
  EXPECT_EQ(r.self_intersections, 0);
  EXPECT_GT(r.volume, 0.0);
  // The volume is a small share of the box but not vanishing.
  const double box = (r.bbox_max - r.bbox_min).prod();
  EXPECT_GT(r.volume, 0.001 * box);
  EXPECT_LT(r.volume, box);
  EXPECT_EQ(r.vertices, m.V.rows());
  EXPECT_EQ(r.faces, m.F.rows());
}

INSTANTIATE_TEST_SUITE_P(Models, CheckSharedModel,
                         ::testing::Values(SharedModel{"pelvis_hip.stl", 2}, SharedModel{"propeller.stl", 1},
                                           SharedModel{"hand.obj", 0}, SharedModel{"kitten.obj", 1},
                                           SharedModel{"torus_genus3.off", 3}),
                         [](const auto& info) {
                           std::string n = info.param.file;
                           return n.substr(0, n.find('.'));
                         });

TEST(CheckSharedModelCounts, MatchTheReadme) {
  // Vertex and face counts from ../shared/models/README.md.
  const std::string dir = IGAPREP_SHARED_MODELS_DIR;
  if (!std::filesystem::exists(dir + "/pelvis_hip.stl")) GTEST_SKIP() << "shared models not found at " << dir;
  const struct {
    const char* file;
    int v, f;
  } expected[] = {{"pelvis_hip.stl", 8107, 16218}, {"propeller.stl", 7410, 14820}, {"hand.obj", 7993, 15982},
                  {"kitten.obj", 9275, 18550}, {"torus_genus3.off", 3596, 7200}};
  for (const auto& e : expected) {
    SurfaceReport r;
    load_checked_surface(dir + "/" + e.file, &r);
    EXPECT_EQ(r.vertices, e.v) << e.file;
    EXPECT_EQ(r.faces, e.f) << e.file;
  }
}

// Issue 21, item 7: a solid whose volume overflows (coordinates near 1e300)
// or underflows (near 1e-300) is a defect, not a surface with volume -nan or 0.
TEST(CheckSurfaceDefects, AVolumeThatOverflowsOrVanishesIsADefect) {
  const TriMesh torus = grid_torus(24, 12);
  for (const double scale : {1e110, 1e-110}) {
    TriMesh m = torus;
    m.V *= scale;
    const SurfaceReport r = check_surface(m, "scaled.off");
    ASSERT_EQ(r.errors.size(), 1u) << scale << ": " << igaprep::mesh::format_report(r);
    EXPECT_TRUE(contains(r.errors[0], scale > 1 ? "scaled.off: its enclosed volume overflows"
                                                : "scaled.off: it encloses no volume"))
        << r.errors[0];
  }
  TriMesh fine = torus;
  fine.V *= 1e-3;
  EXPECT_TRUE(check_surface(fine, "small.off").ok());
}

// Issue 21, item 11: a FIFO or a device is refused before it is read (it
// would block or never end).
TEST(CheckSurfaceDefects, AFifoOrADeviceIsNotReadAsASurface) {
  const std::string fifo = std::string(IGAPREP_BINARY_DIR) + "/test_surface.fifo.stl";
  std::filesystem::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  for (const std::string& path : {fifo, std::string("/dev/zero")}) {
    try {
      read_surface(path);
      ADD_FAILURE() << path << " was read";
    } catch (const igaprep::Error& e) {
      EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput);
      EXPECT_TRUE(contains(e.what(), path + ": is not a regular file")) << e.what();
    }
  }
  std::filesystem::remove(fifo);
}
