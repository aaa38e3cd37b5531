#include "mesh/LandmarkValidation.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace surfacemaps;

TEST(LandmarkValidation, LandmarkIds)
{
  EXPECT_TRUE(checkLandmarkIds({ -1, 0, 1, -1 }).empty());
  ASSERT_EQ(checkLandmarkIds({ 1, 0, 1 }).size(), 1u);
  EXPECT_NE(checkLandmarkIds({ 1, 0, 1 })[0].find("landmark id 1 on two vertices (0 and 2)"),
    std::string::npos);
  EXPECT_EQ(checkLandmarkIds({ -5, 0 }).size(), 1u);
}

TEST(LandmarkValidation, LandmarkCorrespondence)
{
  const std::vector<std::string> names{ "a", "b", "c" };
  auto ok = checkLandmarkCorrespondence({ { 0, -1, 1 }, { -1, 1, -1, 0 }, { 1, 0 } }, names);
  for (const auto& d : ok)
  {
    EXPECT_TRUE(d.empty());
  }
  auto counts = checkLandmarkCorrespondence({ { 0, 1 }, { 0, -1 }, { 1, 0 } }, names);
  ASSERT_EQ(counts[1].size(), 1u);
  EXPECT_NE(counts[1][0].find("landmark counts do not match: a has 2, b has 1"), std::string::npos);
  EXPECT_TRUE(counts[2].empty());
  auto ids = checkLandmarkCorrespondence({ { 0, 1 }, { 0, 2 }, { 1, 0 } }, names);
  ASSERT_EQ(ids[1].size(), 1u);
  EXPECT_NE(ids[1][0].find("id 1 is on a (vertex 1) but not on b"), std::string::npos);
}
