// TetGen on nested shells (tetrahedralize.h).
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cstdio>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <map>
#include <string>
#include <vector>

#include "igaprep/core/error.h"
#include "igaprep/mesh/enclosed_volume.h"
#include "igaprep/mesh/offset_surface.h"
#include "igaprep/mesh/read_surface.h"
#include "igaprep/mesh/tetrahedralize.h"
#include "igaprep/models/shapes.h"

namespace {

using igaprep::mesh::TetMesh;
using igaprep::mesh::TriMesh;

double tet_volume(const TetMesh& m, Eigen::Index t) {
  const Eigen::Vector3d a = m.V.row(m.T(t, 0)), b = m.V.row(m.T(t, 1)), c = m.V.row(m.T(t, 2)), d = m.V.row(m.T(t, 3));
  return (b - a).dot((c - a).cross(d - a)) / 6.0;
}

TriMesh translated(TriMesh m, const Eigen::RowVector3d& shift) {
  m.V.rowwise() += shift;
  return m;
}

// A flat triangulated disc of radius r at height z (an open surface): a
// centre, then `rings` rings of `sectors` points.
TriMesh disc(double r, double z, int rings, int sectors) {
  TriMesh m;
  m.V.resize(1 + rings * sectors, 3);
  m.V.row(0) << 0, 0, z;
  for (int i = 1; i <= rings; ++i)
    for (int j = 0; j < sectors; ++j) {
      const double a = 2 * M_PI * (j + 0.5 * i) / sectors;
      m.V.row(1 + (i - 1) * sectors + j) << r * i / rings * std::cos(a), r * i / rings * std::sin(a), z;
    }
  std::vector<Eigen::RowVector3i> f;
  for (int j = 0; j < sectors; ++j) f.push_back({0, 1 + j, 1 + (j + 1) % sectors});
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < sectors; ++j) {
      const int a0 = 1 + (i - 1) * sectors, b0 = 1 + i * sectors, j1 = (j + 1) % sectors;
      f.push_back({a0 + j, b0 + j, b0 + j1});
      f.push_back({a0 + j, b0 + j1, a0 + j1});
    }
  m.F.resize(f.size(), 3);
  for (std::size_t i = 0; i < f.size(); ++i) m.F.row(i) = f[i];
  return m;
}

// Checks shared by every case: positive tets, input triangles as marked tet
// faces whose neighbouring tets have the right materials, material volumes.
void check_tet_mesh(const TetMesh& tm, const std::vector<TriMesh>& surfaces, const std::vector<TriMesh>& embedded) {
  const int n = static_cast<int>(surfaces.size());
  ASSERT_GT(tm.T.rows(), 0);
  ASSERT_EQ(tm.material.size(), tm.T.rows());
  for (Eigen::Index t = 0; t < tm.T.rows(); ++t) ASSERT_GT(tet_volume(tm, t), 0.0) << "tet " << t;
  EXPECT_GE(tm.material.minCoeff(), 0);
  EXPECT_LE(tm.material.maxCoeff(), n - 1);

  // Face -> materials of the tets on either side.
  std::map<std::array<int, 3>, std::vector<int>> face_tets;
  static const int kFace[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  for (Eigen::Index t = 0; t < tm.T.rows(); ++t)
    for (const auto& fc : kFace) {
      std::array<int, 3> k{tm.T(t, fc[0]), tm.T(t, fc[1]), tm.T(t, fc[2])};
      std::sort(k.begin(), k.end());
      face_tets[k].push_back(tm.material(t));
    }

  // Input triangles in order, with their markers, at their original positions.
  std::vector<const TriMesh*> all;
  for (const auto& s : surfaces) all.push_back(&s);
  for (const auto& s : embedded) all.push_back(&s);
  Eigen::Index row = 0;
  for (std::size_t k = 0; k < all.size(); ++k) {
    for (Eigen::Index f = 0; f < all[k]->F.rows(); ++f, ++row) {
      ASSERT_LT(row, tm.F.rows());
      ASSERT_EQ(tm.F_marker(row), static_cast<int>(k));
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(tm.V.row(tm.F(row, c)), all[k]->V.row(all[k]->F(f, c))) << "surface " << k << " face " << f;
      std::array<int, 3> key{tm.F(row, 0), tm.F(row, 1), tm.F(row, 2)};
      std::sort(key.begin(), key.end());
      auto it = face_tets.find(key);
      ASSERT_NE(it, face_tets.end()) << "surface " << k << " triangle " << f << " is not a tet face";
      std::vector<int> mats = it->second;
      std::sort(mats.begin(), mats.end());
      if (static_cast<int>(k) == 0) {
        EXPECT_EQ(mats, std::vector<int>({0})) << "outer face " << f;
      } else if (static_cast<int>(k) < n) {
        EXPECT_EQ(mats, std::vector<int>({static_cast<int>(k) - 1, static_cast<int>(k)})) << "surface " << k << " face " << f;
      } else {
        ASSERT_EQ(mats.size(), 2u);
        EXPECT_EQ(mats[0], mats[1]) << "embedded surface face " << f << " separates two materials";
      }
    }
  }
  EXPECT_EQ(row, tm.F.rows());

  // Material volumes equal the volumes between the surfaces.
  std::vector<double> mat_vol(n, 0.0);
  for (Eigen::Index t = 0; t < tm.T.rows(); ++t) mat_vol[tm.material(t)] += tet_volume(tm, t);
  for (int i = 0; i < n; ++i) {
    const double expected = igaprep::mesh::enclosed_volume(surfaces[i]) -
                            (i + 1 < n ? igaprep::mesh::enclosed_volume(surfaces[i + 1]) : 0.0);
    EXPECT_NEAR(mat_vol[i], expected, 1e-9 * std::abs(expected)) << "material " << i;
  }
}

}  // namespace

