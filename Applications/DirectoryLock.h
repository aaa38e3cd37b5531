// The `surfacemap` command line: advisory locks on directories, so that one
// run at a time writes a map directory.
#pragma once

#include <string>

namespace surfacemap
{

/// An advisory lock (flock) on a directory, held while this object lives.
/// Only surfacemap's own runs take these locks; the kernel releases them
/// when a process dies, so a held lock means a live writer.
class DirectoryLock
{
public:
  /// Locks `directory`; with `wait`, waits while another process holds it,
  /// otherwise gives up at once (busy()).
  DirectoryLock(const std::string& directory, bool wait);
  ~DirectoryLock();
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;

  /// This object holds the lock.
  bool locked() const { return this->Fd >= 0; }
  /// Another process holds it (only without `wait`).
  bool busy() const { return this->Busy; }
  /// Neither: the directory cannot be opened or its file system has no
  /// flock (then nothing is known about other writers).
  bool unavailable() const { return !this->locked() && !this->Busy; }

private:
  int Fd = -1;
  bool Busy = false;
};

/// True if another process holds the lock on `directory` (a live run
/// writing it); false if it is free or cannot be locked at all.
bool lockedByAnother(const std::string& directory);

} // namespace surfacemap
