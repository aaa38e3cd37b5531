// The `surfacemap` command line: reading a command's arguments (options,
// their values, unknown options).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace surfacemap
{

/// True for an argument that starts with '-': an option, never a file.
bool isOption(const std::string& argument);

/// True for the option naming the directory a command writes into: "-o" or
/// "--output-dir" (one declaration for every command that writes one).
bool isOutputDirOption(const std::string& argument);

/// The value after the option args[i], advancing i to it; throws UsageError
/// "<option> needs <what>" when the arguments end first.
const std::string& optionValue(const std::vector<std::string>& args,
  std::size_t& i,
  const char* what = "a value");

/// Throws UsageError "unknown option '<argument>'".
[[noreturn]] void unknownOption(const std::string& argument);

} // namespace surfacemap
