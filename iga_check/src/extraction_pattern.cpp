#include "extraction_pattern.h"

#include <algorithm>

namespace igaprep::iga_check::detail {

BlockLowerMatrix::BlockLowerMatrix(const spline::ExtractionModel& m) : lower_(static_cast<std::size_t>(m.function_count())) {
  for (const spline::ExtractionElement& e : m.elements)
    for (const int g : e.functions)
      for (const int f : e.functions)
        if (f >= g) lower_[static_cast<std::size_t>(g)].push_back(f);
  for (std::vector<int>& l : lower_) {
    std::sort(l.begin(), l.end());
    l.erase(std::unique(l.begin(), l.end()), l.end());
  }
  // Column 3 g + j: the diagonal block's rows 3 g + j .. 3 g + 2, then three rows per block f > g.
  const Eigen::Index n = 3 * m.function_count();
  std::vector<int> outer(static_cast<std::size_t>(n) + 1, 0), inner;
  for (std::size_t g = 0; g < lower_.size(); ++g)
    for (int j = 0; j < 3; ++j) {
      for (const int f : lower_[g])
        for (int i = f == static_cast<int>(g) ? j : 0; i < 3; ++i) inner.push_back(3 * f + i);
      outer[3 * g + static_cast<std::size_t>(j) + 1] = static_cast<int>(inner.size());
    }
  K_.resize(n, n);
  K_.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
  std::copy(outer.begin(), outer.end(), K_.outerIndexPtr());
  std::copy(inner.begin(), inner.end(), K_.innerIndexPtr());
  std::fill(K_.valuePtr(), K_.valuePtr() + inner.size(), 0.0);
}

void BlockLowerMatrix::add(const std::vector<int>& functions, const Eigen::MatrixXd& Ke) {
  double* values = K_.valuePtr();
  const int* outer = K_.outerIndexPtr();
  for (std::size_t b = 0; b < functions.size(); ++b) {
    const int g = functions[b];
    const std::vector<int>& l = lower_[static_cast<std::size_t>(g)];
    for (std::size_t a = 0; a < functions.size(); ++a) {
      const int f = functions[a];
      if (f < g) continue;
      const int k = static_cast<int>(std::lower_bound(l.begin(), l.end(), f) - l.begin());
      for (int j = 0; j < 3; ++j) {
        const int first = outer[3 * g + j] + (k == 0 ? 0 : (3 - j) + 3 * (k - 1));
        for (int i = f == g ? j : 0; i < 3; ++i)
          values[first + i - (f == g ? j : 0)] += Ke(3 * static_cast<Eigen::Index>(a) + i, 3 * static_cast<Eigen::Index>(b) + j);
      }
    }
  }
}

}  // namespace igaprep::iga_check::detail
