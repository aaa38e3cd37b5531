#include "base/ThreadCount.h"

#include <omp.h>

namespace surfacemaps
{

ScopedThreadCount::ScopedThreadCount(int threads)
{
  if (threads > 0)
  {
    this->Previous = omp_get_max_threads();
    omp_set_num_threads(threads);
  }
}

ScopedThreadCount::~ScopedThreadCount()
{
  if (this->Previous > 0)
  {
    omp_set_num_threads(this->Previous);
  }
}

int ScopedThreadCount::current()
{
  return omp_get_max_threads();
}

} // namespace surfacemaps
