#pragma once
// Runs f and expects a bad_input whose message contains every fragment and
// names no command-line option (library errors speak of the problem).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "igaprep/core/error.h"

namespace solve_test {

template <class F>
void expect_bad_input(F f, const std::vector<std::string>& fragments) {
  try {
    f();
    ADD_FAILURE() << "no error thrown";
  } catch (const igaprep::Error& e) {
    EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput) << e.what();
    for (const auto& s : fragments) EXPECT_NE(std::string(e.what()).find(s), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find("--"), std::string::npos) << e.what();
  }
}

}  // namespace solve_test
