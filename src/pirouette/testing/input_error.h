#pragma once

#include <gtest/gtest.h>

#include "pirouette/core/input_error.h"

namespace pirouette::testing {

// Runs `load`, which must throw core::InputError, and returns the error (a
// test failure, and an empty error, when it throws none).
template <typename F>
core::InputError ExpectInputError(F&& load) {
  try {
    load();
  } catch (const core::InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no core::InputError was thrown";
  return {"", -1, "", ""};
}

}  // namespace pirouette::testing
