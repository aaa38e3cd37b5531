#include "VirtualDisplay.h"

#include "vtkLogger.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

// Xlib last: its macros (None, Status, Bool) clash with other headers.
#include <X11/Xlib.h>

namespace surfacemap
{

namespace
{

// How long Xvfb may take to accept connections (it usually takes well under
// a second; a loaded machine may need more).
const int StartTimeoutMs = 20000;

// The Xvfb this process started (0: none) and the connection held open.
pid_t virtualServer = 0;
::Display* held = nullptr;

void stopVirtualServer()
{
  if (virtualServer > 0)
  {
    kill(virtualServer, SIGTERM);
    waitpid(virtualServer, nullptr, 0); // its lock file and socket are gone when it returns
    virtualServer = 0;
  }
}

// In the child between fork and exec: async-signal-safe calls only.
[[noreturn]] void execXvfb(int numberFd, const char* fdText)
{
  prctl(PR_SET_PDEATHSIG, SIGTERM); // dies with this process, even when it is killed
  fcntl(numberFd, F_SETFD, 0);      // the one descriptor Xvfb inherits on purpose
  const int null = open("/dev/null", O_RDWR);
  if (null >= 0)
  {
    dup2(null, STDIN_FILENO);
    dup2(null, STDOUT_FILENO);
    dup2(null, STDERR_FILENO); // its warnings about fonts and keymaps are no concern of the user
  }
  // -displayfd: Xvfb picks a free display number itself and writes it to the
  // descriptor once it accepts connections; -noreset keeps it up between clients.
  execlp("Xvfb",
    "Xvfb",
    "-displayfd",
    fdText,
    "-screen",
    "0",
    "1920x1200x24",
    "-nolisten",
    "tcp",
    "-noreset",
    static_cast<char*>(nullptr));
  _exit(127);
}

// The display number Xvfb writes to `fd` (up to a newline or its exit), or
// empty after StartTimeoutMs.
std::string readDisplayNumber(int fd)
{
  using Clock = std::chrono::steady_clock;
  std::string number;
  const Clock::time_point deadline = Clock::now() + std::chrono::milliseconds(StartTimeoutMs);
  while (Clock::now() < deadline)
  {
    const auto left =
      std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    pollfd wait{ fd, POLLIN, 0 };
    const int ready = poll(&wait, 1, static_cast<int>(std::max<long long>(left, 1)));
    if (ready < 0 && errno == EINTR)
    {
      continue;
    }
    char c = 0;
    const ssize_t n = ready > 0 ? read(fd, &c, 1) : -1;
    if (n < 0 && ready > 0 && errno == EINTR)
    {
      continue;
    }
    if (n <= 0 || c == '\n')
    {
      break; // timeout, or end of file: Xvfb exited
    }
    number += c;
  }
  return number;
}

// Starts Xvfb; its display name (":N"), or empty with `why` set.
std::string startVirtualServer(std::string& why)
{
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0)
  {
    why = "cannot create a pipe to start Xvfb";
    return "";
  }
  const std::string fdText = std::to_string(fds[1]);
  const pid_t pid = fork();
  if (pid == 0)
  {
    execXvfb(fds[1], fdText.c_str());
  }
  close(fds[1]);
  if (pid < 0)
  {
    close(fds[0]);
    why = "cannot start Xvfb (fork failed)";
    return "";
  }
  const std::string number = readDisplayNumber(fds[0]);
  close(fds[0]);
  if (number.empty())
  {
    kill(pid, SIGTERM);
    int status = 0;
    waitpid(pid, &status, 0);
    why = WIFEXITED(status) && WEXITSTATUS(status) == 127
      ? "Xvfb, which would provide a virtual one, is not installed (Debian package xvfb)"
      : "Xvfb, started to provide a virtual one, did not accept connections";
    return "";
  }
  virtualServer = pid;
  std::atexit(stopVirtualServer);
  return ":" + number;
}

} // namespace

std::string prepareDisplay()
{
  if (held)
  {
    return "";
  }
  const char* name = std::getenv("DISPLAY");
  const std::string given = name ? name : "";
  if (!given.empty())
  {
    held = XOpenDisplay(nullptr);
    if (held)
    {
      return "";
    }
  }
  std::string why;
  const std::string display = startVirtualServer(why);
  if (!display.empty())
  {
    setenv("DISPLAY", display.c_str(), 1);
    held = XOpenDisplay(nullptr);
    if (held)
    {
      vtkLogF(INFO,
        "pictures: rendering on the virtual display %s (Xvfb, stopped at exit)",
        display.c_str());
      return "";
    }
    why = "Xvfb started as display " + display + " but does not accept connections";
  }
  const std::string missing = given.empty()
    ? std::string("no display to render on (DISPLAY is not set)")
    : "cannot open the display '" + given + "' to render on";
  return missing + " and " + why;
}

} // namespace surfacemap
