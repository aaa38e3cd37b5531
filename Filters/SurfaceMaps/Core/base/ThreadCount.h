// SurfaceMaps engine: the number of OpenMP threads for a stretch of work.
#pragma once

namespace surfacemaps
{

/// Sets the calling thread's OpenMP thread count for the object's lifetime
/// and restores the previous count afterwards. `threads` <= 0 leaves the
/// count alone (OpenMP's default: OMP_NUM_THREADS, else all cores). Results
/// of the engine do not depend on the thread count (its reductions are
/// deterministic), only the time does.
class ScopedThreadCount
{
public:
  explicit ScopedThreadCount(int threads);
  ~ScopedThreadCount();
  ScopedThreadCount(const ScopedThreadCount&) = delete;
  ScopedThreadCount& operator=(const ScopedThreadCount&) = delete;

  /// The calling thread's current OpenMP thread count.
  static int current();

private:
  int Previous = 0;
};

} // namespace surfacemaps
