// The `surfacemap` command line: atomic file writes, and the signal handler
// that removes temporary files (and an interrupted command's staging
// directory or map files) on SIGINT and SIGTERM. The handler's paths live in fixed storage
// registered here.
#include "AtomicFiles.h"

#include "Terminal.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace surfacemap
{

void writeFailed(const std::string& path, const std::string& reason)
{
  throw std::runtime_error("cannot write '" + path + "': " + reason);
}

namespace
{
std::string temporaryName(const std::string& path)
{
  return path + ".tmp." + std::to_string(getpid());
}

// Temporary files being written, for the signal handler to remove: fixed
// storage, since a handler may neither allocate nor take locks.
constexpr int TemporarySlots = 16;
constexpr std::size_t TemporaryPathSize = 4096;
char TemporaryPaths[TemporarySlots][TemporaryPathSize];
volatile std::sig_atomic_t TemporaryInUse[TemporarySlots];

// Directories for InterruptCleanup, in the same kind of fixed storage.
constexpr int DirectorySlots = 4;
char DirectoryPaths[DirectorySlots][TemporaryPathSize];
volatile std::sig_atomic_t DirectoryScope[DirectorySlots];
volatile std::sig_atomic_t DirectoryInUse[DirectorySlots];

bool registerPath(char* slot, const std::string& path)
{
  if (path.size() >= TemporaryPathSize)
  {
    return false;
  }
  std::memcpy(slot, path.c_str(), path.size() + 1);
  std::atomic_signal_fence(std::memory_order_seq_cst);
  return true;
}

bool startsWith(const char* text, const char* prefix)
{
  return std::strncmp(text, prefix, std::strlen(prefix)) == 0;
}

// A name a map writes (isMapFileName's pattern, loosely) or a temporary
// file; async-signal-safe (no allocation, no locale).
bool isMapWrittenName(const char* name)
{
  if (std::strcmp(name, "report.json") == 0 || std::strcmp(name, "fit.csv") == 0 ||
    std::strcmp(name, "correspondences.npz") == 0 || std::strstr(name, ".tmp.") != nullptr)
  {
    return true;
  }
  const std::size_t length = std::strlen(name);
  return (startsWith(name, "common_") || startsWith(name, "mapped_") ||
           startsWith(name, "embedding_")) &&
    length > 4 && std::strcmp(name + length - 4, ".vtp") == 0;
}

struct DirectoryEntry
{
  std::uint64_t inode;
  std::int64_t offset;
  unsigned short length;
  unsigned char type;
  char name[1];
};

// Removes the entries of the open directory `fd` (only the map's files with
// `mapFilesOnly`; otherwise every file, and the subdirectories with their
// files while `depth` > 0), with system calls only: a signal handler may
// not allocate. One buffer per depth, since a subdirectory is read while
// its parent's buffer is still being walked.
void removeEntriesAt(int fd, int depth, bool mapFilesOnly)
{
  constexpr int Depths = 2;
  alignas(8) static char buffers[Depths][8192];
  char* buffer = buffers[depth < Depths ? depth : Depths - 1];
  // Unlinking while reading the directory may skip entries: read it again
  // until a pass removes nothing.
  for (bool removed = true; removed;)
  {
    removed = false;
    lseek(fd, 0, SEEK_SET);
    for (long n; (n = syscall(SYS_getdents64, fd, buffer, sizeof(buffers[0]))) > 0;)
    {
      for (long at = 0; at < n;)
      {
        const auto* entry = reinterpret_cast<const DirectoryEntry*>(buffer + at);
        at += entry->length;
        const char* name = entry->name;
        if (std::strcmp(name, ".") == 0 || std::strcmp(name, "..") == 0 ||
          (mapFilesOnly && !isMapWrittenName(name)))
        {
          continue;
        }
        if (unlinkat(fd, name, 0) == 0)
        {
          removed = true;
        }
        else if (errno == EISDIR && depth > 0 && !mapFilesOnly)
        {
          const int sub = openat(fd, name, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
          if (sub >= 0)
          {
            removeEntriesAt(sub, depth - 1, false);
            close(sub);
          }
          removed = unlinkat(fd, name, AT_REMOVEDIR) == 0 || removed;
        }
      }
    }
  }
}

void removeWrittenFilesOf(const char* directory, bool mapFilesOnly)
{
  const int fd = open(directory, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0)
  {
    return;
  }
  removeEntriesAt(fd, 1, mapFilesOnly);
  close(fd);
  if (!mapFilesOnly)
  {
    rmdir(directory);
  }
}

extern "C" void removeTemporariesAndExit(int signal)
{
  for (int k = 0; k < TemporarySlots; ++k)
  {
    if (TemporaryInUse[k])
    {
      unlink(TemporaryPaths[k]);
    }
  }
  for (int k = 0; k < DirectorySlots; ++k)
  {
    if (DirectoryInUse[k])
    {
      removeWrittenFilesOf(DirectoryPaths[k], DirectoryScope[k] == InterruptCleanup::MapFiles);
    }
  }
  // The default action, so the parent sees death by this signal.
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

// A temporary file name registered for removal on SIGINT/SIGTERM while this
// object lives; the file itself is removed by remove() or the destructor.
class TemporaryFile
{
public:
  explicit TemporaryFile(const std::string& path)
    : Path(temporaryName(path))
  {
    for (int k = 0; k < TemporarySlots; ++k)
    {
      if (!TemporaryInUse[k] && this->Path.size() < TemporaryPathSize)
      {
        std::memcpy(TemporaryPaths[k], this->Path.c_str(), this->Path.size() + 1);
        std::atomic_signal_fence(std::memory_order_seq_cst);
        TemporaryInUse[k] = 1;
        this->Slot = k;
        break;
      }
    }
  }
  ~TemporaryFile()
  {
    this->remove();
    if (this->Slot >= 0)
    {
      TemporaryInUse[this->Slot] = 0;
    }
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  const std::string& path() const { return this->Path; }
  void remove()
  {
    if (!this->Renamed)
    {
      std::remove(this->Path.c_str());
    }
  }
  /// Renames the file to `target`; throws std::runtime_error naming `target`.
  void renameTo(const std::string& target)
  {
    if (std::rename(this->Path.c_str(), target.c_str()) != 0)
    {
      writeFailed(target, std::strerror(errno));
    }
    this->Renamed = true;
  }

private:
  std::string Path;
  int Slot = -1;
  bool Renamed = false;
};

// Writes `content` to a new file `temporary` with every step checked: each
// write, fsync (data on the disk, where the file system supports it), close,
// and the size that arrived. Throws std::runtime_error naming `path`.
void writeChecked(const std::string& temporary, const std::string& path, const std::string& content)
{
  const int fd = open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0)
  {
    writeFailed(path, std::strerror(errno));
  }
  std::size_t written = 0;
  while (written < content.size())
  {
    const ssize_t n = write(fd, content.data() + written, content.size() - written);
    if (n < 0 && errno == EINTR)
    {
      continue;
    }
    if (n <= 0)
    {
      const std::string reason = n < 0 ? std::strerror(errno) : "nothing was written";
      close(fd);
      writeFailed(path, reason);
    }
    written += static_cast<std::size_t>(n);
  }
  if (fsync(fd) != 0 && errno != EINVAL && errno != EROFS)
  {
    const std::string reason = std::strerror(errno);
    close(fd);
    writeFailed(path, reason);
  }
  if (close(fd) != 0)
  {
    writeFailed(path, std::strerror(errno));
  }
  struct stat info;
  if (stat(temporary.c_str(), &info) != 0)
  {
    writeFailed(path, std::strerror(errno));
  }
  if (static_cast<unsigned long long>(info.st_size) != content.size())
  {
    writeFailed(path,
      "only " + std::to_string(static_cast<long long>(info.st_size)) + " of " +
        std::to_string(content.size()) + " bytes reached the disk");
  }
}
} // namespace

InterruptCleanup::InterruptCleanup(const std::string& directory, Scope scope)
{
  for (int k = 0; k < DirectorySlots; ++k)
  {
    if (!DirectoryInUse[k] && registerPath(DirectoryPaths[k], directory))
    {
      DirectoryScope[k] = scope;
      DirectoryInUse[k] = 1;
      this->Slot = k;
      return;
    }
  }
}

InterruptCleanup::~InterruptCleanup()
{
  if (this->Slot >= 0)
  {
    DirectoryInUse[this->Slot] = 0;
  }
}

InterruptHold::InterruptHold()
{
  sigset_t held;
  sigemptyset(&held);
  sigaddset(&held, SIGINT);
  sigaddset(&held, SIGTERM);
  sigprocmask(SIG_BLOCK, &held, &this->Previous);
}

InterruptHold::~InterruptHold()
{
  sigprocmask(SIG_SETMASK, &this->Previous, nullptr);
}

void installSignalHandlers()
{
  struct sigaction action = {};
  action.sa_handler = removeTemporariesAndExit;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  // Past a file size limit write() then fails with EFBIG, which is reported,
  // instead of the process dying with the temporary file left behind.
  std::signal(SIGXFSZ, SIG_IGN);
}

bool renameUnsupported(int error)
{
  return error == EINVAL || error == ENOSYS || error == EOPNOTSUPP;
}

int renameNoReplace(const std::string& from, const std::string& to)
{
  if (renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0)
  {
    return 0;
  }
  if (!renameUnsupported(errno))
  {
    return errno;
  }
  struct stat info;
  if (lstat(to.c_str(), &info) == 0)
  {
    return EEXIST;
  }
  return std::rename(from.c_str(), to.c_str()) == 0 ? 0 : errno;
}

int exchangePaths(const std::string& a, const std::string& b)
{
  return renameat2(AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(), RENAME_EXCHANGE) == 0 ? 0 : errno;
}

void checkWritable(const std::string& path)
{
  TemporaryFile temporary(path);
  std::FILE* file = std::fopen(temporary.path().c_str(), "wb");
  if (!file)
  {
    writeFailed(path, std::strerror(errno));
  }
  std::fclose(file);
}

bool canWrite(const std::string& path)
{
  return succeeds([&path] { checkWritable(path); });
}

void writeFileAtomically(const std::string& path, const std::string& content)
{
  TemporaryFile temporary(path);
  writeChecked(temporary.path(), path, content);
  temporary.renameTo(path);
}

} // namespace surfacemap
