// The `surfacemap` command line: what a command shows on the terminal
// besides its results: errors, warnings and a progress bar.
#pragma once

#include <functional>
#include <string>
#include <vector>

class vtkAlgorithm;
class vtkObject;

namespace surfacemap
{

/// A progress bar on stderr while an algorithm runs, only if stderr is a
/// terminal.
class ProgressBar
{
public:
  explicit ProgressBar(vtkAlgorithm* algorithm);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

private:
  static void callback(vtkObject*, unsigned long, void* self, void*);
  vtkAlgorithm* Algorithm;
  unsigned long Tag = 0;
  bool Shown = false;
};

/// Prints "surfacemap: warning: <message>" on stderr.
void printWarning(const std::string& message);

/// Prints every message with printError, in order.
void printErrors(const std::vector<std::string>& messages);

/// Runs `step`; if it throws std::runtime_error (a file that cannot be read,
/// created or written), prints the message and returns false, for the
/// caller to exit with ExitBadInput. Other exceptions pass.
bool succeeds(const std::function<void()>& step);

} // namespace surfacemap
