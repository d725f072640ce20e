#pragma once
// Private to export/: numbers as text that reads back exactly (17 significant
// digits, "%.17g"), independent of the stream's locale and flags.
#include <cstdio>
#include <string>

namespace igaprep::exporter::detail {

inline std::string exact(double x) {
  char buf[40];
  std::snprintf(buf, sizeof(buf), "%.17g", x);
  return buf;
}

}  // namespace igaprep::exporter::detail
