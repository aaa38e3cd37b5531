#include "FiniteDifferences.h"
#include "embedding/Decimation.h"
#include "embedding/SphereEmbedding.h"
#include "energy/EmbeddingEnergy.h"
#include "io/ObjReader.h"
#include "io/OffReader.h"
#include "io/PlyReader.h"
#include "mesh/MeshValidation.h"
#include "mesh/Primitives.h"
#include "optimisation/Objective.h"

#include <gtest/gtest.h>

#include <omp.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <random>
#include <set>

using namespace surfacemaps;
using namespace surfacemaps::testing;

namespace
{
const std::string Data = SURFACEMAPS_DATA_DIR;

PolygonMesh ellipsoid()
{
  return readObj(Data + "/ellipsoid.obj");
}
} // namespace

TEST(Decimation, ReachesATetrahedronThroughIndependentLevels)
{
  const PolygonMesh mesh = ellipsoid();
  const DecimationResult r = decimateToTetrahedron(mesh);
  ASSERT_FALSE(r.levels.empty());
  EXPECT_EQ(r.levels.back().triangles.size(), 4u);
  std::set<int> removedSoFar;
  std::size_t previousTriangles = r.triangles.size();
  for (const DecimationLevel& level : r.levels)
  {
    std::set<int> removed;
    for (const Collapse& c : level.collapses)
    {
      removed.insert(c.removed);
      EXPECT_EQ(removedSoFar.count(c.removed), 0u);
      EXPECT_NE(std::find(c.ring.begin(), c.ring.end(), c.kept), c.ring.end());
    }
    for (const Collapse& c : level.collapses)
    {
      for (int w : c.ring)
      {
        EXPECT_EQ(removed.count(w), 0u) << "ring vertex removed in the same level";
      }
    }
    // Each half-edge collapse removes a vertex and two triangles.
    EXPECT_EQ(level.triangles.size(), previousTriangles - 2 * level.collapses.size());
    previousTriangles = level.triangles.size();
    removedSoFar.insert(removed.begin(), removed.end());
  }
  EXPECT_EQ(removedSoFar.size(), mesh.points.size() - 4);
}

TEST(EmbeddingEnergy, DerivativesMatchFiniteDifferences)
{
  const PolygonMesh mesh = ellipsoid();
  std::vector<Eigen::Vector3d> sphere;
  for (const auto& p : mesh.points)
  {
    sphere.push_back((p + Eigen::Vector3d(0.1, 0.0, 0.05)).normalized());
  }
  SpherePoints points(sphere);
  EmbeddingEnergy energy;
  energy.triangles = mesh.triangles();
  energy.input = &mesh.points;
  energy.barrierWeight = 0.01;
  energy.inputArea = 2.0;
  energy.chordArea = 11.0;
  Objective objective;
  objective.addTerm(std::make_shared<ElementTerm<3, EmbeddingEnergy>>("embedding", energy));

  // Restrict the finite differences to the variables of a few vertices.
  Eigen::VectorXd g;
  Eigen::SparseMatrix<double> H;
  const double e = objective.hessian(points, -1.0, g, H);
  EXPECT_NEAR(e, objective.value(points), 1e-12 * std::abs(e));
  const Eigen::MatrixXd full = Eigen::MatrixXd(H).selfadjointView<Eigen::Upper>();
  const std::vector<int> vars = { 0, 1, 14, 15, 300, 301 };
  auto f = [&](const Eigen::VectorXd& y)
  {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(points.numberOfVariables());
    for (std::size_t k = 0; k < vars.size(); ++k)
    {
      x[vars[k]] = y[k];
    }
    SpherePoints moved = points;
    moved.retract(x, 1.0);
    return objective.value(moved);
  };
  const Eigen::VectorXd y0 = Eigen::VectorXd::Zero(vars.size());
  const Eigen::VectorXd fdG = finiteDifferenceGradient(f, y0);
  const Eigen::MatrixXd fdH = finiteDifferenceHessian(f, y0);
  Eigen::VectorXd gSub(vars.size());
  Eigen::MatrixXd hSub(vars.size(), vars.size());
  for (std::size_t a = 0; a < vars.size(); ++a)
  {
    gSub[a] = g[vars[a]];
    for (std::size_t b = 0; b < vars.size(); ++b)
    {
      hSub(a, b) = full(vars[a], vars[b]);
    }
  }
  EXPECT_LT(relativeError(gSub, fdG), 1e-6);
  EXPECT_LT(relativeError(hSub, fdH), 1e-4);
}

