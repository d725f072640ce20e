#include "igaprep/core/parallel.h"

#include <exception>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace igaprep {

void parallel_for(std::size_t n, const std::function<void(std::size_t)>& work) {
  std::vector<std::exception_ptr> failed(n);
  const auto count = static_cast<long long>(n);
#pragma omp parallel for schedule(dynamic)
  for (long long i = 0; i < count; ++i) {
    try {
      work(static_cast<std::size_t>(i));
    } catch (...) {
      failed[static_cast<std::size_t>(i)] = std::current_exception();
    }
  }
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

void set_thread_count(int threads) {
#ifdef _OPENMP
  omp_set_num_threads(threads > 0 ? threads : omp_get_num_procs());
#else
  (void)threads;
#endif
}

}  // namespace igaprep
