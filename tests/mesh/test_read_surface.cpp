// Readers (STL ASCII/binary, OBJ, OFF, PLY ASCII/binary) on small files,
// reading errors, and write -> read round trips.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <unistd.h>

#include <Eigen/Geometry>

#include "igaprep/core/error.h"
#include "igaprep/mesh/enclosed_volume.h"
#include "igaprep/mesh/read_surface.h"
#include "igaprep/mesh/write_surface.h"

using igaprep::mesh::read_surface;
using igaprep::mesh::TriMesh;
using igaprep::mesh::write_surface;

namespace {

std::string data(const std::string& name) { return std::string(IGAPREP_TEST_DATA_DIR) + "/mesh/" + name; }

// Expects read_surface(path) to throw a bad-input error whose message names
// the file and contains `words`.
void expect_read_error(const std::string& name, const std::string& words) {
  const std::string path = data(name);
  try {
    read_surface(path);
    FAIL() << name << " was read without error";
  } catch (const igaprep::Error& e) {
    const std::string msg = e.what();
    EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput) << msg;
    EXPECT_NE(msg.find(name), std::string::npos) << "message does not name the file: " << msg;
    EXPECT_NE(msg.find(words), std::string::npos) << "message lacks '" << words << "': " << msg;
  }
}

// A folder of this process's own, removed when the test program ends.
std::string temp_dir() {
  struct Folder {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("igaprep_meshio_test_" + std::to_string(::getpid()));
    Folder() { std::filesystem::create_directories(path); }
    ~Folder() {
      std::error_code ec;
      std::filesystem::remove_all(path, ec);
    }
  };
  static Folder folder;
  return folder.path.string();
}

// Subdivided octahedron on the unit sphere: coordinates that are not floats.
TriMesh round_sphere() {
  TriMesh m;
  m.V.resize(6, 3);
  m.V << 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1;
  m.F.resize(8, 3);
  m.F << 0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5;
  for (int level = 0; level < 2; ++level) {
    std::map<std::pair<int, int>, int> mid;
    std::vector<Eigen::Vector3d> V;
    for (int i = 0; i < m.V.rows(); ++i) V.push_back(m.V.row(i));
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      V.push_back((V[a] + V[b]).normalized());
      return mid[key] = static_cast<int>(V.size()) - 1;
    };
    Eigen::MatrixXi F(4 * m.F.rows(), 3);
    for (int f = 0; f < m.F.rows(); ++f) {
      const int a = m.F(f, 0), b = m.F(f, 1), c = m.F(f, 2);
      const int ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      F.row(4 * f) << a, ab, ca;
      F.row(4 * f + 1) << ab, b, bc;
      F.row(4 * f + 2) << ca, bc, c;
      F.row(4 * f + 3) << ab, bc, ca;
    }
    m.V.resize(V.size(), 3);
    for (size_t i = 0; i < V.size(); ++i) m.V.row(i) = V[i];
    m.F = F;
  }
  return m;
}

}  // namespace

struct GoodFile {
  const char* name;
  int vertices, faces;
  double volume;
};

std::ostream& operator<<(std::ostream& out, const GoodFile& g) { return out << g.name; }

class ReadGoodFile : public ::testing::TestWithParam<GoodFile> {};

TEST_P(ReadGoodFile, CountsVolumeAndBox) {
  const GoodFile& g = GetParam();
  const TriMesh m = read_surface(data(g.name));
  EXPECT_EQ(m.V.rows(), g.vertices);
  EXPECT_EQ(m.F.rows(), g.faces);
  EXPECT_NEAR(igaprep::mesh::enclosed_volume(m), g.volume, 1e-12);
  EXPECT_NEAR(m.V.minCoeff(), 0.0, 0.0);
  EXPECT_NEAR(m.V.maxCoeff(), 1.0, 0.0);
  EXPECT_GE(m.F.minCoeff(), 0);
  EXPECT_LT(m.F.maxCoeff(), m.V.rows());
}

