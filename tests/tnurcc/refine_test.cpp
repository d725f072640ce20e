// The hand-written refinement against OpenSubdiv: the same refined cage,
// the same limit surface, the opposite-edge rule kept.
#include <gtest/gtest.h>

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>
#include <random>

#include "igaprep/spline/tnurcc_limit.h"
#include "igaprep/spline/tnurcc_refine.h"
#include "tnurcc/tnurcc_models.h"

namespace {

using namespace igaprep::spline;
namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

struct Point {
  double x[3];
  void Clear() { x[0] = x[1] = x[2] = 0.0; }
  void AddWithWeight(const Point& p, double w) {
    for (int d = 0; d < 3; ++d) x[d] += w * p.x[d];
  }
};

// OpenSubdiv's uniform refinement of the cage by one level, the child
// points ordered as refine_cage orders them (face, edge, vertex points).
Eigen::MatrixXd opensubdiv_refined(const Cage& c) {
  std::vector<int> counts(c.faces.size(), 4), corners, pairs;
  std::vector<float> weights;
  for (const auto& f : c.faces) corners.insert(corners.end(), f.begin(), f.end());
  for (const auto& e : c.edges)
    if (e.sharpness > 0) {
      pairs.insert(pairs.end(), e.vertices.begin(), e.vertices.end());
      weights.push_back(float(e.sharpness));
    }
  Far::TopologyDescriptor d;
  d.numVertices = int(c.points.rows());
  d.numFaces = int(c.faces.size());
  d.numVertsPerFace = counts.data();
  d.vertIndicesPerFace = corners.data();
  d.numCreases = int(weights.size());
  d.creaseVertexIndexPairs = pairs.data();
  d.creaseWeights = weights.data();
  Sdc::Options o;
  o.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> r(Factory::Create(d, Factory::Options(Sdc::SCHEME_CATMARK, o)));
  r->RefineUniform(Far::TopologyRefiner::UniformOptions(1));
  std::vector<Point> src(c.points.rows()), dst(r->GetLevel(1).GetNumVertices());
  for (int v = 0; v < c.points.rows(); ++v)
    for (int k = 0; k < 3; ++k) src[v].x[k] = c.points(v, k);
  Point* from = src.data();
  Point* to = dst.data();
  Far::PrimvarRefinerReal<double>(*r).Interpolate(1, from, to);
  const Far::TopologyLevel& l0 = r->GetLevel(0);
  const int nf = int(c.faces.size()), ne = int(c.edges.size());
  Eigen::MatrixXd out(nf + ne + c.points.rows(), 3);
  auto put = [&](int row, int child) { out.row(row) << dst[child].x[0], dst[child].x[1], dst[child].x[2]; };
  for (int f = 0; f < nf; ++f) put(f, l0.GetFaceChildVertex(f));
  for (int e = 0; e < ne; ++e) put(nf + e, l0.GetEdgeChildVertex(l0.FindEdge(c.edges[e].vertices[0], c.edges[e].vertices[1])));
  for (int v = 0; v < c.points.rows(); ++v) put(nf + ne + v, l0.GetVertexChildVertex(v));
  return out;
}

// An open grid (a border with corners), a box with creases, a smooth box.
std::vector<Cage> cages() {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> h(-0.3, 0.3);
  Cage grid;
  const int n = 6;
  grid.points.resize(n * n, 3);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) grid.points.row(i + n * j) << i, j, h(rng);
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) grid.faces.push_back({{i + n * j, i + 1 + n * j, i + 1 + n * (j + 1), i + n * (j + 1)}});
  build_cage_edges(grid);
  CageOptions smooth;
  smooth.crease_angle = 180.0;
  Cage box = surface_cage(tnurcc_test::boxes(2, 2), 0);
  for (int v = 0; v < box.points.rows(); ++v) box.points.row(v) += 0.05 * Eigen::RowVector3d(h(rng), h(rng), h(rng));
  return {grid, box, surface_cage(tnurcc_test::boxes(1, 2), 0, smooth)};
}

TEST(TnurccRefine, RefinedCageIsOpenSubdivs) {
  for (const Cage& c : cages()) {
    const Cage r = refine_cage(c);
    EXPECT_EQ(r.faces.size(), 4 * c.faces.size());
    EXPECT_LT((r.points - opensubdiv_refined(c)).cwiseAbs().maxCoeff(), 1e-14);
    EXPECT_TRUE(opposite_edge_violations(r).empty());
    EXPECT_DOUBLE_EQ(r.edges[0].interval, c.edges[0].interval / 2);
    long creases = 0, parent_creases = 0;
    for (const auto& e : r.edges) creases += e.sharpness > 0;
    for (const auto& e : c.edges) parent_creases += e.sharpness > 0;
    EXPECT_EQ(creases, 2 * parent_creases);
  }
}

TEST(TnurccRefine, LimitSurfaceIsUnchanged) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const Cage& c : cages()) {
    const Cage r = refine_cage(c);
    std::vector<LimitLocation> parent, child;
    for (int f = 0; f < int(c.faces.size()); ++f)
      for (int k = 0; k < 4; ++k) {
        const double a = unit(rng), b = unit(rng);
        child.push_back({4 * f + k, a, b});
        const double s[4] = {a / 2, 1 - b / 2, 1 - a / 2, b / 2}, t[4] = {b / 2, a / 2, 1 - b / 2, 1 - a / 2};
        parent.push_back({f, s[k], t[k]});
      }
    // The child isolated one level less: the same patches, Gregory end caps included.
    LimitOptions po, co;
    co.isolation_level = po.isolation_level - 1;
    const Eigen::MatrixXd X = limit_stencils(c, parent, po).value * c.points;
    const Eigen::MatrixXd Y = limit_stencils(r, child, co).value * r.points;
    EXPECT_LT((X - Y).cwiseAbs().maxCoeff(), 1e-12);
  }
}

TEST(TnurccRefine, RefusesWhatItCannotRefine) {
  Cage c = cages()[0];
  c.edges[0].interval = 2.0;
  EXPECT_THROW(refine_cage(c), igaprep::Error);
  c = cages()[0];
  c.edges[3].sharpness = 2.0;
  EXPECT_THROW(refine_cage(c), igaprep::Error);
}

}  // namespace

namespace {

TEST(TnurccRefine, LimitPositionMasksAreOpenSubdivsLimitPoints) {
  for (const Cage& c : cages()) {
    const Eigen::MatrixXd masks = limit_positions(c);
    // Each vertex at a corner of one of its faces.
    std::vector<LimitLocation> at(c.points.rows());
    std::vector<bool> seen(c.points.rows(), false);
    const double s[4] = {0, 1, 1, 0}, t[4] = {0, 0, 1, 1};
    for (int f = 0; f < int(c.faces.size()); ++f)
      for (int k = 0; k < 4; ++k)
        if (!seen[c.faces[f][k]]) {
          seen[c.faces[f][k]] = true;
          at[c.faces[f][k]] = {f, s[k], t[k]};
        }
    const Eigen::MatrixXd X = limit_stencils(c, at).value * c.points;
    EXPECT_LT((X - masks).cwiseAbs().maxCoeff(), 1e-12);
  }
}

}  // namespace
