// Inputs added to an existing map (addToSurfaceMap) on small inputs with
// short schedules.
#include "MapTestInputs.h"
#include "base/Error.h"
#include "geometry/MapMetrics.h"
#include "map/AddToMap.h"
#include "map/SurfaceMap.h"

#include <gtest/gtest.h>

using namespace surfacemaps;
using namespace surfacemaps::testing;

namespace
{
SurfaceMapOptions populationSchedule()
{
  SurfaceMapOptions options;
  options.pairs = PairScheme::Mean;
  options.refinementRounds = 0;
  options.landmarkIterations = 20;
  options.coarseIterations = 4;
  options.fineIterations = 4;
  options.targetError = 5e-3;
  return options;
}

const std::vector<Eigen::Vector3d> Directions{ { 0, 0, 1 }, { 1, 0, 0 }, { 0, 1, 0.2 } };

/// Three existing inputs and one to add, with the same three landmarks.
std::vector<MapInput> population()
{
  std::vector<MapInput> inputs{ icosphereInput(2, 0.0, { 1.0, 1.0, 1.0 }, 0.3),
    icosphereInput(3, 0.3, { 1.4, 1.0, 0.8 }),
    icosphereInput(2, -0.2, { 0.8, 1.2, 1.0 }, 0.2),
    icosphereInput(3, 0.6, { 1.2, 0.9, 1.1 }, 0.25) };
  for (MapInput& input : inputs)
  {
    setLandmarks(input, Directions);
  }
  return inputs;
}

ExistingMap existingOf(const SurfaceMapResult& r)
{
  return { r.triangles, r.spherePositions, r.lifted, r.landmarks };
}

/// The inputs as the existing map used them: its embeddings f_j.
std::vector<MapInput> asUsed(std::vector<MapInput> inputs, const SurfaceMapResult& r)
{
  for (std::size_t j = 0; j < r.inputSpherePositions.size(); ++j)
  {
    inputs[j].spherePositions = r.inputSpherePositions[j];
  }
  return inputs;
}

double largestDistance(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b)
{
  double d = 0.0;
  for (std::size_t v = 0; v < a.size(); ++v)
  {
    d = std::max(d, (a[v] - b[v]).norm());
  }
  return d;
}
} // namespace

// The added input gets a certified map of the existing map's quality, and
// the existing inputs keep theirs: T's existing vertices stay where they were
// on every existing input, and the exact maps between existing inputs move
// by little (new vertices lie on the existing triangles).
TEST(AddToMap, AddedInputIsMappedAndTheExistingMapsStay)
{
  const std::vector<MapInput> all = population();
  const std::vector<MapInput> three(all.begin(), all.begin() + 3);
  const SurfaceMapOptions options = populationSchedule();
  const SurfaceMapResult before = computeSurfaceMap(three, options);
  const std::vector<MapInput> inputs = asUsed(all, before);
  const SurfaceMapResult after = addToSurfaceMap(existingOf(before), inputs, options);

  ASSERT_EQ(after.certificates.size(), 4u);
  for (const BijectivityCertificate& c : after.certificates)
  {
    EXPECT_TRUE(c.bijective) << c.reason;
  }
  const std::size_t nv = before.spherePositions[0].size();
  ASSERT_GE(after.spherePositions[0].size(), nv);
  EXPECT_GE(after.triangles.size(), before.triangles.size());
  for (int j = 0; j < 3; ++j)
  {
    // The existing embeddings and lifts, bit for bit on the existing vertices.
    EXPECT_EQ(after.inputSpherePositions[j], before.inputSpherePositions[j]);
    const std::vector<Eigen::Vector3d> kept(
      after.spherePositions[j].begin(), after.spherePositions[j].begin() + nv);
    EXPECT_EQ(kept, before.spherePositions[j]) << "input " << j;
    EXPECT_LT(largestDistance(before.lifted[j], after.lifted[j]), 1e-12) << "input " << j;
  }
  for (std::size_t v = 0; v < nv; ++v)
  {
    EXPECT_EQ(after.landmarks[v], before.landmarks[v]);
  }
  EXPECT_LT(after.landmarkError, 1e-9); // kept landmarks, the added input's as well
  const double existingSD =
    measureMap(before.lifted[0], before.lifted[2], before.triangles).symmetricDirichlet;
  const MapMetrics added = measureMap(after.lifted[0], after.lifted[3], after.triangles);
  EXPECT_EQ(added.degenerateTriangles, 0);
  EXPECT_LT(added.symmetricDirichlet, 2.0);
  EXPECT_LT(added.symmetricDirichlet, 1.5 * std::max(existingSD, 1.0));
  // The exact map 0 -> 1 between existing inputs, before and after.
  const std::vector<Eigen::Vector3d> exactBefore = mappedVertices(before, three, 0, 1);
  const std::vector<Eigen::Vector3d> exactAfter = mappedVertices(after, inputs, 0, 1);
  EXPECT_LT(largestDistance(exactBefore, exactAfter), 1e-3);
  EXPECT_EQ(mappedVertices(after, inputs, 0, 3).size(), inputs[0].mesh.points.size());
}

