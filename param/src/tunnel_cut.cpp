// The cuts tunnel loops give (tunnel_loops.h, tunnel_loop_cuts).
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "igaprep/core/edge_key.h"
#include "igaprep/core/error.h"
#include "igaprep/param/tunnel_loops.h"
#include "cut_smoothing.h"
#include "face_graph.h"

namespace igaprep::param {
namespace {

// Neighbour weights as for the thin sides: the rim prefers sharp edges.
constexpr double kSharpness = 0.3;
// At most this many sign choices are tried (2^6: genus 7).
constexpr int kMaxSignChoices = 64;
// Plate pairs up to this many times their median distance apart pull the
// two sides of a thin part apart (as for the thin sides).
constexpr double kThinFactor = 2.0;

// The faces beside each loop: +1 on its left (the face that runs a -> b for
// consecutive loop vertices a, b), -1 on its right, 0 elsewhere; one column
// per loop.
Eigen::MatrixXi loop_sides(const mesh::TriMesh& m, const std::vector<std::vector<int>>& loops) {
  std::unordered_map<std::uint64_t, int> face_of;
  for (int f = 0; f < static_cast<int>(m.F.rows()); ++f)
    for (int k = 0; k < 3; ++k)
      face_of[(static_cast<std::uint64_t>(m.F(f, k)) << 32) | static_cast<std::uint32_t>(m.F(f, (k + 1) % 3))] = f;
  Eigen::MatrixXi side = Eigen::MatrixXi::Zero(m.F.rows(), static_cast<Eigen::Index>(loops.size()));
  auto face = [&](int a, int b) {
    const auto it = face_of.find((static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b));
    if (it == face_of.end()) throw internal_error("tunnel cut: a loop edge is no edge of T1");
    return it->second;
  };
  for (std::size_t l = 0; l < loops.size(); ++l)
    for (std::size_t k = 0; k < loops[l].size(); ++k) {
      const int a = loops[l][k], b = loops[l][(k + 1) % loops[l].size()];
      side(face(a, b), static_cast<Eigen::Index>(l)) = 1;
      side(face(b, a), static_cast<Eigen::Index>(l)) = -1;
    }
  return side;
}

// T1's faces as a graph with the loops' sides: what every field shares.
struct CutSurface {
  detail::FaceGeometry geometry;
  std::vector<detail::FaceEdge> edges;
  Eigen::MatrixXi sides;  // loop_sides
  std::unordered_set<std::uint64_t> loop_edges;
};

CutSurface cut_surface(const mesh::TriMesh& m, const std::vector<std::vector<int>>& loops) {
  CutSurface s{detail::face_geometry(m), detail::face_neighbours(m), loop_sides(m, loops), {}};
  for (const auto& loop : loops)
    for (std::size_t k = 0; k < loop.size(); ++k) s.loop_edges.insert(edge_key(loop[k], loop[(k + 1) % loop.size()]));
  return s;
}

// The face field with given values beside the loops: harmonic on T1 cut
// along them (no coupling across a loop edge) and, with plate pairs, the
// thin sides' pull of each pair to opposite values. One factorisation, then
// one solve per choice of signs.
class SideField {
 public:
  SideField(const CutSurface& surface, const std::vector<detail::PlatePair>& pairs, double max_distance)
      : sides_(surface.sides) {
    const detail::FaceGeometry& geometry = surface.geometry;
    const Eigen::Index nf = sides_.rows();
    free_.assign(static_cast<std::size_t>(nf), -1);
    int nfree = 0;
    for (Eigen::Index f = 0; f < nf; ++f)
      if (sides_.row(f).isZero()) free_[static_cast<std::size_t>(f)] = nfree++;
    std::vector<Eigen::Triplet<double>> a, b;
    for (const detail::FaceEdge& e : surface.edges) {
      if (surface.loop_edges.count(edge_key(e.u, e.v))) continue;
      const double w = detail::neighbour_weight(geometry, e, kSharpness) + 1e-12;
      for (const auto& [p, q] : {std::pair{e.a, e.b}, std::pair{e.b, e.a}}) {
        const int i = free_[static_cast<std::size_t>(p)], j = free_[static_cast<std::size_t>(q)];
        if (i < 0) continue;
        a.emplace_back(i, i, w);
        if (j >= 0) a.emplace_back(i, j, -w);
        else b.emplace_back(i, q, w);
      }
    }
    for (const detail::PlatePair& p : pairs) {
      if (p.distance > max_distance) continue;
      const double w = geometry.area(p.face) / (p.distance * p.distance);
      for (const auto& [f, g] : {std::pair{p.face, p.opposite}, std::pair{p.opposite, p.face}}) {
        const int i = free_[static_cast<std::size_t>(f)], j = free_[static_cast<std::size_t>(g)];
        if (i < 0) continue;
        a.emplace_back(i, i, w);
        if (j >= 0) a.emplace_back(i, j, w);
        else b.emplace_back(i, g, -w);
      }
    }
    Eigen::SparseMatrix<double> A(nfree, nfree);
    A.setFromTriplets(a.begin(), a.end());
    coupling_.resize(nfree, nf);
    coupling_.setFromTriplets(b.begin(), b.end());
    solver_.compute(A);
    if (solver_.info() != Eigen::Success) throw internal_error("tunnel cut: the side field's matrix is singular");
  }

