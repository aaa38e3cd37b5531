#include "base/FreedMemory.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#if defined(__SANITIZE_ADDRESS__)
#define SURFACEMAPS_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SURFACEMAPS_TEST_ASAN 1
#endif
#endif

using namespace surfacemaps;

// Each test runs in its own process (gtest_discover_tests), so the settings
// below do not leak into other tests.

TEST(FreedMemory, LargeBlocksComeFromTheHeapAndStayAfterFree)
{
#if !defined(__GLIBC__) || defined(SURFACEMAPS_TEST_ASAN)
  GTEST_SKIP() << "glibc's own allocator only (AddressSanitizer replaces it)";
#else
  if (std::getenv("GLIBC_TUNABLES") != nullptr)
  {
    GTEST_SKIP() << "GLIBC_TUNABLES is set: the user's settings win";
  }
  ASSERT_TRUE(keepFreedMemoryForReuse());
  // Without the settings glibc maps a 16 MiB block on its own (the default
  // mapping threshold is 128 KiB) and unmaps it on free.
  constexpr std::size_t Size = 16u << 20;
  const struct mallinfo2 before = mallinfo2();
  char* block = static_cast<char*>(std::malloc(Size));
  ASSERT_NE(block, nullptr);
  std::memset(block, 1, Size);
  const struct mallinfo2 allocated = mallinfo2();
  EXPECT_EQ(allocated.hblkhd, before.hblkhd) << "the block was mapped on its own";
  std::free(block);
  const struct mallinfo2 freed = mallinfo2();
  EXPECT_GE(freed.fordblks, before.fordblks + Size) << "the freed block left the heap";
#endif
}

TEST(FreedMemory, TheUsersTunablesWin)
{
#if !defined(__GLIBC__)
  GTEST_SKIP() << "glibc only";
#else
  ASSERT_EQ(setenv("GLIBC_TUNABLES", "glibc.malloc.trim_threshold=4096", 1), 0);
  EXPECT_FALSE(keepFreedMemoryForReuse());
  unsetenv("GLIBC_TUNABLES");
#endif
}
