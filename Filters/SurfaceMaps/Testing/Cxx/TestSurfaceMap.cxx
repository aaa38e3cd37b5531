// The surface map schedule on small inputs with short schedules.
#include "MapTestInputs.h"
#include "base/Error.h"
#include "geometry/MapMetrics.h"
#include "geometry/SphereLocator.h"
#include "map/MappingOrder.h"
#include "map/SurfaceMap.h"

#include <gtest/gtest.h>

using namespace surfacemaps;
using namespace surfacemaps::testing;

namespace
{
SurfaceMapOptions shortSchedule(int coarse, int fine)
{
  SurfaceMapOptions options;
  options.landmarkIterations = 20;
  options.coarseIterations = coarse;
  options.fineIterations = fine;
  options.targetError = 5e-3;
  return options;
}

std::vector<MapInput> landmarkPair()
{
  std::vector<MapInput> inputs{ icosphereInput(3, 0.0, { 1.0, 1.0, 1.0 }, 0.3),
    icosphereInput(3, 0.5, { 1.4, 1.0, 0.8 }) };
  setLandmarks(inputs[0], { { 0, 0, 1 }, { 1, 0, 0 }, { 0, 1, 0.2 } });
  setLandmarks(inputs[1], { { 0.1, 0, 1 }, { 1, 0.2, 0 }, { -0.1, 1, 0.3 } });
  return inputs;
}

void expectCertified(const SurfaceMapResult& r)
{
  for (const BijectivityCertificate& c : r.certificates)
  {
    EXPECT_TRUE(c.bijective) << c.reason;
  }
}
} // namespace

TEST(SurfaceMap, PairModes)
{
  using P = std::vector<std::array<int, 2>>;
  EXPECT_EQ(mapPairs(PairScheme::Star, 4), (P{ { 0, 1 }, { 0, 2 }, { 0, 3 } }));
  EXPECT_EQ(mapPairs(PairScheme::Sequence, 3), (P{ { 0, 1 }, { 1, 2 } }));
  EXPECT_EQ(mapPairs(PairScheme::Cycle, 3), (P{ { 0, 1 }, { 1, 2 }, { 2, 0 } }));
  EXPECT_EQ(mapPairs(PairScheme::All, 3), (P{ { 0, 1 }, { 0, 2 }, { 1, 2 } }));
  // The mean's pairs count its map terms: each input in two.
  EXPECT_EQ(mapPairs(PairScheme::Mean, 3), mapPairs(PairScheme::Cycle, 3));
  EXPECT_TRUE(mapPairs(PairScheme::Star, 1).empty());
}

TEST(SurfaceMap, LandmarkPhaseCoarsensAndReachesTheLandmarks)
{
  SurfaceMapOptions options = shortSchedule(0, 0);
  options.coarseIterations = 0;
  options.fineIterations = 0;
  options.relaxLandmarkPhase = false; // ends as soon as the landmarks are reached
  const std::vector<MapInput> inputs = landmarkPair();
  const SurfaceMapResult r = computeSurfaceMap(inputs, options);
  expectCertified(r);
  ASSERT_EQ(r.phases.size(), 1u);
  EXPECT_EQ(r.phases[0].kind, PhaseKind::Landmarks);
  EXPECT_TRUE(r.phases[0].converged);
  EXPECT_LT(r.phases[0].landmarkError, options.landmarkTolerance);
  EXPECT_LT(r.lifted[0].size(), inputs[0].mesh.points.size() / 10);
}

TEST(SurfaceMap, LandmarkPhaseRelaxesWithoutChangingTheVertexCount)
{
  SurfaceMapOptions options = shortSchedule(0, 0);
  options.coarseIterations = 0;
  options.fineIterations = 0;
  options.relaxLandmarkPhase = false;
  const std::vector<MapInput> inputs = landmarkPair();
  const SurfaceMapResult quick = computeSurfaceMap(inputs, options);
  options.relaxLandmarkPhase = true;
  const SurfaceMapResult relaxed = computeSurfaceMap(inputs, options);
  expectCertified(relaxed);
  ASSERT_EQ(relaxed.phases.size(), 1u);
  EXPECT_GT(relaxed.phases[0].iterations, quick.phases[0].iterations);
  EXPECT_TRUE(
    relaxed.phases[0].converged || relaxed.phases[0].iterations == options.landmarkIterations);
  EXPECT_LT(relaxed.phases[0].landmarkError, options.landmarkTolerance);
  // The relaxation neither splits nor collapses.
  EXPECT_EQ(relaxed.lifted[0].size(), quick.lifted[0].size());
  EXPECT_EQ(relaxed.phases[0].splits, quick.phases[0].splits);
  EXPECT_EQ(relaxed.phases[0].collapses, quick.phases[0].collapses);
}

