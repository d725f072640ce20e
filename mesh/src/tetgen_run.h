#pragma once
// Private helper: runs TetGen 1.5 in a child process. TetGen's library mode
// reports errors by throwing an int after freeing its memory, and its own
// stack object then frees it again, which crashes (double free); some paths
// also call exit(). Isolating it in a fork turns every failure into an error
// with TetGen's own message instead of taking the caller down.
#include <string>
#include <vector>

class tetgenio;

namespace igaprep::mesh::detail {

struct TetgenOutput {
  std::vector<double> points;  // 3 per point
  std::vector<int> tets;       // 4 per tet, 0-based
  std::vector<int> neighbors;  // 4 per tet: neighbour opposite corner j, -1 on the hull
  long child_max_rss_kib = 0;  // peak memory of the TetGen process
};

// Inputs: `in` (0-based), TetGen switches (must include z and n), whether to
// copy TetGen's stdout to ours, `what` for messages.
// Throws bad_input with TetGen's last output lines when it fails or crashes.
TetgenOutput run_tetgen(tetgenio& in, const std::string& switches, bool echo, const std::string& what);

}  // namespace igaprep::mesh::detail
