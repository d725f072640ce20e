#pragma once
// Numbers given on the command line: one, or a comma-separated list.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace igaprep::cli {

// Throws bad_input naming `what` (the flag) for anything but a finite number.
double parse_number(const std::string& s, const std::string& what);
// Comma-separated numbers; empty items (a trailing comma) are refused.
std::vector<double> parse_numbers(const std::string& s, const std::string& what);

// A flag's check: a finite number above 0 ("must be a positive number",
// where CLI::PositiveNumber prints the whole range of double).
CLI::Validator positive_number();

}  // namespace igaprep::cli
