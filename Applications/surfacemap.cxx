// surfacemap: command-line front end of SurfaceMaps.
#include "AtomicFiles.h"
#include "Commands.h"

#include "base/ThreadCount.h"

#include "vtkLogger.h"
#include "vtkOutputWindow.h"
#include "vtkSMPTools.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

namespace surfacemap
{

void printError(const std::string& message)
{
  std::cerr << "surfacemap: error: " << message << "\n";
}

} // namespace surfacemap

namespace
{

struct Command
{
  const char* Name;
  const char* Summary;
  int (*Run)(const std::vector<std::string>&);
  const char* const* Help;
};

const Command Commands[] = {
  { "check",
    "validate meshes as SurfaceMaps inputs and print their statistics",
    &surfacemap::runCheck,
    &surfacemap::CheckHelp },
  { "embed",
    "bijective embedding of a mesh on the unit sphere",
    &surfacemap::runEmbed,
    &surfacemap::EmbedHelp },
  { "evaluate",
    "distortion, approximation error and certificate of a map (two meshes or a map directory)",
    &surfacemap::runEvaluate,
    &surfacemap::EvaluateHelp },
  { "map",
    "bijective map between surfaces through a common triangulation",
    &surfacemap::runMap,
    &surfacemap::MapHelp },
  { "statistics",
    "mean shape, modes of variation and spread of surfaces with one connectivity",
    &surfacemap::runStatistics,
    &surfacemap::StatisticsHelp },
  { "transfer",
    "carry point data and texture coordinates from one input of a map to another",
    &surfacemap::runTransfer,
    &surfacemap::TransferHelp },
};

// The options every command takes, handled here before the command runs.
const char* const CommonOptionsHelp =
  "  -v           log progress and VTK's own messages on stderr (-vv: more)\n"
  "  --threads N  compute on at most N threads (1 to 1024; OpenMP and VTK's\n"
  "               SMP tools; default: OMP_NUM_THREADS, else every core).\n"
  "               Results do not depend on it, only the time does\n";

// The value of --threads; 0 (after printing why) when it is not 1 to 1024.
int threadCount(const std::string& text)
{
  std::size_t end = 0;
  long value = 0;
  try
  {
    value = std::stol(text, &end);
  }
  catch (const std::exception&)
  {
    end = 0;
  }
  if (end == 0 || end != text.size() || value < 1 || value > 1024)
  {
    surfacemap::printError("--threads needs a whole number from 1 to 1024, not '" + text + "'");
    return 0;
  }
  return static_cast<int>(value);
}

void printUsage(std::ostream& os)
{
  os << "usage: surfacemap <command> [options]\n\n"
        "Bijective maps between closed genus-0 surfaces (SurfaceMaps).\n\n"
        "commands:\n";
  for (const Command& c : Commands)
  {
    os << "  " << c.Name << std::string(12 - std::strlen(c.Name), ' ') << c.Summary << "\n";
  }
  os << "\noptions:\n"
        "  -h, --help   show this help, or a command's help after the command\n"
     << CommonOptionsHelp
     << "\nexit codes: 0 ok, 1 internal error, 2 bad usage or bad input, 3 no certified result\n";
}

// Runs `command` with its arguments `rest` (or prints its help); the exit code.
int runCommand(const Command& command, const std::vector<std::string>& rest)
{
  for (const std::string& a : rest)
  {
    if (a == "-h" || a == "--help")
    {
      std::cout << *command.Help << "\nOptions of every command:\n" << CommonOptionsHelp;
      return surfacemap::ExitOk;
    }
  }
  try
  {
    const int code = command.Run(rest);
    // Output lost on stdout (a full disk, a closed pipe) is a failure too.
    std::cout.flush();
    if (std::fflush(stdout) != 0 || std::ferror(stdout) || !std::cout)
    {
      surfacemap::printError(
        std::string("cannot write to standard output: ") + std::strerror(errno ? errno : EIO));
      return code == surfacemap::ExitOk ? surfacemap::ExitBadInput : code;
    }
    return code;
  }
  catch (const surfacemap::UsageError& e)
  {
    surfacemap::printError(e.Message);
    std::cerr << "run 'surfacemap " << command.Name << " --help' for usage\n";
    return surfacemap::ExitBadInput;
  }
  catch (const std::exception& e)
  {
    surfacemap::printError(std::string("internal error: ") + e.what());
    return surfacemap::ExitInternalError;
  }
}

} // namespace

int main(int argc, char* argv[])
{
  // Messages go through our own error reporting; VTK's output window and
  // logger would repeat them with source locations. -v shows them again.
  vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  surfacemap::installSignalHandlers();

  std::vector<std::string> args;
  int verbosity = 0;
  int threads = 0;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "-v" || arg == "-vv" || arg == "-vvv")
    {
      verbosity += static_cast<int>(arg.size()) - 1;
    }
    else if (arg == "--threads")
    {
      threads = threadCount(i + 1 < argc ? argv[++i] : "");
      if (threads == 0)
      {
        return surfacemap::ExitBadInput;
      }
    }
    else
    {
      args.push_back(arg);
    }
  }
  if (verbosity > 0)
  {
    vtkOutputWindow::GetInstance()->SetDisplayModeToDefault();
    vtkLogger::SetStderrVerbosity(
      verbosity >= 2 ? vtkLogger::VERBOSITY_TRACE : vtkLogger::VERBOSITY_1);
  }

  if (args.empty() || args[0] == "-h" || args[0] == "--help" || args[0] == "help")
  {
    printUsage(args.empty() ? std::cerr : std::cout);
    return args.empty() ? surfacemap::ExitBadInput : surfacemap::ExitOk;
  }

  // One setting for every command and every parallel loop in it: OpenMP's
  // for the engine (whose filters leave the count alone by default) and
  // VTK's SMP tools for the evaluation's distance queries.
  const surfacemaps::ScopedThreadCount scopedThreads(threads);
  if (threads > 0)
  {
    vtkSMPTools::Initialize(threads);
  }
  for (const Command& command : Commands)
  {
    if (args[0] == command.Name)
    {
      return runCommand(command, std::vector<std::string>(args.begin() + 1, args.end()));
    }
  }
  surfacemap::printError("unknown command '" + args[0] + "'");
  printUsage(std::cerr);
  return surfacemap::ExitBadInput;
}
