#pragma once
// printf-style formatting into a string (summary lines and messages).
#include <Eigen/Core>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <string>

namespace igaprep {

__attribute__((format(printf, 1, 2))) inline std::string text(const char* format, ...) {
  va_list args;
  va_start(args, format);
  va_list copy;
  va_copy(copy, args);
  const int n = std::vsnprintf(nullptr, 0, format, copy);
  va_end(copy);
  std::string out(n > 0 ? static_cast<std::size_t>(n) : 0, '\0');
  if (n > 0) std::vsnprintf(out.data(), out.size() + 1, format, args);
  va_end(args);
  return out;
}

// A point for messages: "(x y z)", 4 significant digits each.
inline std::string point_text(const Eigen::Vector3d& x) { return text("(%.4g %.4g %.4g)", x[0], x[1], x[2]); }

// The same with the round-off of a computed point shown as 0: components
// below 1e-9 of `scale` (the model's size, 1 for a unit vector).
inline std::string point_text(const Eigen::Vector3d& x, double scale) {
  Eigen::Vector3d y = x;
  for (int k = 0; k < 3; ++k)
    if (std::abs(y[k]) < 1e-9 * scale) y[k] = 0.0;  // -0 too
  return point_text(y);
}

// The first byte of `s` that is not well-formed UTF-8 text (a bad or overlong
// sequence, a surrogate, or a control character other than tab, newline and
// carriage return, which XML 1.0 cannot hold); npos when there is none.
inline std::size_t invalid_text_at(const std::string& s) {
  std::size_t i = 0;
  while (i < s.size()) {
    const auto b = static_cast<unsigned char>(s[i]);
    if (b < 0x80) {
      if (b < 0x20 && b != '\t' && b != '\n' && b != '\r') return i;
      ++i;
      continue;
    }
    const int n = b >= 0xF0 && b <= 0xF4 ? 3 : b >= 0xE0 ? (b <= 0xEF ? 2 : -1) : b >= 0xC2 ? 1 : -1;
    if (n < 0) return i;
    unsigned cp = b & (0x3F >> n);
    for (int k = 1; k <= n; ++k) {
      if (i + static_cast<std::size_t>(k) >= s.size()) return i;
      const auto c = static_cast<unsigned char>(s[i + static_cast<std::size_t>(k)]);
      if ((c & 0xC0) != 0x80) return i;
      cp = (cp << 6) | (c & 0x3F);
    }
    const unsigned lowest[4] = {0, 0x80, 0x800, 0x10000};
    if (cp < lowest[n] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return i;
    i += static_cast<std::size_t>(n) + 1;
  }
  return std::string::npos;
}

}  // namespace igaprep
