#include "elasticity_stiffness.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "elasticity_basis.h"
#include "igaprep/core/error.h"
#include "igaprep/core/parallel.h"
#include "igaprep/core/progress.h"
#include "igaprep/iga_check/elasticity_element.h"

namespace igaprep::iga_check::detail {

namespace {

// The global control points of every element, patch by patch, elements u
// fastest (the order of the assembly loops).
std::vector<std::vector<int>> element_control_points(const spline::MultiPatch& mp,
                                                     const std::vector<PatchTables>& tables,
                                                     const spline::GlobalNumbering& num) {
  std::vector<std::vector<int>> element_cps;
  for (size_t p = 0; p < mp.patches.size(); ++p) {
    const spline::Patch& pa = mp.patches[p];
    for (const auto& ew : tables[p][2])
      for (const auto& ev : tables[p][1])
        for (const auto& eu : tables[p][0]) {
          std::vector<int> ids;
          ids.reserve((pa.degrees[0] + 1) * (pa.degrees[1] + 1) * (pa.degrees[2] + 1));
          for (int iw = 0; iw <= pa.degrees[2]; ++iw)
            for (int iv = 0; iv <= pa.degrees[1]; ++iv)
              for (int iu = 0; iu <= pa.degrees[0]; ++iu)
                ids.push_back(num.global[p][pa.index(eu.first + iu, ev.first + iv, ew.first + iw)]);
          element_cps.push_back(std::move(ids));
        }
  }
  return element_cps;
}

// The patch's elements in assembly order (u fastest): their spans per direction.
std::vector<std::array<const DirElement*, 3>> patch_elements(const PatchTables& t) {
  std::vector<std::array<const DirElement*, 3>> out;
  for (const auto& ew : t[2])
    for (const auto& ev : t[1])
      for (const auto& eu : t[0]) out.push_back({{&eu, &ev, &ew}});
  return out;
}

// The Jacobian determinant keeps the sign of the patch's first non-zero one.
void check_jacobian(const ElementValues& ev, int patch, double& sign) {
  for (Eigen::Index q = 0; q < ev.det.size(); ++q) {
    const double d = ev.det(q);
    if (sign == 0.0 && d != 0.0 && std::isfinite(d)) sign = d > 0 ? 1.0 : -1.0;
    if (!(d * sign > 0.0)) {
      std::ostringstream s;
      s << "patch " << patch << ": the Jacobian determinant vanishes or changes sign near x = ("
        << ev.x(q, 0) << ", " << ev.x(q, 1) << ", " << ev.x(q, 2)
        << "); the model is not valid for analysis (certify_model finds such elements)";
      throw bad_input(s.str());
    }
  }
}

// The element's share of K_fd u_d and u_d^T K_dd u_d, for an element with
// non-zero constrained values.
void add_lifting(const ElasticityDofs& dofs, const std::vector<int>& gid, const Eigen::MatrixXd& Ke,
                 StiffnessSystem& sys, Eigen::VectorXd& ue, Eigen::VectorXd& Ku_e) {
  const int n = static_cast<int>(gid.size());
  ue.setZero(3 * n);
  bool any = false;
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < 3; ++i) {
      const double v = dofs.values(3 * gid[a] + i);
      if (v != 0.0) {
        ue(i * n + a) = v;
        any = true;
      }
    }
  if (!any) return;
  Ku_e.noalias() = Ke * ue;
  sys.constrained_energy += ue.dot(Ku_e);
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < 3; ++i) {
      const int r = dofs.equation[3 * gid[a] + i];
      if (r >= 0) sys.lifting(r) += Ku_e(i * n + a);
    }
}

}  // namespace

StiffnessSystem assemble_stiffness(const spline::MultiPatch& mp, const std::vector<PatchTables>& tables,
                                   const ElasticityDofs& dofs, const std::vector<LameParameters>& lame,
                                   ElasticityReport& report, const ProgressCallback& progress_callback) {
  const std::vector<std::vector<int>> element_cps = element_control_points(mp, tables, dofs.numbering);
  report.elements = static_cast<long long>(element_cps.size());
  StiffnessPattern P = build_stiffness_pattern(element_cps, dofs.numbering.count, dofs.equation);
  report.nonzeros = P.K.nonZeros();
  StiffnessSystem sys;
  sys.lifting = Eigen::VectorXd::Zero(dofs.unknowns);
  const bool has_prescribed = dofs.prescribed > 0;
  Progress progress("assembling stiffness", element_cps.size(), progress_callback);
  // Element matrices of a chunk on all cores (parallel_for), then checked and
  // added in element order: the matrix is the same bit for bit on any number
  // of threads, and a chunk's matrices stay small (32 x 295 KB at degree 3).
  constexpr std::size_t kChunk = 32;
  std::vector<ElementValues> ev(kChunk);
  std::vector<Eigen::MatrixXd> Ke(kChunk);
  Eigen::VectorXd ue, Ku_e;
  size_t e = 0;
  for (size_t p = 0; p < mp.patches.size(); ++p) {
    const spline::Patch& pa = mp.patches[p];
    const LameParameters& lm = lame[pa.material];
    const std::vector<std::array<const DirElement*, 3>> elements = patch_elements(tables[p]);
    double sign = 0.0;
    for (std::size_t start = 0; start < elements.size(); start += kChunk) {
      const std::size_t n = std::min(kChunk, elements.size() - start);
      parallel_for(n, [&](std::size_t i) {
        const auto& el = elements[start + i];
        element_values(pa, *el[0], *el[1], *el[2], true, ev[i]);
        Eigen::MatrixXd work;
        element_stiffness(ev[i].grad, ev[i].w.cwiseProduct(ev[i].det.cwiseAbs()), lm, Ke[i], work);
      });
      for (std::size_t i = 0; i < n; ++i) {
        check_jacobian(ev[i], static_cast<int>(p), sign);
        report.quadrature_points += ev[i].w.size();
        scatter(P, element_cps[e], Ke[i]);
        if (has_prescribed) add_lifting(dofs, element_cps[e], Ke[i], sys, ue, Ku_e);
        progress.update(++e);
      }
    }
  }
  progress.finish();
  sys.matrix = std::move(P.K);
  return sys;
}

}  // namespace igaprep::iga_check::detail
