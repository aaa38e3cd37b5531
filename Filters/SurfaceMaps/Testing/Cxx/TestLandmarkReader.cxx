#include "base/InputError.h"
#include "io/LandmarkReader.h"

#include <gtest/gtest.h>

using namespace surfacemaps;

TEST(LandmarkReader, AllFormats)
{
  EXPECT_EQ(parseLandmarks("4\n7\n\n# comment\n1\n", "a.txt"), (std::vector<int>{ 4, 7, 1 }));
  EXPECT_EQ(parseLandmarks("lk 4816\nlk 4152\n", "a.pinned"), (std::vector<int>{ 4816, 4152 }));
  EXPECT_EQ(parseLandmarks("12 0.5 -1 2e-3\n3 1 1 1\n", "a.vts"), (std::vector<int>{ 12, 3 }));
}

TEST(LandmarkReader, Errors)
{
  EXPECT_THROW(parseLandmarks("lk x\n", "a"), InputError);
  EXPECT_THROW(parseLandmarks("-3\n", "a"), InputError);
  EXPECT_THROW(parseLandmarks("3 foo\n", "a"), InputError);
  try
  {
    parseLandmarks("1\n2\nbanana\n", "a.txt");
    FAIL();
  }
  catch (const InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("a.txt:3:"), std::string::npos) << e.what();
  }
}

TEST(LandmarkReader, IdsFromIndices)
{
  const std::vector<int> ids = landmarkIdsFromIndices({ 3, 0 }, 5, "l");
  EXPECT_EQ(ids, (std::vector<int>{ 1, -1, -1, 0, -1 }));
  try
  {
    landmarkIdsFromIndices({ 3, 9 }, 5, "l.pinned");
    FAIL();
  }
  catch (const InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("landmark 1 is vertex 9, out of range for a mesh with 5"),
      std::string::npos)
      << e.what();
  }
  EXPECT_THROW(landmarkIdsFromIndices({ 2, 2 }, 5, "l"), InputError);
}