TEST(SurfaceMap, KeptLandmarksHoldExactly)
{
  const std::vector<MapInput> inputs = landmarkPair();
  const SurfaceMapResult r = computeSurfaceMap(inputs, shortSchedule(3, 3));
  expectCertified(r);
  EXPECT_EQ(r.landmarkError, 0.0);
  int found = 0;
  for (std::size_t v = 0; v < r.landmarks.size(); ++v)
  {
    if (r.landmarks[v] < 0)
    {
      continue;
    }
    ++found;
    for (int i = 0; i < 2; ++i)
    {
      const auto& ids = inputs[i].landmarks;
      const int w =
        static_cast<int>(std::find(ids.begin(), ids.end(), r.landmarks[v]) - ids.begin());
      EXPECT_EQ(r.lifted[i][v], inputs[i].mesh.points[w]);
    }
  }
  EXPECT_EQ(found, 3);
}

TEST(SurfaceMap, SmallerTargetErrorGivesAFinerTriangulation)
{
  const std::vector<MapInput> inputs{ icosphereInput(3, 0.0, { 1.0, 1.0, 1.0 }, 0.5),
    icosphereInput(3, 0.2, { 1.3, 1.0, 0.8 }, 0.2) };
  SurfaceMapOptions options = shortSchedule(3, 6);
  options.targetError = 1e-2;
  const SurfaceMapResult coarse = computeSurfaceMap(inputs, options);
  options.targetError = 2e-3;
  const SurfaceMapResult fine = computeSurfaceMap(inputs, options);
  expectCertified(coarse);
  expectCertified(fine);
  EXPECT_GT(fine.lifted[0].size(), 1.3 * coarse.lifted[0].size());
}

TEST(SurfaceMap, SingleInputIsABijectiveRemeshing)
{
  const std::vector<MapInput> inputs{ icosphereInput(3, 0.0, { 1.0, 0.8, 0.6 }, 0.4) };
  const SurfaceMapResult r = computeSurfaceMap(inputs, shortSchedule(3, 5));
  expectCertified(r);
  ASSERT_EQ(r.lifted.size(), 1u);
  EXPECT_GT(r.lifted[0].size(), 20u);
  EXPECT_EQ(mappedVertices(r, inputs, 0, 0), inputs[0].mesh.points); // the identity, exactly
  // Every lifted vertex lies on its source triangle of the input.
  for (std::size_t v = 0; v < r.lifted[0].size(); ++v)
  {
    const SurfacePoint& p = r.sourcePoints[0][v];
    EXPECT_NEAR(p.barycentric.sum(), 1.0, 1e-12);
    EXPECT_GE(p.barycentric.minCoeff(), -1e-9);
  }
}

TEST(SurfaceMap, ThreeInputsShareOneCertifiedTriangulation)
{
  const std::vector<MapInput> inputs{ icosphereInput(2, 0.0, { 1.0, 1.0, 1.0 }, 0.3),
    icosphereInput(3, 0.3, { 1.4, 1.0, 0.8 }),
    icosphereInput(2, -0.2, { 0.8, 1.2, 1.0 }, 0.2) };
  SurfaceMapOptions options = shortSchedule(3, 4);
  options.pairs = PairScheme::All;
  const SurfaceMapResult r = computeSurfaceMap(inputs, options);
  ASSERT_EQ(r.certificates.size(), 3u);
  expectCertified(r);
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_EQ(r.lifted[i].size(), r.lifted[0].size());
    EXPECT_EQ(mappedVertices(r, inputs, 0, i).size(), inputs[0].mesh.points.size());
    const MapMetrics m = measureMap(r.lifted[0], r.lifted[i], r.triangles);
    EXPECT_EQ(m.degenerateTriangles, 0);
    EXPECT_LT(m.symmetricDirichlet, 2.0);
  }
}

