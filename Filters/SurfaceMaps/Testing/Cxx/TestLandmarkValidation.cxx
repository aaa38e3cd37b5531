#include "mesh/LandmarkValidation.h"
#include "mesh/Primitives.h"

#include <Eigen/Geometry>

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

namespace
{
// An icosphere with 6 landmarks at scattered vertices, and its image under `transform`
// (triangles reversed when it mirrors, so the mesh stays outward oriented).
PolygonMesh transformed(const PolygonMesh& mesh, const Eigen::Matrix3d& transform)
{
  PolygonMesh result = mesh;
  for (Eigen::Vector3d& p : result.points)
  {
    p = transform * p + Eigen::Vector3d(3.0, -1.0, 2.0);
  }
  if (transform.determinant() < 0)
  {
    for (std::size_t f = 0; f < result.numberOfFaces(); ++f)
    {
      std::swap(result.faceVertices[result.faceOffsets[f] + 1],
        result.faceVertices[result.faceOffsets[f] + 2]);
    }
  }
  return result;
}
} // namespace

TEST(LandmarkValidation, MirroredLandmarksAreFound)
{
  const PolygonMesh sphere = makeIcosphere(2);
  std::vector<int> ids(sphere.points.size(), -1);
  const int vertices[] = { 0, 7, 19, 33, 58, 101 };
  for (int k = 0; k < 6; ++k)
  {
    ids[vertices[k]] = k;
  }
  // A rotation, scaling and translation keeps every orientation.
  const Eigen::Matrix3d rotation =
    1.7 * Eigen::AngleAxisd(1.1, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const PolygonMesh turned = transformed(sphere, rotation);
  const LandmarkOrientation same = compareLandmarkOrientation(sphere, ids, turned, ids);
  EXPECT_GT(same.triples, 10);
  EXPECT_EQ(same.opposite, 0);
  // A mirror flips every decisive triple.
  const PolygonMesh mirrored = transformed(sphere, Eigen::Vector3d(-1.0, 1.0, 1.0).asDiagonal());
  const LandmarkOrientation flipped = compareLandmarkOrientation(sphere, ids, mirrored, ids);
  EXPECT_GT(flipped.triples, 10);
  EXPECT_EQ(flipped.opposite, flipped.triples);

  const std::vector<std::string> warnings = checkLandmarkMirroring(
    { &sphere, &turned, &mirrored }, { ids, ids, ids }, { "input 0", "input 1", "input 2" });
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("the landmarks of input 2 are the mirror image of those of input 0"),
    std::string::npos);
}

// Landmarks close to a plane through the centroid (both tips and a midline
// point of a tube) turn either way with noise: no evidence, no warning. Here
// the third landmark sits a little above or below the plane of the first two
// and the centroid (z = 0), on two copies of one sphere.
TEST(LandmarkValidation, NearlyPlanarTriplesDoNotVote)
{
  const PolygonMesh sphere = makeIcosphere(3);
  auto nearest = [&](const Eigen::Vector3d& target)
  {
    int best = 0;
    for (std::size_t v = 0; v < sphere.points.size(); ++v)
    {
      if ((sphere.points[v] - target).norm() < (sphere.points[best] - target).norm())
      {
        best = static_cast<int>(v);
      }
    }
    return best;
  };
  auto landmarks = [&](double lift)
  {
    std::vector<int> ids(sphere.points.size(), -1);
    ids[nearest(Eigen::Vector3d(1, 0, 0))] = 0;
    ids[nearest(Eigen::Vector3d(0, 1, 0))] = 1;
    ids[nearest(Eigen::Vector3d(-0.7, -0.7, lift).normalized())] = 2;
    return ids;
  };
  const std::vector<int> above = landmarks(0.06);
  const std::vector<int> below = landmarks(-0.06);
  const LandmarkOrientation o = compareLandmarkOrientation(sphere, above, sphere, below);
  EXPECT_EQ(o.triples, 0);
  EXPECT_TRUE(
    checkLandmarkMirroring({ &sphere, &sphere }, { above, below }, { "input 0", "input 1" }).empty());
  // Well off the plane the same triple decides, and the two sides disagree.
  const LandmarkOrientation far =
    compareLandmarkOrientation(sphere, landmarks(0.8), sphere, landmarks(-0.8));
  EXPECT_EQ(far.triples, 1);
  EXPECT_EQ(far.opposite, 1);
}
