// The `surfacemap` command line: advisory locks on directories.
#include "DirectoryLock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>

namespace surfacemap
{

DirectoryLock::DirectoryLock(const std::string& directory, bool wait)
{
  const int fd = open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0)
  {
    return;
  }
  int result;
  do
  {
    result = flock(fd, LOCK_EX | (wait ? 0 : LOCK_NB));
  } while (result != 0 && errno == EINTR);
  if (result == 0)
  {
    this->Fd = fd;
    return;
  }
  this->Busy = errno == EWOULDBLOCK;
  close(fd);
}

DirectoryLock::~DirectoryLock()
{
  if (this->Fd >= 0)
  {
    close(this->Fd); // releases the lock
  }
}

bool lockedByAnother(const std::string& directory)
{
  return DirectoryLock(directory, false).busy();
}

} // namespace surfacemap
