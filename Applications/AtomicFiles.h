// The `surfacemap` command line: files written atomically (a temporary name,
// every write checked, then renamed) and the signal handling that removes
// what an interrupted command leaves half written.
#pragma once

#include <string>

namespace surfacemap
{

/// Makes SIGINT and SIGTERM remove the temporary files being written before
/// the process ends, and ignores SIGXFSZ so a file size limit is a reported
/// write error. Call once at the start of main.
void installSignalHandlers();

/// While it lives, SIGINT and SIGTERM remove the files of `directory` that a
/// map writes (report.json, common_/mapped_/embedding_<i>.vtp, temporary
/// *.tmp.* files) and then the directory if that left it empty; any other
/// file stays, and with it the directory. For a map being written beside
/// the directory it will replace, and for the replaced map's files.
class InterruptCleanup
{
public:
  explicit InterruptCleanup(const std::string& directory);
  ~InterruptCleanup();
  InterruptCleanup(const InterruptCleanup&) = delete;
  InterruptCleanup& operator=(const InterruptCleanup&) = delete;

private:
  int Slot = -1;
};

/// While it lives, SIGINT and SIGTERM first rename `moved` back to
/// `original` (before any InterruptCleanup runs). The rename fails, and
/// changes nothing, while `original` exists: only the moment between moving
/// a directory away and moving its replacement in is undone.
class InterruptRestore
{
public:
  InterruptRestore(const std::string& moved, const std::string& original);
  ~InterruptRestore();
  InterruptRestore(const InterruptRestore&) = delete;
  InterruptRestore& operator=(const InterruptRestore&) = delete;

private:
  bool Registered = false;
};

/// Writes `content` to a temporary name beside `path`, checks every write,
/// fsync, close and the size on disk, then renames it. On any failure the
/// temporary file is removed and std::runtime_error names `path`.
void writeFileAtomically(const std::string& path, const std::string& content);

/// Throws std::runtime_error "cannot write '<path>': <reason>".
[[noreturn]] void writeFailed(const std::string& path, const std::string& reason);

/// Throws std::runtime_error naming `path` if no file can be created there
/// (checked before long computations whose result would be lost).
void checkWritable(const std::string& path);

/// True if a file can be created at `path`; otherwise prints why (as
/// checkWritable's message) and returns false, for the caller to exit with
/// ExitBadInput.
bool canWrite(const std::string& path);

} // namespace surfacemap
