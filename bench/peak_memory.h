#pragma once
// Peak resident set size of this process so far (VmHWM in /proc/self/status).
#include <cstdlib>
#include <fstream>
#include <string>

inline long peak_memory_kib() {
  std::ifstream f("/proc/self/status");
  std::string line;
  while (std::getline(f, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::atol(line.c_str() + 6);
  return -1;
}
