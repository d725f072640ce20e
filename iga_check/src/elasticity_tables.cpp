#include "elasticity_tables.h"

#include <map>

#include "igaprep/iga_check/elasticity_quadrature.h"

namespace igaprep::iga_check::detail {

std::vector<PatchTables> quadrature_tables(const spline::MultiPatch& mp, int extra_quadrature) {
  struct GaussRule {
    Eigen::VectorXd points, weights;
  };
  std::map<int, GaussRule> rules;  // by number of points, each computed once
  std::vector<PatchTables> tables(mp.patches.size());
  for (size_t p = 0; p < mp.patches.size(); ++p)
    for (int d = 0; d < 3; ++d) {
      const spline::Patch& pa = mp.patches[p];
      const int n = pa.degrees[d] + 1 + extra_quadrature;
      auto [it, added] = rules.try_emplace(n);
      if (added) gauss_legendre(n, it->second.points, it->second.weights);
      tables[p][d] = direction_elements(pa.knots[d], pa.degrees[d], it->second.points, it->second.weights);
    }
  return tables;
}

}  // namespace igaprep::iga_check::detail
