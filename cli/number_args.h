#pragma once
// Numbers given on the command line: one, or a comma-separated list.
#include <string>
#include <vector>

namespace igaprep::cli {

// Throws bad_input naming `what` (the flag) for anything but a finite number.
double parse_number(const std::string& s, const std::string& what);
// Comma-separated numbers; empty items (a trailing comma) are refused.
std::vector<double> parse_numbers(const std::string& s, const std::string& what);

}  // namespace igaprep::cli
