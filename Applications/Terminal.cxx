// The `surfacemap` command line: messages and the progress bar on the
// terminal.
#include "Terminal.h"

#include "Commands.h"

#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"

#include <unistd.h>

#include <iostream>
#include <stdexcept>

namespace surfacemap
{

ProgressBar::ProgressBar(vtkAlgorithm* algorithm)
  : Algorithm(algorithm)
{
  if (!isatty(STDERR_FILENO))
  {
    return;
  }
  vtkNew<vtkCallbackCommand> command;
  command->SetCallback(&ProgressBar::callback);
  command->SetClientData(this);
  this->Tag = algorithm->AddObserver(vtkCommand::ProgressEvent, command);
}

ProgressBar::~ProgressBar()
{
  if (this->Tag)
  {
    this->Algorithm->RemoveObserver(this->Tag);
  }
  if (this->Shown)
  {
    std::cerr << "\n";
  }
}

void ProgressBar::callback(vtkObject*, unsigned long, void* self, void*)
{
  auto* bar = static_cast<ProgressBar*>(self);
  const double progress = bar->Algorithm->GetProgress();
  const int width = 30;
  const int filled = static_cast<int>(progress * width + 0.5);
  const char* text = bar->Algorithm->GetProgressText();
  // \033[K clears what a longer earlier text left on the line.
  std::cerr << "\r[" << std::string(filled, '#') << std::string(width - filled, ' ') << "] "
            << static_cast<int>(100 * progress + 0.5) << "% " << (text ? text : "") << "\033[K"
            << std::flush;
  bar->Shown = true;
}

void printWarning(const std::string& message)
{
  std::cerr << "surfacemap: warning: " << message << "\n";
}

void printErrors(const std::vector<std::string>& messages)
{
  for (const std::string& m : messages)
  {
    printError(m);
  }
}

bool succeeds(const std::function<void()>& step)
{
  try
  {
    step();
    return true;
  }
  catch (const std::runtime_error& e)
  {
    printError(e.what());
    return false;
  }
}

} // namespace surfacemap
