// SurfaceMaps engine: the engine's error types, by what a failure means for
// the caller. Callers (the filters' error policy, the command line's exit
// codes) decide by ErrorKind; any other exception is an internal failure.
#pragma once

#include <stdexcept>
#include <string>

namespace surfacemaps
{

enum class ErrorKind
{
  /// User input (a file, a mesh, a landmark list, a setting) cannot be used.
  Input,
  /// The computation ran on usable input but found no certified result (no
  /// bijective embedding, the error bound not met, T beyond its budget).
  NoResult,
};

/// An engine failure the caller can name. The message names the input, the
/// defect and where it is; callers show it as is.
class Error : public std::runtime_error
{
public:
  Error(ErrorKind kind, const std::string& message)
    : std::runtime_error(message)
    , Kind(kind)
  {
  }
  ErrorKind kind() const { return this->Kind; }

private:
  ErrorKind Kind;
};

/// Thrown when user input cannot be used.
class InputError : public Error
{
public:
  explicit InputError(const std::string& message)
    : Error(ErrorKind::Input, message)
  {
  }
};

/// Thrown when usable input gives no certified result.
class NoResultError : public Error
{
public:
  explicit NoResultError(const std::string& message)
    : Error(ErrorKind::NoResult, message)
  {
  }
};

} // namespace surfacemaps