  // signs(l) is the value on loop l's left, minus it on its right.
  Eigen::VectorXd solve(const Eigen::VectorXi& signs) const {
    const Eigen::VectorXd fixed = (sides_ * signs).cast<double>();
    const Eigen::VectorXd inner = solver_.solve(coupling_ * fixed);
    Eigen::VectorXd x = fixed;
    for (std::size_t f = 0; f < free_.size(); ++f)
      if (free_[f] >= 0) x(static_cast<Eigen::Index>(f)) = inner(free_[f]);
    return x;
  }

 private:
  const Eigen::MatrixXi& sides_;
  std::vector<int> free_;
  Eigen::SparseMatrix<double> coupling_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver_;
};

std::string describe(const std::vector<std::vector<int>>& loops, const Eigen::VectorXi& signs, bool thin) {
  std::string s = "tunnel loops (" + std::to_string(loops.size()) + " of";
  for (std::size_t l = 0; l < loops.size(); ++l) s += (l ? ", " : " ") + std::to_string(loops[l].size());
  s += " edges; sides ";
  for (Eigen::Index l = 0; l < signs.size(); ++l) s += signs(l) > 0 ? '+' : '-';
  return s + (thin ? "; the thin parts' two sides)" : ")");
}

}  // namespace

std::vector<CutLoops> tunnel_loop_cuts(const mesh::TriMesh& T1, const std::vector<std::vector<int>>& loops,
                                       const std::string& name, std::vector<std::string>& refusals) {
  if (loops.empty()) throw internal_error("tunnel cut: no loops");
  const CutSurface surface = cut_surface(T1, loops);
  const std::vector<detail::PlatePair> pairs = detail::plate_pairs(T1, surface.geometry);
  const double max_distance = pairs.empty() ? 0.0 : kThinFactor * detail::median_distance(pairs);
  const int choices = loops.size() > 7 ? kMaxSignChoices : std::min(1 << (loops.size() - 1), kMaxSignChoices);
  std::vector<CutLoops> valid;
  for (const bool thin : {false, true}) {
    if (thin && pairs.empty()) break;
    const SideField field(surface, thin ? pairs : std::vector<detail::PlatePair>{}, max_distance);
    for (int choice = 0; choice < choices; ++choice) {
      Eigen::VectorXi signs = Eigen::VectorXi::Ones(static_cast<Eigen::Index>(loops.size()));
      for (std::size_t l = 1; l < loops.size(); ++l)
        if (choice & (1 << (l - 1))) signs(static_cast<Eigen::Index>(l)) = -1;
      const std::string source = describe(loops, signs, thin);
      Eigen::VectorXd x = field.solve(signs);
      detail::give_small_pieces_away(surface.edges, surface.geometry.area, x);
      const Eigen::VectorXi face_side = x.unaryExpr([](double v) { return v < 0.0 ? -1 : 1; });
      try {
        CutLoops edges = validate_cut(T1, face_side, name, source);
        valid.push_back(detail::smoothed_cut(std::move(edges), name, source + ", smoothed"));
      } catch (const Error& e) {
        if (e.kind() != ErrorKind::BadInput) throw;
        refusals.push_back(source + ": " + e.what());
      }
    }
  }
  std::stable_sort(valid.begin(), valid.end(),
                   [](const CutLoops& a, const CutLoops& b) { return loops_length(a) < loops_length(b); });
  return valid;
}

}  // namespace igaprep::param
