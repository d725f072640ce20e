// Linked into every test runner: the allocator setting the CLI makes at start
// (core/allocator.h), so that the library tests run as the CLI does.
#include "igaprep/core/allocator.h"

namespace {
const bool kAllocatorSet = (igaprep::keep_freed_memory_for_reuse(), true);
}  // namespace
