#pragma once
// Independent work items on the machine's cores (OpenMP when the build has
// it, else one after the other). Each item writes only its own results, so
// the outcome does not depend on the number of threads.
#include <cstddef>
#include <functional>

namespace igaprep {

// Calls work(i) for i in [0, n), in any order and on any thread. When items
// throw, the exception of the lowest such i is rethrown after all have run.
void parallel_for(std::size_t n, const std::function<void(std::size_t)>& work);

// Threads parallel_for uses from now on (0: the OpenMP default, all cores).
void set_thread_count(int threads);

}  // namespace igaprep
