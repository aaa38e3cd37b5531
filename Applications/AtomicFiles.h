// The `surfacemap` command line: files written atomically (a temporary name,
// every write checked, then renamed) and the signal handling that removes
// what an interrupted command leaves half written.
#pragma once

#include <signal.h>

#include <string>

namespace surfacemap
{

/// Makes SIGINT and SIGTERM remove the temporary files being written before
/// the process ends, and ignores SIGXFSZ so a file size limit is a reported
/// write error. Call once at the start of main.
void installSignalHandlers();

/// While it lives, SIGINT and SIGTERM remove what a command was writing into
/// `directory` before the process ends:
/// - MapFiles: the files a map writes (report.json, common_/mapped_/
///   embedding_<i>.vtp, fit.csv, correspondences.npz, temporary *.tmp.*
///   files); any other file stays, and
///   so does the directory (a map written in place);
/// - Everything: every file in it and in its subdirectories (one level
///   deep), then the directory itself (a command's private staging
///   directory).
class InterruptCleanup
{
public:
  enum Scope
  {
    MapFiles,
    Everything
  };
  InterruptCleanup(const std::string& directory, Scope scope);
  ~InterruptCleanup();
  InterruptCleanup(const InterruptCleanup&) = delete;
  InterruptCleanup& operator=(const InterruptCleanup&) = delete;

private:
  int Slot = -1;
};

/// While it lives, SIGINT and SIGTERM wait (blocked, then delivered when it
/// ends): for the few renames that publish a result, which must happen all
/// or none.
class InterruptHold
{
public:
  InterruptHold();
  ~InterruptHold();
  InterruptHold(const InterruptHold&) = delete;
  InterruptHold& operator=(const InterruptHold&) = delete;

private:
  sigset_t Previous;
};

/// Writes `content` to a temporary name beside `path`, checks every write,
/// fsync, close and the size on disk, then renames it. On any failure the
/// temporary file is removed and std::runtime_error names `path`.
void writeFileAtomically(const std::string& path, const std::string& content);

/// Renames `from` to `to` unless `to` exists (renameat2 RENAME_NOREPLACE);
/// where the file system lacks the flag, checks and then renames (callers
/// hold a lock against other surfacemap runs). Returns 0 or the errno
/// (EEXIST when `to` exists).
int renameNoReplace(const std::string& from, const std::string& to);

/// Swaps the entries `a` and `b` in one step (renameat2 RENAME_EXCHANGE).
/// Returns 0 or the errno; renameUnsupported(errno) where the file system
/// cannot exchange.
int exchangePaths(const std::string& a, const std::string& b);

/// True for the errno of a renameat2 flag the file system or kernel lacks.
bool renameUnsupported(int error);

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
