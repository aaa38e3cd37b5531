// The `surfacemap` command line: the output directory of a command, created
// and checked for writing before a computation, removed again when the
// command created it and no result came out.
#pragma once

#include <memory>
#include <string>
#include <vector>

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

class InterruptCleanup;

/// A command's private directory inside its output directory
/// (`directory`/<name>.tmp.<pid>) for files that belong together, such as
/// animation frames and the index files naming them: removed on SIGINT,
/// SIGTERM and when this object dies, so an interrupted command leaves none
/// of them; publish() moves them into `directory` at the end.
class StagingDirectory
{
public:
  /// Creates it; throws std::runtime_error naming it on failure.
  StagingDirectory(const std::string& directory, const std::string& name);
  /// Removes it with whatever is still in it.
  ~StagingDirectory();
  StagingDirectory(const StagingDirectory&) = delete;
  StagingDirectory& operator=(const StagingDirectory&) = delete;

  const std::string& path() const { return this->Path; }

  /// Moves the entries `names` (files or directories of path()) into the
  /// output directory in this order, replacing entries of the same name (a
  /// directory exchanged in one step where the file system can, then the
  /// replaced one removed), with SIGINT and SIGTERM held until all are
  /// moved. Throws std::runtime_error naming an entry that cannot be moved.
  void publish(const std::vector<std::string>& names);

private:
  std::string Directory;
  std::string Path;
  std::unique_ptr<InterruptCleanup> Cleanup;
};

} // namespace surfacemap
