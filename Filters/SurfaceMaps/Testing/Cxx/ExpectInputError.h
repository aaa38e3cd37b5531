// Test helper: an InputError whose message contains a given part.
#pragma once

#include "base/Error.h"

#include <gtest/gtest.h>

#include <string>

namespace surfacemaps
{
namespace testing
{

/// Runs `f` and expects it to throw InputError with `part` in its message.
template<typename F>
void expectInputError(F f, const std::string& part)
{
  try
  {
    f();
    ADD_FAILURE() << "no InputError (expected one containing '" << part << "')";
  }
  catch (const InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

} // namespace testing
} // namespace surfacemaps