TEST(Tetrahedralize, NestedSpheres) {
  const std::vector<TriMesh> shells{igaprep::models::make_ellipsoid(1, 1, 1, 3),
                                    igaprep::models::make_ellipsoid(0.6, 0.55, 0.5, 2)};
  const TetMesh tm = igaprep::mesh::tetrahedralize(shells);
  check_tet_mesh(tm, shells, {});
  EXPECT_EQ(tm.material.maxCoeff(), 1);
}

TEST(Tetrahedralize, ThreeShellsWithMaxVolume) {
  const std::vector<TriMesh> shells{igaprep::models::make_ellipsoid(1, 1, 1, 3),
                                    igaprep::models::make_ellipsoid(0.7, 0.7, 0.7, 3),
                                    igaprep::models::make_ellipsoid(0.3, 0.3, 0.3, 2)};
  const double bound = 0.0005;
  igaprep::mesh::TetgenOptions opt;
  opt.max_volume = bound;
  const TetMesh tm = igaprep::mesh::tetrahedralize(shells, {}, opt);
  check_tet_mesh(tm, shells, {});
  // -Y forbids Steiner points on the input triangles, so TetGen rejects
  // refinement points that would encroach on them: tets touching an input
  // surface may exceed the bound somewhat; tets away from them must not.
  int input_points = 0;
  for (const auto& sh : shells) input_points += static_cast<int>(sh.V.rows());
  int above = 0, above_off_surface = 0;
  double largest = 0;
  for (Eigen::Index t = 0; t < tm.T.rows(); ++t) {
    const bool over = tet_volume(tm, t) > bound * (1 + 1e-9);
    const int on_surface = (tm.T.row(t).array() < input_points).count();
    above += over;
    above_off_surface += over && on_surface == 0;
    largest = std::max(largest, tet_volume(tm, t));
  }
  std::printf("max-volume bound %g: %d of %d tets above (%d not touching an input surface), largest %g\n", bound, above,
              int(tm.T.rows()), above_off_surface, largest);
  EXPECT_EQ(above_off_surface, 0);
  EXPECT_LE(above, 0.02 * tm.T.rows());
  EXPECT_LE(largest, 2 * bound);
  const TetMesh free = igaprep::mesh::tetrahedralize(shells);
  double largest_free = 0;
  for (Eigen::Index t = 0; t < free.T.rows(); ++t) largest_free = std::max(largest_free, tet_volume(free, t));
  EXPECT_GT(largest_free, 2 * bound);  // without it TetGen makes larger tets
  EXPECT_GT(tm.T.rows(), free.T.rows());
}

