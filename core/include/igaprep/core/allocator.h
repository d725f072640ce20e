#pragma once
// How the process's allocator treats large freed blocks. glibc hands blocks
// over 128 kB back to the system when they are freed (mmap) and trims the
// heap's top, so a loop that allocates and frees a few MB per step (a layer
// of elements' grid evaluation, a trial step of the Jacobian repair)
// page-faults its memory in anew every time: on ring2 that was 3 of the
// check's 8 s, all of it system time.

namespace igaprep {

// Keeps freed blocks up to 32 MB in the heap and lets up to 256 MB of free
// heap stay with the process. For executables (the CLI, the test runners) to
// call once at start; library code never changes process-wide settings.
void keep_freed_memory_for_reuse();

}  // namespace igaprep
