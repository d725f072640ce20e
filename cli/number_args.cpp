#include "number_args.h"

#include <cmath>
#include <exception>
#include <sstream>

#include "igaprep/core/error.h"

namespace igaprep::cli {

double parse_number(const std::string& s, const std::string& what) {
  try {
    size_t used = 0;
    const double v = std::stod(s, &used);
    if (used == s.size() && std::isfinite(v)) return v;
  } catch (const std::exception&) {
  }
  throw bad_input(what + ": '" + s + "' is not a finite number");
}

std::vector<double> parse_numbers(const std::string& s, const std::string& what) {
  std::vector<double> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(parse_number(item, what));
  if (!s.empty() && s.back() == ',') throw bad_input(what + ": '" + s + "' ends with a comma");
  return out;
}

CLI::Validator positive_number() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        try {
          size_t used = 0;
          const double v = std::stod(s, &used);
          if (used == s.size() && std::isfinite(v) && v > 0.0) return "";
        } catch (const std::exception&) {
        }
        return "'" + s + "' must be a positive number";
      },
      "POSITIVE");
}

}  // namespace igaprep::cli
