#include "elasticity_tables.h"

namespace igaprep::iga_check::detail {

std::vector<PatchTables> quadrature_tables(const spline::MultiPatch& mp, int extra_quadrature) {
  std::vector<PatchTables> tables(mp.patches.size());
  for (size_t p = 0; p < mp.patches.size(); ++p) tables[p] = patch_elements(mp.patches[p], extra_quadrature);
  return tables;
}

}  // namespace igaprep::iga_check::detail
