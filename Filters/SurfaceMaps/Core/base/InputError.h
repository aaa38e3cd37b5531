// SurfaceMaps engine: error type for defects in user input.
#pragma once

#include <stdexcept>
#include <string>

namespace surfacemaps
{

/// Thrown when user input (a file, a mesh, a landmark list) cannot be used.
/// The message names the input, the defect and where it is; callers show it
/// as is. Internal failures use other exception types.
class InputError : public std::runtime_error
{
public:
  explicit InputError(const std::string& message)
    : std::runtime_error(message)
  {
  }
};

} // namespace surfacemaps