TEST(EmbeddingEnergy, DistortionIsOneForTheSphereItself)
{
  // A fine icosphere is nearly its own chord mesh: distortion close to 1.
  const PolygonMesh ico = makeIcosphere(3);
  EXPECT_NEAR(embeddingDistortion(ico.points, ico.points, ico.triangles()), 1.0, 1e-12);
  std::vector<Eigen::Vector3d> stretched = ico.points;
  for (auto& p : stretched)
  {
    p.x() *= 2.0;
  }
  EXPECT_GT(embeddingDistortion(stretched, ico.points, ico.triangles()), 1.1);
}

TEST(SphereEmbedding, CertifiedOnEveryDataMesh)
{
  const std::vector<PolygonMesh> meshes = { readObj(Data + "/ellipsoid.obj"),
    readOff(Data + "/blob.off"),
    readPly(Data + "/limbs.ply"),
    readObj(Data + "/spot.obj"),
    makeTetrahedron(),
    makeOctahedron() };
  for (const PolygonMesh& mesh : meshes)
  {
    ASSERT_TRUE(validateMesh(mesh).valid());
    const SphereEmbeddingResult r = embedOnSphere(mesh);
    ASSERT_EQ(r.positions.size(), mesh.points.size());
    // Certified independently of the embedding's own check.
    const BijectivityCertificate c = certifyBijective(r.positions, mesh.triangles());
    EXPECT_TRUE(c.bijective) << c.reason;
    EXPECT_NEAR(c.degree, 1.0, 1e-9);
    for (const auto& p : r.positions)
    {
      EXPECT_NEAR(p.norm(), 1.0, 1e-12);
    }
    EXPECT_GE(r.distortion, 1.0);
    EXPECT_LT(r.distortion, 2.0) << mesh.points.size() << " vertices";
  }
}

TEST(SphereEmbedding, DeterministicForAFixedThreadCount)
{
  const PolygonMesh mesh = readOff(Data + "/blob.off");
  const SphereEmbeddingResult a = embedOnSphere(mesh);
  const SphereEmbeddingResult b = embedOnSphere(mesh);
  ASSERT_EQ(a.positions.size(), b.positions.size());
  for (std::size_t i = 0; i < a.positions.size(); ++i)
  {
    ASSERT_EQ(a.positions[i], b.positions[i]) << "vertex " << i;
  }
  EXPECT_EQ(a.newtonIterations, b.newtonIterations);
}

TEST(SphereEmbedding, ConcurrentEmbeddingsAreDeterministic)
{
  // Several embeddings at once share global state (BLAS thread count, METIS'
  // random numbers) and lend each other threads: run twice, each mesh's
  // result must not change, and must equal its embedding alone on one thread
  // and on all threads.
  const std::vector<PolygonMesh> meshes = {
    readOff(Data + "/blob.off"), readObj(Data + "/ellipsoid.obj"), readPly(Data + "/limbs.ply")
  };
  const std::vector<const PolygonMesh*> pointers = { &meshes[0], &meshes[1], &meshes[2] };
  const std::vector<SphereEmbeddingResult> first = embedAllOnSphere(pointers);
  const std::vector<SphereEmbeddingResult> second = embedAllOnSphere(pointers);
  const int threads = omp_get_max_threads();
  const SphereEmbeddingResult aloneAllThreads = embedOnSphere(meshes[2]);
  omp_set_num_threads(1);
  const SphereEmbeddingResult alone = embedOnSphere(meshes[2]);
  omp_set_num_threads(threads);
  ASSERT_EQ(first.size(), 3u);
  for (std::size_t m = 0; m < 3; ++m)
  {
    EXPECT_TRUE(first[m].certificate.bijective);
    ASSERT_EQ(first[m].positions.size(), meshes[m].points.size());
    for (std::size_t i = 0; i < first[m].positions.size(); ++i)
    {
      ASSERT_EQ(first[m].positions[i], second[m].positions[i]) << "mesh " << m << " vertex " << i;
    }
  }
  for (std::size_t i = 0; i < alone.positions.size(); ++i)
  {
    ASSERT_EQ(first[2].positions[i], alone.positions[i]) << "vertex " << i;
    ASSERT_EQ(first[2].positions[i], aloneAllThreads.positions[i]) << "vertex " << i;
  }
}

TEST(SphereEmbedding, FailureNamesTheMesh)
{
  PolygonMesh torus = makeTorus(12, 8);
  const PolygonMesh ok = makeOctahedron();
  try
  {
    embedAllOnSphere({ &ok, &torus });
    FAIL() << "a torus has no sphere embedding";
  }
  catch (const EmbeddingFailure& e)
  {
    EXPECT_EQ(e.index, 1);
  }
}

namespace
{
// Several reports, none below the one before, the last exactly 1.
void expectProgressRisesToOne(const std::vector<double>& reported)
{
  ASSERT_GT(reported.size(), 3u);
  for (std::size_t i = 1; i < reported.size(); ++i)
  {
    EXPECT_GE(reported[i], reported[i - 1]);
  }
  EXPECT_EQ(reported.back(), 1.0);
}
} // namespace

