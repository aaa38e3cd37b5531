// Turning one embedding onto another without landmarks: the rotation of a
// rigidly moved, differently meshed copy is found, a symmetric shape is
// reported as uncertain, and a map without landmarks finds the right
// correspondence.
#include "MapTestInputs.h"
#include "map/PreparedInput.h"
#include "map/RotationSearch.h"
#include "map/SurfaceMap.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>

using namespace surfacemaps;
using namespace surfacemaps::testing;

namespace
{

double degreesBetween(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b)
{
  return Eigen::AngleAxisd(a.transpose() * b).angle() * 180.0 / M_PI;
}

const Eigen::Vector3d Axes = bumpyAxes();
const Eigen::Matrix3d SphereTurn =
  Eigen::AngleAxisd(2.2, Eigen::Vector3d(-1.0, 0.3, 2.0).normalized()).matrix();

Eigen::Affine3d someMotion()
{
  Eigen::Affine3d motion = Eigen::Affine3d::Identity();
  motion.rotate(Eigen::AngleAxisd(0.9, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()));
  motion.pretranslate(Eigen::Vector3d(3.0, -1.0, 0.5));
  return motion;
}

std::vector<PreparedInput> prepared(const std::vector<MapInput>& inputs)
{
  return prepareInputs(inputs, landmarkVertices(inputs), SurfaceMapOptions().approximationSamples);
}

} // namespace

TEST(RotationSearch, FindsTheTurnOfAMovedCopyMeshedOtherwise)
{
  const std::vector<MapInput> inputs{ bumpyEllipsoid(3, Eigen::Matrix3d::Identity(),
                                        Eigen::Affine3d::Identity()),
    bumpyEllipsoid(2, SphereTurn, someMotion()) };
  const std::vector<PreparedInput> surfaces = prepared(inputs);
  const RotationSearchResult found = searchRotation(surfaces[0], surfaces[1]);
  // The embedding of input 1 is input 0's turned by SphereTurn: turning it
  // back is the right correspondence.
  EXPECT_LT(degreesBetween(found.rotation, SphereTurn.transpose()), 3.0);
  EXPECT_GT(found.runnerUpMisfit, 1.5 * found.misfit);
  EXPECT_GT(found.runnerUpAngle, 45.0);
}

TEST(RotationSearch, WarnsWhenASymmetricShapeFitsTwoWays)
{
  // A plain ellipsoid is the same after half a turn about any of its axes.
  const std::vector<MapInput> inputs{
    bumpyEllipsoid(3, Eigen::Matrix3d::Identity(), Eigen::Affine3d::Identity(), false),
    bumpyEllipsoid(2, SphereTurn, someMotion(), false)
  };
  std::vector<PreparedInput> surfaces = prepared(inputs);
  std::vector<std::string> warnings;
  Logger log;
  log.sink = [&](Logger::Level level, const std::string& message)
  {
    if (level == Logger::Warning)
    {
      warnings.push_back(message);
    }
  };
  alignWithoutLandmarks(surfaces, log);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("input 1"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("uncertain"), std::string::npos) << warnings[0];
}

/// How far the map of `result` carries input 0's point nearest `tip` from
/// the same point of input 1 (moved back by `motion`): T's vertex nearest
/// the tip on input 0 against its image on input 1.
double carriedMisfit(const SurfaceMapResult& result,
  const Eigen::Vector3d& tip,
  const Eigen::Affine3d& motion)
{
  std::size_t nearest = 0;
  for (std::size_t k = 0; k < result.lifted[0].size(); ++k)
  {
    if ((result.lifted[0][k] - tip).norm() < (result.lifted[0][nearest] - tip).norm())
    {
      nearest = k;
    }
  }
  return (motion.inverse() * result.lifted[1][nearest] - result.lifted[0][nearest]).norm();
}

TEST(RotationSearch, AMapWithoutLandmarksFindsTheBumps)
{
  const Eigen::Affine3d motion = someMotion();
  const std::vector<MapInput> inputs{ bumpyEllipsoid(2, Eigen::Matrix3d::Identity(),
                                        Eigen::Affine3d::Identity()),
    bumpyEllipsoid(2, SphereTurn, motion) };
  SurfaceMapOptions options;
  options.coarseIterations = 10;
  options.fineIterations = 0;
  options.refinementRounds = 0;
  const SurfaceMapResult result = computeSurfaceMap(inputs, options);
  ASSERT_TRUE(result.certificates[1].bijective);
  for (const Eigen::Vector3d& bump : bumpyTips())
  {
    const Eigen::Vector3d tip = inputs[0].mesh.points[closestVertex(inputs[0], bump)];
    EXPECT_LT(carriedMisfit(result, tip, motion), 0.1 * Axes.maxCoeff())
      << "bump at " << bump.transpose();
  }
  // Without the search the map starts from the embeddings' arbitrary turn
  // (here the test's, far from the identity): the bump is not found.
  options.landmarkFreeAlignment = false;
  const SurfaceMapResult unturned = computeSurfaceMap(inputs, options);
  const Eigen::Vector3d tip = inputs[0].mesh.points[closestVertex(inputs[0], bumpyTips()[0])];
  EXPECT_GT(carriedMisfit(unturned, tip, motion), 0.3 * Axes.maxCoeff());
}