// Each input against the mean shape instead of pairs: certified, and the maps
// between the inputs as little distorted as with pairs.
TEST(SurfaceMap, MeanShapeDistortionCertifiesAndFitsEveryInput)
{
  std::vector<MapInput> inputs{ icosphereInput(2, 0.0, { 1.0, 1.0, 1.0 }, 0.3),
    icosphereInput(3, 0.3, { 1.4, 1.0, 0.8 }),
    icosphereInput(2, -0.2, { 0.8, 1.2, 1.0 }, 0.2) };
  SurfaceMapOptions options = shortSchedule(3, 4);
  options.pairs = PairScheme::Mean;
  const SurfaceMapResult r = computeSurfaceMap(inputs, options);
  ASSERT_EQ(r.certificates.size(), 3u);
  expectCertified(r);
  for (int i = 1; i < 3; ++i)
  {
    const MapMetrics m = measureMap(r.lifted[0], r.lifted[i], r.triangles);
    EXPECT_EQ(m.degenerateTriangles, 0);
    EXPECT_LT(m.symmetricDirichlet, 2.0);
  }
}

// With pairs that name no input (all, mean) the map does not depend on the
// order of the inputs: the same T and the same lifts, bit for bit, in any
// order; the most typical input is mapped first. Star keeps the order given.
TEST(SurfaceMap, OrderFreePairingsGiveTheSameMapInAnyOrder)
{
  const std::vector<MapInput> inputs{ icosphereInput(2, 0.0, { 1.0, 1.0, 1.0 }, 0.3),
    icosphereInput(2, 0.3, { 1.4, 1.0, 0.8 }),
    icosphereInput(2, -0.2, { 0.8, 1.2, 1.0 }, 0.2) };
  SurfaceMapOptions options = shortSchedule(2, 2);
  options.pairs = PairScheme::Mean;
  const SurfaceMapResult r = computeSurfaceMap(inputs, options);
  expectCertified(r);
  for (const std::vector<int>& order : { std::vector<int>{ 2, 0, 1 }, std::vector<int>{ 1, 2, 0 } })
  {
    std::vector<MapInput> permuted;
    for (const int i : order)
    {
      permuted.push_back(inputs[i]);
    }
    const SurfaceMapResult p = computeSurfaceMap(permuted, options);
    EXPECT_EQ(p.triangles, r.triangles);
    for (std::size_t k = 0; k < order.size(); ++k)
    {
      EXPECT_EQ(p.lifted[k], r.lifted[order[k]]) << "input " << k;
      EXPECT_EQ(p.spherePositions[k], r.spherePositions[order[k]]) << "input " << k;
      EXPECT_EQ(mappedVertices(p, permuted, k, 0), mappedVertices(r, inputs, order[k], order[0]));
    }
  }
  // Ellipsoids stretched 1, 1.5 and 2.25 times along x: the middle one first.
  const std::vector<MapInput> stretched{ icosphereInput(2, 0.0, { 2.25, 1.0, 1.0 }),
    icosphereInput(2, 0.0, { 1.0, 1.0, 1.0 }),
    icosphereInput(2, 0.0, { 1.5, 1.0, 1.0 }) };
  EXPECT_EQ(mappingOrder(stretched, PairScheme::Mean).front(), 2);
  EXPECT_EQ(mappingOrder(stretched, PairScheme::All).front(), 2);
  EXPECT_EQ(mappingOrder(stretched, PairScheme::Star), (std::vector<int>{ 0, 1, 2 }));
  EXPECT_EQ(mappingOrder(stretched, PairScheme::Sequence), (std::vector<int>{ 0, 1, 2 }));
}

// Conjugate gradients preconditioned per embedding (BlockSolveInputs) solve
// the same Newton systems as the coupled factorisation: on three inputs the
// schedule must end certified at nearly the same energy.
TEST(SurfaceMap, BlockSolveReachesTheCoupledSolvesEnergy)
{
  const std::vector<MapInput> inputs{ icosphereInput(2, 0.0, { 1.0, 1.0, 1.0 }, 0.3),
    icosphereInput(3, 0.3, { 1.4, 1.0, 0.8 }),
    icosphereInput(2, -0.2, { 0.8, 1.2, 1.0 }, 0.2) };
  SurfaceMapOptions options = shortSchedule(3, 4);
  options.refinementRounds = 0;
  options.blockSolveInputs = 0;
  const SurfaceMapResult coupled = computeSurfaceMap(inputs, options);
  options.blockSolveInputs = 3;
  const SurfaceMapResult blocks = computeSurfaceMap(inputs, options);
  expectCertified(coupled);
  expectCertified(blocks);
  const double e = coupled.phases.back().energy;
  EXPECT_NEAR(blocks.phases.back().energy, e, 0.02 * e);
}

