// Nesting of closed surfaces: nested spheres accepted; crossing, touching,
// reversed and separate pairs rejected with both names.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "igaprep/core/error.h"
#include "igaprep/mesh/check_surface.h"
#include "igaprep/mesh/nesting.h"
#include "igaprep/models/shapes.h"

using igaprep::mesh::check_nesting;
using igaprep::mesh::NestingReport;
using igaprep::mesh::TriMesh;

namespace {

// Icosahedron subdivided `levels` times, projected to the sphere.
TriMesh icosphere(double radius, const Eigen::Vector3d& centre, int levels) {
  TriMesh m = igaprep::models::make_ellipsoid(radius, radius, radius, levels);
  m.V.rowwise() += centre.transpose();
  return m;
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

TEST(Nesting, IcosphereIsAValidOutwardSurface) {
  const TriMesh s = icosphere(1.0, Eigen::Vector3d::Zero(), 2);
  const auto r = igaprep::mesh::check_surface(s, "sphere");
  EXPECT_TRUE(r.ok());
  EXPECT_TRUE(r.warnings.empty());  // already outward: the tests below use the orientation as made
  EXPECT_EQ(r.faces, 320);
  EXPECT_EQ(r.genus, 0);
  // Inscribed polyhedron: a little below the ball's 4/3 pi (4.047 at 320 faces).
  EXPECT_LT(r.volume, 4.0 / 3.0 * M_PI);
  EXPECT_GT(r.volume, 0.95 * 4.0 / 3.0 * M_PI);
}

TEST(Nesting, SphereInsideSphere) {
  const TriMesh outer = icosphere(1.0, Eigen::Vector3d::Zero(), 3);
  const TriMesh inner = icosphere(0.5, Eigen::Vector3d::Zero(), 3);
  const NestingReport r = check_nesting({outer, inner}, {"outer", "inner"});
  EXPECT_TRUE(r.nested);
  EXPECT_TRUE(r.errors.empty());
  // Three levels, the innermost off centre but inside.
  const TriMesh core = icosphere(0.2, Eigen::Vector3d(0.2, 0.1, 0), 2);
  EXPECT_TRUE(check_nesting({outer, inner, core}, {"T1", "T2", "T3"}).nested);
  // A single surface is trivially nested.
  EXPECT_TRUE(check_nesting({outer}, {"T1"}).nested);
}

TEST(Nesting, ReversedOrderIsRejected) {
  const TriMesh outer = icosphere(1.0, Eigen::Vector3d::Zero(), 2);
  const TriMesh inner = icosphere(0.5, Eigen::Vector3d::Zero(), 2);
  const NestingReport r = check_nesting({inner, outer}, {"small.stl", "big.stl"});
  EXPECT_FALSE(r.nested);
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_TRUE(contains(r.errors[0], "'big.stl' is not inside 'small.stl'")) << r.errors[0];
  EXPECT_TRUE(contains(r.errors[0], "order is reversed")) << r.errors[0];
}

TEST(Nesting, SeparateSurfacesAreRejected) {
  const TriMesh a = icosphere(1.0, Eigen::Vector3d::Zero(), 2);
  const TriMesh b = icosphere(0.5, Eigen::Vector3d(3, 0, 0), 2);
  const NestingReport r = check_nesting({a, b}, {"a.obj", "b.obj"});
  EXPECT_FALSE(r.nested);
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_TRUE(contains(r.errors[0], "'b.obj' is not inside 'a.obj'")) << r.errors[0];
  EXPECT_TRUE(contains(r.errors[0], "outside each other")) << r.errors[0];
}

TEST(Nesting, CrossingPairIsRejectedNamingBoth) {
  const TriMesh a = icosphere(1.0, Eigen::Vector3d::Zero(), 2);
  const TriMesh b = icosphere(1.0, Eigen::Vector3d(1, 0, 0), 2);
  const NestingReport r = check_nesting({a, b}, {"left.off", "right.off"});
  EXPECT_FALSE(r.nested);
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_TRUE(contains(r.errors[0], "surfaces 'left.off' and 'right.off' intersect or touch")) << r.errors[0];
  EXPECT_TRUE(contains(r.errors[0], "pairs of faces meet, e.g. face")) << r.errors[0];
}

TEST(Nesting, TouchingSurfacesAreRejected) {
  // Inner sphere: the outer one shrunk by 1/2 towards its vertex 0, so the two
  // share that vertex exactly and are otherwise nested.
  const TriMesh outer = icosphere(1.0, Eigen::Vector3d::Zero(), 2);
  TriMesh inner = outer;
  const Eigen::RowVector3d p = outer.V.row(0);
  for (int i = 0; i < inner.V.rows(); ++i) inner.V.row(i) = p + 0.5 * (outer.V.row(i) - p);
  ASSERT_EQ(inner.V.row(0), p);
  const NestingReport r = check_nesting({outer, inner}, {"T1", "T2"});
  EXPECT_FALSE(r.nested);
  ASSERT_GE(r.errors.size(), 1u);
  EXPECT_TRUE(contains(r.errors[0], "surfaces 'T1' and 'T2' intersect or touch")) << r.errors[0];

  // Touching at a single point only: a small sphere moved until one of its
  // vertices lands exactly on a vertex of the outer sphere... from inside.
  TriMesh ball = icosphere(0.25, Eigen::Vector3d::Zero(), 1);
  // Vertex 0 of both icospheres points the same way; put the ball's vertex 0 on the outer's.
  const Eigen::RowVector3d shift = outer.V.row(0) - ball.V.row(0);
  for (int i = 0; i < ball.V.rows(); ++i) ball.V.row(i) += shift;
  const NestingReport point = check_nesting({outer, ball}, {"shell", "ball"});
  EXPECT_FALSE(point.nested);
  ASSERT_EQ(point.errors.size(), 1u);
  EXPECT_TRUE(contains(point.errors[0], "'shell' and 'ball' intersect or touch")) << point.errors[0];
}

TEST(Nesting, NonConsecutivePairsMustNotMeetEither) {
  const TriMesh t1 = icosphere(1.0, Eigen::Vector3d::Zero(), 2);
  const TriMesh t2 = icosphere(0.6, Eigen::Vector3d::Zero(), 2);
  const TriMesh t3 = icosphere(0.5, Eigen::Vector3d(0.6, 0, 0), 2);  // reaches x = 1.1: crosses T2 and T1
  const NestingReport r = check_nesting({t1, t2, t3}, {"T1", "T2", "T3"});
  EXPECT_FALSE(r.nested);
  std::string all;
  for (const auto& e : r.errors) all += e + "\n";
  EXPECT_TRUE(contains(all, "'T1' and 'T3' intersect or touch")) << all;
  EXPECT_TRUE(contains(all, "'T2' and 'T3' intersect or touch")) << all;
}

TEST(Nesting, OpenSurfaceAndBadArguments) {
  TriMesh open = icosphere(1.0, Eigen::Vector3d::Zero(), 1);
  open.F.conservativeResize(open.F.rows() - 1, 3);
  const NestingReport r = check_nesting({open, icosphere(0.5, Eigen::Vector3d::Zero(), 1)}, {"cup", "ball"});
  EXPECT_FALSE(r.nested);
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_TRUE(contains(r.errors[0], "'cup' is not a closed")) << r.errors[0];
  EXPECT_THROW(check_nesting({open}, {"a", "b"}), igaprep::Error);
}