TEST(SphereEmbedding, TooDistortedEverywhereKeepsTheLeastDistortedAttempt)
{
  // No attempt can reach distortion 1 (an ellipsoid is no sphere). The first
  // gives up at its first level above it (a stronger barrier follows); the
  // second and third run to the end, both certified and too distorted, and
  // the result is the less distorted of them, not the last (the barrier
  // alone, which minimises no distortion).
  const PolygonMesh mesh = ellipsoid();
  std::vector<double> distortions;
  int abandoned = 0;
  SphereEmbeddingOptions options;
  options.maxDistortion = 1.0;
  options.log.sink = [&](Logger::Level, const std::string& message)
  {
    const std::string key = "(distortion ";
    const auto at = message.find(key);
    if (message.find("sphere embedding attempt") == 0 && at != std::string::npos)
    {
      distortions.push_back(std::stod(message.substr(at + key.size())));
    }
    if (message.find("attempt 1 failed: nearly degenerate triangles on the sphere at") !=
      std::string::npos)
    {
      ++abandoned;
    }
  };
  const SphereEmbeddingResult result = embedOnSphere(mesh, options);
  EXPECT_EQ(abandoned, 1);
  ASSERT_EQ(distortions.size(), 2u);
  EXPECT_TRUE(result.certificate.bijective);
  const auto least = std::min_element(distortions.begin(), distortions.end());
  // The messages print six decimals.
  EXPECT_NEAR(result.distortion, *least, 1e-6);
  EXPECT_LT(result.distortion, distortions.back() - 1e-3);
  EXPECT_EQ(result.attempt, 2 + static_cast<int>(least - distortions.begin()));
}

TEST(SphereEmbedding, FinalIterationsGoOnWhileATriangleIsSqueezed)
{
  // After two final iterations some triangle has the smallest ratio r of its
  // share of the sphere to its share of the area. Asking for 1.5 r makes the
  // final iterations go on, until no triangle is below it or the cap; with
  // the check off they stop at two. Both runs are the same up to there.
  const PolygonMesh mesh = readPly(Data + "/limbs.ply");
  SphereEmbeddingOptions options;
  options.finalIterations = 2;
  options.finalTolerance = 0.0;
  options.finalIterationsSqueezed = 40;
  options.squeezedRatio = 0.0;
  const SphereEmbeddingResult off = embedOnSphere(mesh, options);

  // The reported ratio, recomputed from the positions.
  const auto triangles = mesh.triangles();
  std::vector<double> sphereShare, areaShare;
  for (const auto& t : triangles)
  {
    const auto& p = off.positions;
    const auto& x = mesh.points;
    sphereShare.push_back((p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]).norm());
    areaShare.push_back((x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).norm());
  }
  const double sphereTotal = std::accumulate(sphereShare.begin(), sphereShare.end(), 0.0);
  const double areaTotal = std::accumulate(areaShare.begin(), areaShare.end(), 0.0);
  double smallest = std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < triangles.size(); ++f)
  {
    smallest = std::min(smallest, (sphereShare[f] / sphereTotal) / (areaShare[f] / areaTotal));
  }
  EXPECT_NEAR(off.smallestAreaRatio, smallest, 1e-12 * smallest);
  ASSERT_GT(off.smallestAreaRatio, 0.0);
  ASSERT_LT(off.smallestAreaRatio, 1.0);

  options.squeezedRatio = 1.5 * off.smallestAreaRatio;
  const SphereEmbeddingResult on = embedOnSphere(mesh, options);
  EXPECT_TRUE(on.certificate.bijective);
  const int extra = on.newtonIterations - off.newtonIterations;
  EXPECT_GE(extra, 1);
  EXPECT_LE(extra, 38);
  EXPECT_TRUE(on.smallestAreaRatio >= options.squeezedRatio || extra == 38)
    << on.smallestAreaRatio << " after " << extra << " more iterations";
}

TEST(SphereEmbedding, ProgressIsMonotoneAndAbortStops)
{
  const PolygonMesh mesh = ellipsoid();
  SphereEmbeddingOptions options;
  std::vector<double> reported;
  options.progress = [&](double f)
  {
    reported.push_back(f);
    return true;
  };
  embedOnSphere(mesh, options);
  expectProgressRisesToOne(reported);

  // A retried attempt goes on from where the failed one stopped: with no
  // distortion acceptable, all three attempts run.
  reported.clear();
  SphereEmbeddingOptions retrying = options;
  retrying.maxDistortion = 1.0;
  embedOnSphere(mesh, retrying);
  expectProgressRisesToOne(reported);

  int calls = 0;
  options.progress = [&](double) { return ++calls < 3; };
  EXPECT_THROW(embedOnSphere(mesh, options), Aborted);
  EXPECT_EQ(calls, 3);
}