TEST(SurfaceMap, ProgressIsMonotoneAndCanAbort)
{
  const std::vector<MapInput> inputs = landmarkPair();
  SurfaceMapOptions options = shortSchedule(3, 3);
  std::vector<double> fractions;
  options.progress = [&](const SurfaceMapProgress& p)
  {
    fractions.push_back(p.fraction);
    return true;
  };
  computeSurfaceMap(inputs, options);
  ASSERT_GE(fractions.size(), 6u);
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_LE(fractions.back(), 1.0);

  int calls = 0;
  options.progress = [&](const SurfaceMapProgress&) { return ++calls < 2; };
  EXPECT_THROW(computeSurfaceMap(inputs, options), Aborted);
  EXPECT_EQ(calls, 2);
}

TEST(SurfaceMap, InconsistentInputIsRejected)
{
  std::vector<MapInput> inputs = landmarkPair();
  inputs[1].landmarks[0] = 9; // landmark 9 only on input 1
  EXPECT_THROW(computeSurfaceMap(inputs), InputError);
  inputs = landmarkPair();
  inputs[1].spherePositions.pop_back();
  EXPECT_THROW(computeSurfaceMap(inputs), InputError);
  EXPECT_THROW(computeSurfaceMap({}), InputError);
}

TEST(SurfaceMap, RefinementRunsWhereTheExactMapIsDistorted)
{
  const std::vector<MapInput> inputs = landmarkPair();
  SurfaceMapOptions options = shortSchedule(3, 4);
  options.refinementRounds = 1;
  options.refinementIterations = 3;
  options.refinementDistortion = 1e9; // nothing that distorted: no refinement
  const SurfaceMapResult plain = computeSurfaceMap(inputs, options);
  EXPECT_EQ(plain.phases.back().kind, PhaseKind::Fine);
  // Every input triangle is distorted beyond 1 + 1e-9: the sizing shrinks
  // everywhere, so the refinement adds vertices, and the map stays certified.
  options.refinementDistortion = 1.0 + 1e-9;
  const SurfaceMapResult refined = computeSurfaceMap(inputs, options);
  expectCertified(refined);
  ASSERT_EQ(refined.phases.back().kind, PhaseKind::Refine);
  EXPECT_GE(refined.phases.back().iterations, 1);
  EXPECT_GT(refined.phases.back().vertices, plain.phases.back().vertices);
}

// Against the mean shape the refinement measures each input's map onto its
// own approximating mesh: nothing distorted, nothing refined; everything
// distorted, T grows on every input and stays certified.
TEST(SurfaceMap, MeanShapeRefinementMeasuresEachInputsOwnMap)
{
  const std::vector<MapInput> inputs{ icosphereInput(2, 0.0, { 1.0, 1.0, 1.0 }, 0.3),
    icosphereInput(2, 0.3, { 1.4, 1.0, 0.8 }),
    icosphereInput(2, -0.2, { 0.8, 1.2, 1.0 }, 0.2) };
  SurfaceMapOptions options = shortSchedule(2, 3);
  options.pairs = PairScheme::Mean;
  options.refinementRounds = 1;
  options.refinementIterations = 2;
  options.refinementDistortion = 1e9;
  const SurfaceMapResult plain = computeSurfaceMap(inputs, options);
  EXPECT_EQ(plain.phases.back().kind, PhaseKind::Fine);
  options.refinementDistortion = 1.0 + 1e-9;
  const SurfaceMapResult refined = computeSurfaceMap(inputs, options);
  expectCertified(refined);
  ASSERT_EQ(refined.phases.back().kind, PhaseKind::Refine);
  EXPECT_GT(refined.phases.back().vertices, plain.phases.back().vertices);
}

