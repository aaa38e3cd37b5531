// The `surfacemap` command line: a VTK algorithm's error and warning events
// as plain messages.
#include "AlgorithmMessages.h"

#include "Terminal.h"

#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"

namespace surfacemap
{

namespace
{
// vtkErrorMacro/vtkWarningMacro text: "ERROR: In file, line N\nClass (0x...): message"
std::string macroMessage(void* text, const char* none)
{
  std::string message = text ? static_cast<const char*>(text) : none;
  const std::size_t marker = message.find("): ");
  if (marker != std::string::npos)
  {
    message = message.substr(marker + 3);
  }
  while (!message.empty() && (message.back() == '\n' || message.back() == ' '))
  {
    message.pop_back();
  }
  return message;
}
} // namespace

ErrorCapture::ErrorCapture(vtkAlgorithm* algorithm, unsigned long event)
  : Algorithm(algorithm)
{
  vtkNew<vtkCallbackCommand> command;
  command->SetCallback(&ErrorCapture::callback);
  command->SetClientData(this);
  this->Tag = algorithm->AddObserver(event ? event : vtkCommand::ErrorEvent, command);
}

ErrorCapture::~ErrorCapture()
{
  this->Algorithm->RemoveObserver(this->Tag);
}

void ErrorCapture::callback(vtkObject*, unsigned long, void* self, void* text)
{
  static_cast<ErrorCapture*>(self)->Messages.push_back(macroMessage(text, "unknown error"));
}

WarningPrinter::WarningPrinter(vtkAlgorithm* algorithm)
  : Algorithm(algorithm)
{
  vtkNew<vtkCallbackCommand> command;
  command->SetCallback(&WarningPrinter::callback);
  this->Tag = algorithm->AddObserver(vtkCommand::WarningEvent, command);
}

WarningPrinter::~WarningPrinter()
{
  this->Algorithm->RemoveObserver(this->Tag);
}

void WarningPrinter::callback(vtkObject*, unsigned long, void*, void* text)
{
  printWarning(macroMessage(text, "unknown warning"));
}

} // namespace surfacemap