TEST(Tetrahedralize, EmbeddedDiscAndClosedSurface) {
  const std::vector<TriMesh> shells{igaprep::models::make_ellipsoid(1, 1, 1, 3),
                                    igaprep::models::make_ellipsoid(0.45, 0.45, 0.45, 2)};
  // An open disc inside T2 and a small closed sphere between T1 and T2: both
  // become tet faces, and neither changes any material.
  const std::vector<TriMesh> embedded{disc(0.3, 0.02, 4, 16),
                                      translated(igaprep::models::make_ellipsoid(0.15, 0.15, 0.15, 1), {0, 0, 0.7})};
  const TetMesh tm = igaprep::mesh::tetrahedralize(shells, embedded);
  check_tet_mesh(tm, shells, embedded);
  int disc_faces = 0, ball_faces = 0;
  for (Eigen::Index f = 0; f < tm.F.rows(); ++f) {
    disc_faces += tm.F_marker(f) == 2;
    ball_faces += tm.F_marker(f) == 3;
  }
  EXPECT_EQ(disc_faces, embedded[0].F.rows());
  EXPECT_EQ(ball_faces, embedded[1].F.rows());
}

TEST(Tetrahedralize, IntersectingSurfacesAreRefused) {
  const std::vector<TriMesh> shells{igaprep::models::make_ellipsoid(1, 1, 1, 2),
                                    translated(igaprep::models::make_ellipsoid(0.5, 0.5, 0.5, 2), {0.8, 0.0, 0.0})};
  try {
    igaprep::mesh::tetrahedralize(shells);
    FAIL() << "intersecting surfaces were accepted";
  } catch (const igaprep::Error& e) {
    EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput) << e.what();
    EXPECT_NE(std::string(e.what()).find("intersect"), std::string::npos) << e.what();
  }
}

TEST(Tetrahedralize, OpenShellIsRefused) {
  TriMesh s = igaprep::models::make_ellipsoid(1, 1, 1, 2);
  s.F.conservativeResize(s.F.rows() - 1, 3);
  try {
    igaprep::mesh::tetrahedralize({s});
    FAIL() << "an open T1 was accepted";
  } catch (const igaprep::Error& e) {
    EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput) << e.what();
    EXPECT_NE(std::string(e.what()).find("surface T1 is not closed"), std::string::npos) << e.what();
  }
}

TEST(Tetrahedralize, TetgenFailureIsAnErrorNotACrash) {
  // One self-intersecting surface (a vertex pulled through the solid to the
  // other side): only TetGen sees it; its failure must come back as an error.
  TriMesh s = igaprep::models::make_ellipsoid(1, 1, 1, 2);
  Eigen::Index top = 0;
  s.V.col(2).maxCoeff(&top);
  s.V.row(top) << 0.01, 0.02, -1.6;
  try {
    igaprep::mesh::tetrahedralize({s});
    FAIL() << "a self-intersecting surface was accepted";
  } catch (const igaprep::Error& e) {
    EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput) << e.what();
    EXPECT_NE(std::string(e.what()).find("TetGen"), std::string::npos) << e.what();
    std::printf("message: %s\n", e.what());
  }
}

// An embedded surface that crosses itself (a disc whose outer ring of
// vertices is folded back over its inside) is refused before TetGen, with
// where it crosses; TetGen alone would only say that a segment and a subface
// intersect.
TEST(Tetrahedralize, SelfIntersectingEmbeddedSurfaceIsRefused) {
  const std::vector<TriMesh> shells{igaprep::models::make_ellipsoid(1, 1, 1, 2)};
  TriMesh d = disc(0.5, 0.0, 4, 16);
  // The outermost vertices go to the opposite side of the centre, at
  // alternating heights just above and below the disc.
  Eigen::Index far = 0;
  d.V.rowwise().norm().maxCoeff(&far);
  const double r = d.V.row(far).norm();
  for (Eigen::Index i = 0; i < d.V.rows(); ++i)
    if (d.V.row(i).norm() > 0.99 * r) d.V.row(i) *= -0.3, d.V(i, 2) = 0.05 * ((i % 2) ? 1.0 : -1.0);
  try {
    igaprep::mesh::tetrahedralize(shells, {d});
    FAIL() << "a self-intersecting embedded surface was accepted";
  } catch (const igaprep::Error& e) {
    EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput) << e.what();
    EXPECT_NE(std::string(e.what()).find("embedded surface 0 intersects itself"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("near ("), std::string::npos) << e.what();
  }
  // The same disc unfolded is accepted.
  EXPECT_NO_THROW(igaprep::mesh::tetrahedralize(shells, {disc(0.5, 0.0, 4, 16)}));
}

