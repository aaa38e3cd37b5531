// SurfaceMaps engine: the one exception type that ends a computation early.
#pragma once

namespace surfacemaps
{

/// Thrown when a progress callback asks to stop (the user aborted). Not an
/// error: callers discard partial results and report nothing. Every
/// algorithm of the engine and every filter of the module use this type.
struct Aborted
{
};

} // namespace surfacemaps