INSTANTIATE_TEST_SUITE_P(AllFormats, ReadGoodFile,
                         ::testing::Values(GoodFile{"tetra_ascii.stl", 4, 4, 1.0 / 6}, GoodFile{"tetra_binary.stl", 4, 4, 1.0 / 6},
                                           GoodFile{"cube_quads.obj", 8, 12, 1.0}, GoodFile{"tetra_rgb.obj", 4, 4, 1.0 / 6},
                                           GoodFile{"cube.off", 8, 12, 1.0}, GoodFile{"tetra_off_content.txt", 4, 4, 1.0 / 6},
                                           GoodFile{"tetra_ascii.ply", 4, 4, 1.0 / 6},
                                           GoodFile{"tetra_binary_le.ply", 4, 4, 1.0 / 6},
                                           GoodFile{"tetra_binary_be.ply", 4, 4, 1.0 / 6}),
                         [](const auto& info) {
                           std::string n = info.param.name;
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

TEST(ReadSurface, ObjColoursAfterXyzAreIgnored) {
  const TriMesh m = read_surface(data("tetra_rgb.obj"));
  Eigen::MatrixXd expected(4, 3);
  expected << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  EXPECT_EQ(m.V, expected);
  // Negative (relative) indices -4..-1 are vertices 0..3.
  EXPECT_EQ(m.F.row(0), Eigen::RowVector3i(0, 2, 1));
}

TEST(ReadSurface, ObjQuadsAreFanTriangulated) {
  const TriMesh m = read_surface(data("cube_quads.obj"));
  // First quad 1 3 4 2 (1-based) becomes (0, 2, 3) and (0, 3, 1).
  EXPECT_EQ(m.F.row(0), Eigen::RowVector3i(0, 2, 3));
  EXPECT_EQ(m.F.row(1), Eigen::RowVector3i(0, 3, 1));
}

TEST(ReadSurface, StlMergesIdenticalCornersOnly) {
  // Both STL files store 12 corners of 4 distinct points.
  for (const char* name : {"tetra_ascii.stl", "tetra_binary.stl"}) {
    const TriMesh m = read_surface(data(name));
    ASSERT_EQ(m.V.rows(), 4) << name;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) EXPECT_GT((m.V.row(i) - m.V.row(j)).norm(), 0.5) << name;
  }
}

TEST(ReadSurfaceErrors, EachHasItsOwnMessage) {
  expect_read_error("empty.stl", "empty file");
  expect_read_error("truncated_binary.stl", "truncated binary STL");
  expect_read_error("truncated.off", "truncated");
  expect_read_error("truncated_binary_le.ply", "truncated");
  expect_read_error("unknown.dat", "unknown format");
  expect_read_error("unknown_binary.bin", "unknown format");
  expect_read_error("nan.obj", "NaN or infinite coordinate at vertex 2");
  expect_read_error("inf.off", "NaN or infinite coordinate at vertex 3");
  expect_read_error("bad_index.off", "refers to vertex 7");
  expect_read_error("no_such_file.stl", "cannot open");
}

TEST(ReadSurfaceErrors, TruncatedAsciiStl) {
  const std::string path = temp_dir() + "/cut.stl";
  std::ifstream in(data("tetra_ascii.stl"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  {
    std::ofstream out(path);
    out << text.substr(0, text.size() / 2);
  }
  try {
    read_surface(path);
    FAIL() << "truncated ASCII STL was read";
  } catch (const igaprep::Error& e) {
    EXPECT_NE(std::string(e.what()).find("cut.stl: truncated"), std::string::npos) << e.what();
  }
}

TEST(WriteSurface, RoundTripsPreserveTheMesh) {
  const TriMesh m = round_sphere();
  ASSERT_EQ(m.F.rows(), 128);
  const std::string dir = temp_dir();
  for (const char* ext : {"obj", "off", "OFF"}) {
    const std::string path = dir + "/sphere." + ext;
    write_surface(path, m);
    const TriMesh r = read_surface(path);
    EXPECT_EQ(r.V, m.V) << ext << ": coordinates must come back bit for bit";
    EXPECT_EQ(r.F, m.F) << ext;
  }
  // Binary STL stores floats and merges corners: same triangles, corner by
  // corner, to float precision.
  const std::string path = dir + "/sphere.stl";
  write_surface(path, m);
  EXPECT_EQ(std::filesystem::file_size(path), 84u + 50u * 128u);
  const TriMesh r = read_surface(path);
  ASSERT_EQ(r.V.rows(), m.V.rows());
  ASSERT_EQ(r.F.rows(), m.F.rows());
  for (int f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d)
        EXPECT_EQ(r.V(r.F(f, k), d), static_cast<double>(static_cast<float>(m.V(m.F(f, k), d))));
  // The same mesh written twice gives the same bytes (deterministic output).
  write_surface(dir + "/again.stl", m);
  std::ifstream a(path, std::ios::binary), b(dir + "/again.stl", std::ios::binary);
  const std::string sa((std::istreambuf_iterator<char>(a)), {}), sb((std::istreambuf_iterator<char>(b)), {});
  EXPECT_TRUE(sa == sb) << "two writes of one mesh differ";
}

TEST(WriteSurface, SharedModelRoundTrip) {
  const std::string path = std::string(IGAPREP_SHARED_MODELS_DIR) + "/torus_genus3.off";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared models not found at " << IGAPREP_SHARED_MODELS_DIR;
  const TriMesh m = read_surface(path);
  for (const char* ext : {"obj", "off"}) {
    const std::string out = temp_dir() + "/torus." + ext;
    write_surface(out, m);
    const TriMesh r = read_surface(out);
    EXPECT_EQ(r.V, m.V) << ext;
    EXPECT_EQ(r.F, m.F) << ext;
  }
}

TEST(WriteSurface, BadTargetsThrowAndLeaveNothing) {
  const TriMesh m = read_surface(data("tetra_ascii.stl"));
  const std::string dir = temp_dir();
  try {
    write_surface(dir + "/tetra.xyz", m);
    FAIL() << "unknown extension accepted";
  } catch (const igaprep::Error& e) {
    EXPECT_NE(std::string(e.what()).find("unknown extension"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir + "/tetra.xyz"));
  EXPECT_THROW(write_surface(dir + "/no/such/folder/tetra.stl", m), igaprep::Error);
  EXPECT_FALSE(std::filesystem::exists(dir + "/no/such/folder/tetra.stl"));
}

// Issue 21, item 13: a PLY header whose counts do not match its body, and an
// index that is no index, are said as such (they read as "a face with 0
// vertices" and "bad vertex index -2113732608.000000").
TEST(ReadSurfaceErrors, PlyCountsThatDoNotMatchTheBodyAreNamed) {
  std::ifstream in(data("tetra_ascii.ply"));
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto read_error = [&](const std::string& from, const std::string& to) {
    std::string changed = text;
    changed.replace(changed.find(from), from.size(), to);
    const std::string path = temp_dir() + "/changed.ply";
    std::ofstream(path) << changed;
    try {
      read_surface(path);
      ADD_FAILURE() << "read without error";
    } catch (const igaprep::Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string counts = read_error("element vertex 4", "element vertex 5");
  EXPECT_NE(counts.find("continues onto line"), std::string::npos) << counts;
  EXPECT_NE(counts.find("line 18: vertex 4 of 5 continues onto line 19 (one element per line): the header's element counts (5 vertex) do not match the file"), std::string::npos) << counts;
  const std::string index = read_error("3 0 1 3", "3 0 -7 3");
  EXPECT_NE(index.find("face 1: its list of 3 vertex indices holds -7, which is no vertex index"), std::string::npos)
      << index;
}

// A file whose read fails (here: reading /proc/self/mem at address 0 gives
// EIO) is a read error named with the reason, not an empty file.
TEST(ReadSurfaceErrors, AReadErrorIsNamedNotTakenForAnEmptyFile) {
  try {
    read_surface("/proc/self/mem");
    ADD_FAILURE() << "read without error";
  } catch (const igaprep::Error& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput);
    EXPECT_NE(what.find("/proc/self/mem: read error after 0 bytes of the surface file: "), std::string::npos) << what;
    EXPECT_EQ(what.find("empty"), std::string::npos) << what;
  }
}
