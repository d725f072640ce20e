#include "igaprep/spline/tnurcc_limit.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <memory>
#include <utility>
#include <opensubdiv/far/stencilTable.h>
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include "igaprep/core/error.h"

namespace igaprep::spline {
namespace {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

// The cage's topology and creases, refined around its irregular features.
std::unique_ptr<Far::TopologyRefiner> adaptive_refiner(const Cage& cage, int isolation_level) {
  std::vector<int> verts_per_face(cage.faces.size(), 4), corners;
  corners.reserve(4 * cage.faces.size());
  for (const auto& f : cage.faces) corners.insert(corners.end(), f.begin(), f.end());
  std::vector<int> crease_pairs;
  std::vector<float> crease_weights;
  for (const auto& e : cage.edges)
    if (e.sharpness > 0.0) {
      crease_pairs.insert(crease_pairs.end(), e.vertices.begin(), e.vertices.end());
      crease_weights.push_back(static_cast<float>(e.sharpness));
    }
  Far::TopologyDescriptor desc;
  desc.numVertices = static_cast<int>(cage.points.rows());
  desc.numFaces = static_cast<int>(cage.faces.size());
  desc.numVertsPerFace = verts_per_face.data();
  desc.vertIndicesPerFace = corners.data();
  desc.numCreases = static_cast<int>(crease_weights.size());
  desc.creaseVertexIndexPairs = crease_pairs.data();
  desc.creaseWeights = crease_weights.data();
  Sdc::Options sdc;
  sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(
      Factory::Create(desc, Factory::Options(Sdc::SCHEME_CATMARK, sdc)));
  if (!refiner) throw bad_input("T-NURCC limit: OpenSubdiv refused the cage's topology");
  Far::TopologyRefiner::AdaptiveOptions adaptive(isolation_level);
  adaptive.useInfSharpPatch = true;
  refiner->RefineAdaptive(adaptive);
  return refiner;
}

// OpenSubdiv's stencils (rows of control indices and weights) as a
// row-major sparse matrix, filled in place: each row's entries sorted by
// column, as Eigen's compressed format wants.
StencilMatrix to_sparse(int rows, int cols, const std::vector<int>& sizes, const std::vector<int>& offsets,
                        const std::vector<int>& indices, const std::vector<double>& weights) {
  StencilMatrix m(rows, cols);
  long nnz = 0;
  for (int r = 0; r < rows; ++r) nnz += sizes[r];
  m.resizeNonZeros(nnz);
  std::vector<std::pair<int, double>> row;
  long at = 0;
  for (int r = 0; r < rows; ++r) {
    m.outerIndexPtr()[r] = static_cast<int>(at);
    row.clear();
    for (int k = 0; k < sizes[r]; ++k) row.emplace_back(indices[offsets[r] + k], weights[offsets[r] + k]);
    std::sort(row.begin(), row.end());
    for (const auto& [c, w] : row) {
      m.innerIndexPtr()[at] = c;
      m.valuePtr()[at] = w;
      ++at;
    }
  }
  m.outerIndexPtr()[rows] = static_cast<int>(at);
  return m;
}

}  // namespace

LimitStencils limit_stencils(const Cage& cage, const std::vector<LimitLocation>& at, const LimitOptions& options) {
  if (!uniform_intervals(cage, 1e-12))
    throw bad_input("T-NURCC limit: the cage's knot intervals differ; OpenSubdiv evaluates equal intervals only");
  for (const auto& l : at)
    if (l.face < 0 || l.face >= static_cast<int>(cage.faces.size()) || !(l.s >= 0 && l.s <= 1 && l.t >= 0 && l.t <= 1))
      throw bad_input("T-NURCC limit: location (face " + std::to_string(l.face) + ", " + std::to_string(l.s) + ", " +
                      std::to_string(l.t) + ") is outside the cage");
  const auto refiner = adaptive_refiner(cage, options.isolation_level);
  // Locations grouped per face, in the order given (one array per run of a face).
  std::vector<double> s(at.size()), t(at.size());
  using Factory = Far::LimitStencilTableFactoryReal<double>;
  Factory::LocationArrayVec arrays;
  for (size_t i = 0; i < at.size(); ++i) {
    s[i] = at[i].s;
    t[i] = at[i].t;
    if (arrays.empty() || arrays.back().ptexIdx != at[i].face) {
      Factory::LocationArray a;
      a.ptexIdx = at[i].face;
      a.numLocations = 0;
      a.s = &s[i];
      a.t = &t[i];
      arrays.push_back(a);
    }
    ++arrays.back().numLocations;
  }
  Factory::Options opts;
  opts.generate1stDerivatives = options.first_derivatives || options.second_derivatives;
  opts.generate2ndDerivatives = options.second_derivatives;
  std::unique_ptr<const Far::LimitStencilTableReal<double>> table(
      at.empty() ? nullptr : Factory::Create(*refiner, arrays, nullptr, nullptr, opts));
  const int rows = static_cast<int>(at.size()), cols = static_cast<int>(cage.points.rows());
  LimitStencils out;
  if (rows == 0) return out;
  // OpenSubdiv skips a location it finds no patch for; every one must be there.
  if (!table || table->GetNumStencils() != rows)
    throw internal_error("T-NURCC limit: OpenSubdiv gave " + std::to_string(table ? table->GetNumStencils() : 0) +
                         " stencils for " + std::to_string(rows) + " locations");
  const auto& sizes = table->GetSizes();
  const auto& offsets = table->GetOffsets();
  const auto& idx = table->GetControlIndices();
  out.value = to_sparse(rows, cols, sizes, offsets, idx, table->GetWeights());
  if (opts.generate1stDerivatives) {
    out.ds = to_sparse(rows, cols, sizes, offsets, idx, table->GetDuWeights());
    out.dt = to_sparse(rows, cols, sizes, offsets, idx, table->GetDvWeights());
  }
  if (options.second_derivatives) {
    out.dss = to_sparse(rows, cols, sizes, offsets, idx, table->GetDuuWeights());
    out.dst = to_sparse(rows, cols, sizes, offsets, idx, table->GetDuvWeights());
    out.dtt = to_sparse(rows, cols, sizes, offsets, idx, table->GetDvvWeights());
  }
  return out;
}

LimitOptions values_only(LimitOptions options) {
  options.first_derivatives = false;
  options.second_derivatives = false;
  return options;
}

LimitValues limit_values(const LimitStencils& st, const Eigen::MatrixXd& cage_points) {
  if (st.ds.rows() != st.value.rows())
    throw bad_input("T-NURCC limit: normals need the first derivatives' stencils (LimitOptions::first_derivatives)");
  LimitValues v;
  v.point = st.value * cage_points;
  const Eigen::MatrixXd du = st.ds * cage_points, dv = st.dt * cage_points;
  const bool second = st.dss.rows() == st.value.rows() && st.value.rows() > 0;
  Eigen::MatrixXd duu, duv, dvv;
  if (second) {
    duu = st.dss * cage_points;
    duv = st.dst * cage_points;
    dvv = st.dtt * cage_points;
    v.mean_curvature.resize(v.point.rows());
  }
  v.normal.resize(v.point.rows(), 3);
  for (int i = 0; i < v.point.rows(); ++i) {
    const Eigen::Vector3d a = du.row(i).transpose(), b = dv.row(i).transpose();
    const Eigen::Vector3d n = a.cross(b).normalized();
    v.normal.row(i) = n.transpose();
    if (!second) continue;
    // H = (E N - 2 F M + G L) / (2 (E G - F^2)), sign so that a sphere seen
    // with outward normals has H = +1/R.
    const double E = a.dot(a), F = a.dot(b), G = b.dot(b);
    const double L = n.dot(duu.row(i).transpose()), M = n.dot(duv.row(i).transpose()),
                 N = n.dot(dvv.row(i).transpose());
    v.mean_curvature[i] = -(E * N - 2 * F * M + G * L) / (2 * (E * G - F * F));
  }
  return v;
}

std::vector<LimitLocation> face_grid(const Cage& cage, int n, bool include_ends) {
  std::vector<LimitLocation> out;
  out.reserve(cage.faces.size() * n * n);
  for (int f = 0; f < static_cast<int>(cage.faces.size()); ++f)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double s = include_ends ? (n > 1 ? double(i) / (n - 1) : 0.5) : (i + 0.5) / n;
        const double t = include_ends ? (n > 1 ? double(j) / (n - 1) : 0.5) : (j + 0.5) / n;
        out.push_back({f, s, t});
      }
  return out;
}

LimitLocation edge_location(int face, int k, double a) {
  switch (k) {
    case 0: return {face, a, 0.0};
    case 1: return {face, 1.0, a};
    case 2: return {face, 1.0 - a, 1.0};
    default: return {face, 0.0, 1.0 - a};
  }
}

}  // namespace igaprep::spline
