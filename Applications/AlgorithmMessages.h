// The `surfacemap` command line: the error and warning events of a VTK
// algorithm, taken as messages of our own instead of VTK's output window.
#pragma once

#include <string>
#include <vector>

class vtkAlgorithm;
class vtkObject;

namespace surfacemap
{

/// Collects the messages of a VTK algorithm's ErrorEvents (or another event
/// that carries a message, such as WarningEvent), without VTK's
/// source-location prefix, so commands can print them their own way.
class ErrorCapture
{
public:
  explicit ErrorCapture(vtkAlgorithm* algorithm, unsigned long event = 0 /* ErrorEvent */);
  ~ErrorCapture();
  ErrorCapture(const ErrorCapture&) = delete;
  ErrorCapture& operator=(const ErrorCapture&) = delete;

  const std::vector<std::string>& messages() const { return this->Messages; }

private:
  static void callback(vtkObject*, unsigned long, void* self, void* text);
  vtkAlgorithm* Algorithm;
  unsigned long Tag = 0;
  std::vector<std::string> Messages;
};

/// Prints the warnings of an algorithm (vtkWarningMacro) on stderr as they
/// come, "surfacemap: warning: <message>", while this object lives.
class WarningPrinter
{
public:
  explicit WarningPrinter(vtkAlgorithm* algorithm);
  ~WarningPrinter();
  WarningPrinter(const WarningPrinter&) = delete;
  WarningPrinter& operator=(const WarningPrinter&) = delete;

private:
  static void callback(vtkObject*, unsigned long, void*, void* text);
  vtkAlgorithm* Algorithm;
  unsigned long Tag = 0;
};

} // namespace surfacemap
