// SurfaceMaps engine: messages to whoever runs the engine.
#pragma once

#include <functional>
#include <string>

namespace surfacemaps
{

/// Where engine messages go. The VTK layer forwards them to vtkLogger; the
/// default sink drops them. Passed in Options structs, never global.
struct Logger
{
  enum Level
  {
    Warning = -1,
    Info = 0,
    Detail = 1,
  };
  std::function<void(Level, const std::string&)> sink;

  void operator()(Level level, const std::string& message) const
  {
    if (this->sink)
    {
      this->sink(level, message);
    }
  }
};

} // namespace surfacemaps
