#pragma once
// Small checks shared by the parsers of case-file sections: unknown keys and
// numbers in range, each failing with bad_input naming the file and the key.
#include <algorithm>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "igaprep/core/error.h"

namespace igaprep::cli {

[[noreturn]] inline void case_fail(const std::string& file, const std::string& message) {
  throw bad_input(file + ": " + message);
}

inline void refuse_unknown_keys(const nlohmann::json& object, const std::vector<std::string>& known,
                                const std::string& where, const std::string& file) {
  for (auto it = object.begin(); it != object.end(); ++it) {
    if (std::find(known.begin(), known.end(), it.key()) != known.end()) continue;
    std::string list;
    for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
    case_fail(file, "unknown key '" + where + "." + it.key() + "' (known here: " + list + ")");
  }
}

// section[key] as a number in [lo, hi] (or the fallback when absent).
inline double case_number(const nlohmann::json& section, const std::string& key, double fallback, double lo,
                          double hi, const std::string& where, const std::string& file) {
  if (!section.contains(key)) return fallback;
  const nlohmann::json& v = section[key];
  if (!v.is_number() || !(v.get<double>() >= lo && v.get<double>() <= hi))
    case_fail(file, "'" + where + "." + key + "' must be a number in [" + std::to_string(lo) + ", " +
                        std::to_string(hi) + "]");
  return v.get<double>();
}

}  // namespace igaprep::cli
