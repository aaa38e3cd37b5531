// SurfaceMaps engine: BlasThreadGuard's shared count of active guards and the
// OpenBLAS thread count it saved.
#include "optimisation/sparse/BlasThreadGuard.h"

#include <dlfcn.h>
#include <omp.h>

#include <mutex>

namespace surfacemaps
{

namespace
{
struct BlasState
{
  int active = 0;
  int previous = 0;
  void (*set)(int) = nullptr;
};

BlasState& blasState()
{
  static BlasState s;
  return s;
}

std::mutex& blasMutex()
{
  static std::mutex m;
  return m;
}
} // namespace

BlasThreadGuard::BlasThreadGuard()
  : OpenMPThreads(omp_get_max_threads())
{
  std::lock_guard<std::mutex> lock(blasMutex());
  BlasState& s = blasState();
  if (s.active++ == 0)
  {
    using Get = int (*)();
    auto get = reinterpret_cast<Get>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
    s.set = reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
    s.previous = get && s.set ? get() : 0;
    if (s.previous > 0)
    {
      s.set(1);
    }
  }
}

BlasThreadGuard::~BlasThreadGuard()
{
  std::lock_guard<std::mutex> lock(blasMutex());
  BlasState& s = blasState();
  if (--s.active == 0 && s.previous > 0)
  {
    s.set(s.previous);
  }
  omp_set_num_threads(this->OpenMPThreads);
}

} // namespace surfacemaps
