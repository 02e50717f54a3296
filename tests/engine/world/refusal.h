#pragma once
// A change a test expects refused: it throws std::invalid_argument whose message holds `words`
// (the call, the field and what was expected). The caller then checks that nothing changed.
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

namespace rbsim::test {

template <typename Change>
void expectRefused(Change change, const std::string& words) {
  try {
    change();
    ADD_FAILURE() << "accepted; expected: " << words;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

}  // namespace rbsim::test
