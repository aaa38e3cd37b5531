// Landmarks as guides: the check sets aside landmarks the shapes disagree
// with and keeps the right ones, and the map is then bound by the kept ones.
#include "MapTestInputs.h"
#include "map/LandmarkGuides.h"
#include "map/SurfaceMap.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <string>
#include <utility>

using namespace surfacemaps;
using namespace surfacemaps::testing;

namespace
{

const Eigen::Matrix3d SphereTurn =
  Eigen::AngleAxisd(2.2, Eigen::Vector3d(-1.0, 0.3, 2.0).normalized()).matrix();

/// Six landmarks on the two bumpy ellipsoids (input 1 moved and its
/// embedding turned), at the same material points; on input 1 the ids of
/// each pair in `swaps` exchanged.
std::vector<MapInput> landmarkedPair(const std::vector<std::pair<int, int>>& swaps)
{
  Eigen::Affine3d motion = Eigen::Affine3d::Identity();
  motion.rotate(Eigen::AngleAxisd(0.9, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()));
  std::vector<MapInput> inputs{ bumpyEllipsoid(2, Eigen::Matrix3d::Identity(),
                                  Eigen::Affine3d::Identity()),
    bumpyEllipsoid(2, SphereTurn, motion) };
  std::vector<Eigen::Vector3d> directions{ bumpyTips()[0], bumpyTips()[1], { 1, 0, 0 },
    { -1, 0, 0 }, { 0, 0, -1 }, { 0, 1, 0 } };
  setLandmarks(inputs[0], directions);
  for (Eigen::Vector3d& d : directions)
  {
    d = SphereTurn * d;
  }
  for (const auto& [a, b] : swaps)
  {
    std::swap(directions[a], directions[b]);
  }
  setLandmarks(inputs[1], directions);
  return inputs;
}

SurfaceMapOptions shortSchedule()
{
  SurfaceMapOptions options;
  options.coarseIterations = 10;
  options.fineIterations = 0;
  options.refinementRounds = 0;
  return options;
}

const MapFunction Map = [](const std::vector<MapInput>& inputs, const SurfaceMapOptions& options)
{ return computeSurfaceMap(inputs, options); };

} // namespace

TEST(LandmarkGuides, TheShapesConfirmRightLandmarks)
{
  const LandmarkCheck check = confirmLandmarks(landmarkedPair({}), shortSchedule(), Map);
  EXPECT_FALSE(check.undecided);
  EXPECT_EQ(check.confirmed, std::vector<int>({ 0, 1, 2, 3, 4, 5 }));
  EXPECT_TRUE(check.unconfirmed.empty());
}

TEST(LandmarkGuides, TheShapesDoNotConfirmSwappedLandmarks)
{
  // The two bump tips exchanged.
  const LandmarkCheck check = confirmLandmarks(landmarkedPair({ { 0, 1 } }), shortSchedule(), Map);
  EXPECT_FALSE(check.undecided);
  EXPECT_EQ(check.confirmed, std::vector<int>({ 2, 3, 4, 5 }));
  EXPECT_EQ(check.unconfirmed, std::vector<int>({ 0, 1 }));
  for (const int id : check.unconfirmed)
  {
    EXPECT_GT(check.distance.at(id), shortSchedule().landmarkGuideTolerance) << "landmark " << id;
  }
}

TEST(LandmarkGuides, MostlyWrongLandmarksCannotBeJudged)
{
  // Four of six wrong: the shapes confirm two, too few to hold a map.
  const LandmarkCheck check =
    confirmLandmarks(landmarkedPair({ { 0, 1 }, { 2, 3 } }), shortSchedule(), Map);
  EXPECT_TRUE(check.undecided);
  EXPECT_EQ(check.confirmed, std::vector<int>({ 0, 1, 2, 3, 4, 5 }));
  EXPECT_TRUE(check.unconfirmed.empty());
}

TEST(LandmarkGuides, TheMapSetsAsideWhatItDoesNotFindAndNamesIt)
{
  SurfaceMapOptions options = shortSchedule();
  options.landmarksAsGuides = true;
  std::vector<std::string> warnings;
  options.log.sink = [&](Logger::Level level, const std::string& message)
  {
    if (level == Logger::Warning)
    {
      warnings.push_back(message);
    }
  };
  const std::vector<MapInput> inputs = landmarkedPair({ { 2, 3 } });
  const SurfaceMapResult result = computeSurfaceMap(inputs, options);
  EXPECT_EQ(result.setAsideLandmarks, std::vector<int>({ 2, 3 }));
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("landmark 2 set aside"), std::string::npos) << warnings[0];
  // The confirmed landmarks bind the map: T carries them, the others not;
  // and the map puts them where they belong, the swapped ones far off.
  int carried = 0;
  for (const int id : result.landmarks)
  {
    EXPECT_TRUE(id != 2 && id != 3) << id;
    carried += id >= 0;
  }
  EXPECT_EQ(carried, 4);
  const std::map<int, double> distance = landmarkDistances(inputs, result);
  EXPECT_LT(distance.at(0), 1.0);
  EXPECT_GT(distance.at(2), options.landmarkGuideTolerance);
}