// Two inputs added in one call: each into the map of the ones before it.
TEST(AddToMap, SeveralInputsAreAddedOneAfterTheOther)
{
  std::vector<MapInput> all = population();
  all.push_back(icosphereInput(2, -0.4, { 1.1, 1.0, 0.9 }, 0.1));
  setLandmarks(all.back(), Directions);
  const std::vector<MapInput> two(all.begin(), all.begin() + 2);
  const SurfaceMapOptions options = populationSchedule();
  const SurfaceMapResult before = computeSurfaceMap(two, options);
  const SurfaceMapResult after = addToSurfaceMap(existingOf(before), asUsed(all, before), options);
  ASSERT_EQ(after.certificates.size(), 5u);
  for (const BijectivityCertificate& c : after.certificates)
  {
    EXPECT_TRUE(c.bijective) << c.reason;
  }
  for (int i = 2; i < 5; ++i)
  {
    EXPECT_LT(measureMap(after.lifted[0], after.lifted[i], after.triangles).symmetricDirichlet, 2.0)
      << "input " << i;
  }
  // Every addition's phases, in turn (mapped alone: landmarks, coarse, fine).
  EXPECT_EQ(after.phases.size(), 9u);
}

// What adding cannot keep or does not fit is refused, naming the defect.
TEST(AddToMap, BadExistingMapsAndInputsAreRefused)
{
  const std::vector<MapInput> all = population();
  const std::vector<MapInput> three(all.begin(), all.begin() + 3);
  const SurfaceMapOptions options = populationSchedule();
  const SurfaceMapResult before = computeSurfaceMap(three, options);
  const std::vector<MapInput> inputs = asUsed(all, before);
  const ExistingMap existing = existingOf(before);
  auto message = [&](const ExistingMap& map,
                   const std::vector<MapInput>& given,
                   const SurfaceMapOptions& o) -> std::string
  {
    try
    {
      addToSurfaceMap(map, given, o);
    }
    catch (const InputError& e)
    {
      return e.what();
    }
    return "no error";
  };
  SurfaceMapOptions refining = options;
  refining.refinementRounds = 1;
  EXPECT_NE(message(existing, inputs, refining).find("refinement rounds"), std::string::npos);
  EXPECT_NE(message(existing, three, options).find("nothing to add"), std::string::npos);

  std::vector<MapInput> lacking = inputs;
  std::replace(lacking[3].landmarks.begin(), lacking[3].landmarks.end(), 2, -1);
  EXPECT_NE(
    message(existing, lacking, options).find("input 3 has no landmark 2"), std::string::npos);

  ExistingMap folded = existing;
  std::swap(folded.spherePositions[1][0], folded.spherePositions[1][1]);
  EXPECT_NE(
    message(folded, inputs, options).find("on sphere 1 is not bijective"), std::string::npos);

  ExistingMap short_ = existing;
  short_.lifted[2].pop_back();
  EXPECT_NE(message(short_, inputs, options).find("T on input 2"), std::string::npos);
}
