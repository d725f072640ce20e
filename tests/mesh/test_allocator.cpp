// core's keep_freed_memory_for_reuse (called by every test runner at start,
// tests/support/allocator_setup.cpp): a 10 MB block comes from the heap,
// not from its own mapping, and freeing it does not give the heap back.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "igaprep/core/allocator.h"

#if defined(__GLIBC__)
TEST(Allocator, LargeFreedBlocksStayInTheHeap) {
  igaprep::keep_freed_memory_for_reuse();
  const std::size_t size = 10u << 20;
  const struct mallinfo2 before = mallinfo2();
  void* block = std::malloc(size);
  ASSERT_NE(block, nullptr);
  std::memset(block, 1, size);
  const struct mallinfo2 during = mallinfo2();
  EXPECT_EQ(during.hblks, before.hblks) << "the block has its own mapping (glibc's default above 128 kB)";
  std::free(block);
  const struct mallinfo2 after = mallinfo2();
  EXPECT_GE(after.arena, during.arena) << "the heap was trimmed on free";
}
#endif
