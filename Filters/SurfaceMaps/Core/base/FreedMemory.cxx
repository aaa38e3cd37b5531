#include "base/FreedMemory.h"

#include <cstdlib>
#include <cstring>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace surfacemaps
{

bool keepFreedMemoryForReuse()
{
#if defined(__GLIBC__)
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (tunables != nullptr && std::strstr(tunables, "glibc.malloc.") != nullptr)
  {
    return false;
  }
  // glibc refuses a mapping threshold above half its largest thread heap
  // (HEAP_MAX_SIZE / 2: 32 MiB with 64-bit pointers); larger blocks are
  // mapped and unmapped one by one whatever the setting.
  constexpr int MappingThreshold = 32 * 1024 * 1024;
  constexpr int TrimThreshold = 1024 * 1024 * 1024;
  return mallopt(M_MMAP_THRESHOLD, MappingThreshold) == 1 &&
    mallopt(M_TRIM_THRESHOLD, TrimThreshold) == 1;
#else
  return false;
#endif
}

} // namespace surfacemaps
