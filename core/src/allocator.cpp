#include "igaprep/core/allocator.h"

#include <cstdlib>  // defines __GLIBC__ on glibc (features.h); tested before it was, the body compiled to nothing

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace igaprep {

void keep_freed_memory_for_reuse() {
#if defined(__GLIBC__)
  // 32 MB is the largest mmap threshold glibc accepts on 64-bit systems.
  mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);
  mallopt(M_TRIM_THRESHOLD, 256 * 1024 * 1024);
#endif
}

}  // namespace igaprep