TEST(Tetrahedralize, PelvisWithCorticalShell) {
  const std::string path = std::string(IGAPREP_SHARED_MODELS_DIR) + "/pelvis_hip.stl";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared model " << path << " is absent";
  const TriMesh outer = igaprep::mesh::read_surface(path);
  const std::vector<TriMesh> shells{outer, igaprep::mesh::offset_inward(outer, {0.8})};
  const TetMesh tm = igaprep::mesh::tetrahedralize(shells);
  check_tet_mesh(tm, shells, {});
}

namespace {

// The children of `pid` (from /proc/*/stat: "pid (comm) state ppid ...").
std::vector<int> children_of(int pid) {
  std::vector<int> out;
  for (const auto& e : std::filesystem::directory_iterator("/proc")) {
    const std::string name = e.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream in(e.path() / "stat");
    std::string stat;
    std::getline(in, stat);
    const std::size_t close = stat.rfind(')');
    if (close == std::string::npos) continue;
    std::istringstream rest(stat.substr(close + 2));
    char state = 0;
    int ppid = 0;
    rest >> state >> ppid;
    if (ppid == pid) out.push_back(std::stoi(name));
  }
  return out;
}

// Running, not a zombie or gone.
bool alive(int pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string stat;
  if (!std::getline(in, stat)) return false;
  const std::size_t close = stat.rfind(')');
  return close != std::string::npos && close + 2 < stat.size() && stat[close + 2] != 'Z' && stat[close + 2] != 'X';
}

}  // namespace

// Issue 21, item 3: a SIGKILL of the process that runs TetGen (a scheduler,
// a CI timeout) takes the forked worker with it.
TEST(Tetrahedralize, TheWorkerDiesWithItsParent) {
  const pid_t runner = ::fork();
  ASSERT_GE(runner, 0);
  if (runner == 0) {
    igaprep::mesh::TetgenOptions opt;
    opt.max_volume = 1e-9;  // minutes of refinement
    opt.max_tets = 1e12;
    try {
      igaprep::mesh::tetrahedralize({igaprep::models::make_ellipsoid(1, 1, 1, 3)}, {}, opt);
    } catch (...) {
    }
    ::_exit(0);
  }
  std::vector<int> workers;
  for (int i = 0; i < 200 && workers.empty(); ++i) {
    ::usleep(20000);
    workers = children_of(runner);
  }
  ASSERT_EQ(workers.size(), 1u) << "no TetGen worker appeared";
  ::usleep(200000);
  ASSERT_TRUE(alive(workers[0]));
  ::kill(runner, SIGKILL);
  ::waitpid(runner, nullptr, 0);
  bool gone = false;
  for (int i = 0; i < 150 && !gone; ++i) {
    gone = !alive(workers[0]);
    if (!gone) ::usleep(20000);
  }
  EXPECT_TRUE(gone) << "TetGen worker " << workers[0] << " outlived its parent";
  if (!gone) ::kill(workers[0], SIGKILL);
}

// Issue 21, item 6: a maximum tet volume that would make more tets than the
// limit is refused with the estimate before TetGen allocates anything.
TEST(Tetrahedralize, TooManyTetsAreRefusedBeforeTetgenRuns) {
  igaprep::mesh::TetgenOptions opt;
  opt.max_volume = 1e-12;
  try {
    igaprep::mesh::tetrahedralize({igaprep::models::make_ellipsoid(1, 1, 1, 2)}, {}, opt);
    ADD_FAILURE() << "no error";
  } catch (const igaprep::Error& e) {
    EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput);
    const std::string what = e.what();
    EXPECT_NE(what.find("a maximum tet volume of 1e-12 makes at least 4."), std::string::npos) << what;
    EXPECT_NE(what.find("more than the limit of 2e+07 (max_tets)"), std::string::npos) << what;
  }
  opt.max_volume = 0.01;  // about 400 tets and more: within the limit
  EXPECT_GT(igaprep::mesh::tetrahedralize({igaprep::models::make_ellipsoid(1, 1, 1, 2)}, {}, opt).T.rows(), 400);
}
