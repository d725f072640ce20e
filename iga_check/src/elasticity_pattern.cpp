#include "elasticity_pattern.h"

#include <algorithm>

#include "igaprep/core/error.h"

namespace igaprep::iga_check::detail {

namespace {

// Per column block c: the sorted blocks r >= c of control points that share an element with c.
void block_rows(const std::vector<std::vector<int>>& element_cps, int ncp, StiffnessPattern& P) {
  // control point -> elements
  std::vector<long long> inc_start(ncp + 1, 0);
  for (const auto& e : element_cps)
    for (int g : e) ++inc_start[g + 1];
  for (int g = 0; g < ncp; ++g) inc_start[g + 1] += inc_start[g];
  std::vector<int> inc(inc_start[ncp]);
  {
    std::vector<long long> fill(inc_start.begin(), inc_start.end() - 1);
    for (size_t e = 0; e < element_cps.size(); ++e)
      for (int g : element_cps[e]) inc[fill[g]++] = static_cast<int>(e);
  }
  std::vector<int> marker(ncp, -1);
  P.blk_start.assign(ncp + 1, 0);
  P.blk_rows.clear();
  std::vector<int> rows;
  for (int c = 0; c < ncp; ++c) {
    rows.clear();
    for (long long k = inc_start[c]; k < inc_start[c + 1]; ++k)
      for (int r : element_cps[inc[k]])
        if (r >= c && marker[r] != c) {
          marker[r] = c;
          rows.push_back(r);
        }
    std::sort(rows.begin(), rows.end());
    P.blk_rows.insert(P.blk_rows.end(), rows.begin(), rows.end());
    P.blk_start[c + 1] = static_cast<long long>(P.blk_rows.size());
  }
}

// The scalar layout: free components per control point and, per column, the
// start of its rows (compressed column offsets, n + 1 of them).
std::vector<int> column_starts(int ncp, int n, StiffnessPattern& P) {
  P.free_before.assign(3 * ncp, 0);
  P.free_count.assign(ncp, 0);
  for (int g = 0; g < ncp; ++g)
    for (int i = 0; i < 3; ++i) {
      P.free_before[3 * g + i] = P.free_count[g];
      if (P.eq[3 * g + i] >= 0) ++P.free_count[g];
    }
  P.blk_cum.assign(P.blk_rows.size(), 0);
  std::vector<int> outer(n + 1, 0);
  for (int c = 0; c < ncp; ++c) {
    long long cum = 0;
    for (long long k = P.blk_start[c] + 1; k < P.blk_start[c + 1]; ++k) {
      P.blk_cum[k] = cum;
      cum += P.free_count[P.blk_rows[k]];
    }
    for (int j = 0; j < 3; ++j) {
      const int col = P.eq[3 * c + j];
      if (col < 0) continue;
      int diag = 0;
      for (int i = j; i < 3; ++i) diag += P.eq[3 * c + i] >= 0;
      outer[col + 1] = static_cast<int>(diag + cum);
    }
  }
  for (int j = 0; j < n; ++j) {
    if (static_cast<long long>(outer[j]) + outer[j + 1] > 2147483647LL)
      throw bad_input("the stiffness matrix has more than 2^31 non-zeros; refine less");
    outer[j + 1] += outer[j];
  }
  return outer;
}

// P.K with the row indices of every column and zero values.
void fill_pattern(int ncp, int n, const std::vector<int>& outer, StiffnessPattern& P) {
  P.K = SparseMatrix(n, n);
  P.K.resizeNonZeros(outer[n]);
  std::copy(outer.begin(), outer.end(), P.K.outerIndexPtr());
  int* inner = P.K.innerIndexPtr();
  std::fill(P.K.valuePtr(), P.K.valuePtr() + outer[n], 0.0);
  for (int c = 0; c < ncp; ++c)
    for (int j = 0; j < 3; ++j) {
      const int col = P.eq[3 * c + j];
      if (col < 0) continue;
      int pos = outer[col];
      for (long long k = P.blk_start[c]; k < P.blk_start[c + 1]; ++k) {
        const int r = P.blk_rows[k];
        for (int i = (r == c ? j : 0); i < 3; ++i)
          if (P.eq[3 * r + i] >= 0) inner[pos++] = P.eq[3 * r + i];
      }
    }
}

}  // namespace

StiffnessPattern build_stiffness_pattern(const std::vector<std::vector<int>>& element_cps, int ncp,
                                         const std::vector<int>& equation) {
  StiffnessPattern P;
  P.eq = equation;
  block_rows(element_cps, ncp, P);
  const int n = *std::max_element(P.eq.begin(), P.eq.end()) + 1;
  const std::vector<int> outer = column_starts(ncp, n, P);
  fill_pattern(ncp, n, outer, P);
  return P;
}

void scatter(StiffnessPattern& P, const std::vector<int>& gid, const Eigen::MatrixXd& Ke) {
  const int n = static_cast<int>(gid.size());
  double* val = P.K.valuePtr();
  const int* outer = P.K.outerIndexPtr();
  for (int b = 0; b < n; ++b) {
    const int gb = gid[b];
    const int* first = P.blk_rows.data() + P.blk_start[gb];
    const int* last = P.blk_rows.data() + P.blk_start[gb + 1];
    for (int a = 0; a < n; ++a) {
      const int ga = gid[a];
      if (ga < gb) continue;
      const long long k = std::lower_bound(first, last, ga) - P.blk_rows.data();
      for (int j = 0; j < 3; ++j) {
        const int col = P.eq[3 * gb + j];
        if (col < 0) continue;
        const long long base = outer[col];
        if (ga == gb) {
          int off = 0;
          for (int i = j; i < 3; ++i) {
            if (P.eq[3 * ga + i] < 0) continue;
            val[base + off++] += Ke(i * n + a, j * n + b);
          }
        } else {
          int diag = 0;
          for (int i = j; i < 3; ++i) diag += P.eq[3 * gb + i] >= 0;
          const long long row0 = base + diag + P.blk_cum[k];
          for (int i = 0; i < 3; ++i) {
            if (P.eq[3 * ga + i] < 0) continue;
            val[row0 + P.free_before[3 * ga + i]] += Ke(i * n + a, j * n + b);
          }
        }
      }
    }
  }
}

}  // namespace igaprep::iga_check::detail
