// The `surfacemap` command line: shared declarations of its commands.
#pragma once

#include <string>
#include <vector>

namespace surfacemap
{

/// Exit codes of every command.
enum ExitCode
{
  ExitOk = 0,
  ExitInternalError = 1,
  ExitBadInput = 2, // bad usage or bad input
  ExitNoCertifiedResult = 3,
};

/// Thrown for bad usage; main prints the message and the command's help hint.
struct UsageError
{
  std::string Message;
};

/// `surfacemap check MESH... [--landmarks FILE...]`
int runCheck(const std::vector<std::string>& args);
extern const char* const CheckHelp;

/// `surfacemap embed MESH -o OUT.vtp [--on-sphere] [--landmarks FILE]`
int runEmbed(const std::vector<std::string>& args);
extern const char* const EmbedHelp;

/// `surfacemap evaluate SOURCE TARGET [--originals A B] [--output-dir DIR]` or
/// `surfacemap evaluate MAPDIR [--inputs A B ...] [--output-dir DIR]`
int runEvaluate(const std::vector<std::string>& args);
extern const char* const EvaluateHelp;

/// `surfacemap map A B [C ...] --output-dir DIR [options]`
int runMap(const std::vector<std::string>& args);
extern const char* const MapHelp;

/// `surfacemap statistics MAPDIR|MESH... --output-dir DIR [--modes K] [--align MODE]
/// [--frames F] [--pictures]`
int runStatistics(const std::vector<std::string>& args);
extern const char* const StatisticsHelp;

/// `surfacemap transfer MAPDIR --from I --to J [--arrays NAME ...] -o OUT.vtp`
int runTransfer(const std::vector<std::string>& args);
extern const char* const TransferHelp;

/// Prints "surfacemap: error: <message>" on stderr.
void printError(const std::string& message);

} // namespace surfacemap