TEST(SurfaceMap, LaterRefinementRoundsIterateWhileSqueezesRemain)
{
  const std::vector<MapInput> inputs = landmarkPair();
  SurfaceMapOptions options = shortSchedule(3, 4);
  options.refinementRounds = 3;
  options.refinementIterations = 2;
  options.refinementDistortion = 1.0 + 1e-9; // the first round always runs
  auto refineRounds = [&](const SurfaceMapResult& r)
  {
    int rounds = 0;
    for (const MapPhaseReport& phase : r.phases)
    {
      rounds += phase.kind == PhaseKind::Refine;
    }
    return rounds;
  };
  options.squeezeDistortion = 1e9; // no squeeze: the later rounds do not run
  EXPECT_EQ(refineRounds(computeSurfaceMap(inputs, options)), 1);
  options.squeezeDistortion = 1.0 + 1e-9; // everything counts as squeezed
  const SurfaceMapResult all = computeSurfaceMap(inputs, options);
  expectCertified(all);
  EXPECT_EQ(refineRounds(all), 3);
  // They keep the sizing: with the first round's growth almost 0 (sizing
  // times 1 / sqrt(1 + 1e-6)), T stays near its size after that round,
  // where halving the sizing everywhere would about quadruple it.
  options.refinementGrowth = 1e-6;
  const SurfaceMapResult kept = computeSurfaceMap(inputs, options);
  options.refinementRounds = 1;
  const SurfaceMapResult first = computeSurfaceMap(inputs, options);
  expectCertified(kept);
  EXPECT_LT(kept.phases.back().vertices, 1.5 * first.phases.back().vertices);
  options.refinementGrowth = SurfaceMapOptions().refinementGrowth;
  // Nothing above the first threshold, squeezes above a lower one: the
  // first round has nothing to refine, the later ones still run.
  options.refinementRounds = 2;
  options.refinementDistortion = 1e9;
  EXPECT_EQ(refineRounds(computeSurfaceMap(inputs, options)), 1);
}

TEST(SurfaceMap, RefinementGrowthBoundsTheFirstRound)
{
  // Every triangle distorted (area fraction 1): growth 1e9 halves the sizing
  // everywhere, growth 1e-6 leaves it (1 / sqrt(1 + 1e-6)), so only the
  // former adds many vertices.
  const std::vector<MapInput> inputs = landmarkPair();
  SurfaceMapOptions options = shortSchedule(3, 4);
  options.refinementRounds = 1;
  options.refinementIterations = 3;
  options.refinementDistortion = 1.0 + 1e-9;
  options.refinementGrowth = 1e-6;
  const SurfaceMapResult kept = computeSurfaceMap(inputs, options);
  options.refinementGrowth = 1e9;
  const SurfaceMapResult halved = computeSurfaceMap(inputs, options);
  expectCertified(halved);
  ASSERT_EQ(kept.phases.back().kind, PhaseKind::Refine);
  ASSERT_EQ(halved.phases.back().kind, PhaseKind::Refine);
  EXPECT_GT(halved.phases.back().vertices, 1.5 * kept.phases.back().vertices);
}

TEST(SurfaceMap, ErrorBoundHoldsAtEveryInputVertex)
{
  const std::vector<MapInput> inputs = landmarkPair();
  SurfaceMapOptions options = shortSchedule(3, 4);
  options.targetError = 1e-2; // leaves vertices beyond the bound: refinement must run
  options.maxError = 2e-3;
  options.boundRefinementIterations = 4;
  options.boundIterations = 4;
  const SurfaceMapResult r = computeSurfaceMap(inputs, options);
  expectCertified(r);
  int refinements = 0;
  for (const MapPhaseReport& phase : r.phases)
  {
    refinements += phase.kind == PhaseKind::Refine;
  }
  EXPECT_GT(refinements, 0);
  EXPECT_EQ(r.phases.back().kind, PhaseKind::Bound);
  for (std::size_t i = 0; i < inputs.size(); ++i)
  {
    const PolygonMesh& mesh = inputs[i].mesh;
    Eigen::Vector3d lo = mesh.points[0], hi = mesh.points[0];
    for (const Eigen::Vector3d& p : mesh.points)
    {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    const double bound = options.maxError * (hi - lo).norm();
    EXPECT_NEAR(r.errorBound[i], bound, 1e-12 * bound);
    // Independently of the engine's bookkeeping: every input vertex's base
    // point, from the outputs (its sphere point located in T's embedding i,
    // the same barycentric coordinates on T lifted onto input i).
    const SphereLocator onT(r.spherePositions[i], r.triangles);
    double largest = 0.0;
    for (std::size_t v = 0; v < mesh.points.size(); ++v)
    {
      const SphereLocation loc = onT.locate(r.inputSpherePositions[i][v]);
      const auto& t = r.triangles[loc.triangle];
      const Eigen::Vector3d base = loc.alpha * r.lifted[i][t[0]] + loc.beta * r.lifted[i][t[1]] +
        loc.gamma * r.lifted[i][t[2]];
      largest = std::max(largest, (base - mesh.points[v]).norm());
    }
    EXPECT_LT(largest, bound) << "input " << i;
    EXPECT_NEAR(largest, r.baseDistance[i], 1e-9 * bound) << "input " << i;
  }
}
