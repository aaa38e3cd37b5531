// The `surfacemap` command line: the output directory of a command, created
// and checked for writing before a computation, removed again when the
// command created it and no result came out.
#pragma once

#include <string>

namespace surfacemap
{

/// Creates `directory` (with its parents) if missing and checks that the file
/// `probe` can be written in it. Throws std::runtime_error naming what failed.
void createOutputDirectory(const std::string& directory, const std::string& probe);

/// createOutputDirectory before a computation: false after printing why
/// (for the caller to exit with ExitBadInput). `created` receives the
/// outermost directory it had to create (empty if none), for
/// removeCreatedDirectory when no result comes out.
bool prepareOutputDirectory(const std::string& directory,
  const std::string& probe,
  std::string& created);

/// Removes `created` (from prepareOutputDirectory) with everything in it; nothing if empty.
void removeCreatedDirectory(const std::string& created);

} // namespace surfacemap
