// The surface map's energy terms: derivatives against finite differences.
#include "FiniteDifferences.h"
#include "MapTestInputs.h"
#include "energy/ApproximationEnergy.h"
#include "energy/BarrierEnergy.h"
#include "energy/BijectivityBarrier.h"
#include "energy/CoverageEnergy.h"
#include "energy/MapDistortionEnergy.h"
#include "energy/MeshQualityEnergy.h"
#include "map/CommonTriangulation.h"
#include "map/MapEnergy.h"
#include "map/PreparedInput.h"
#include "map/SurfaceMap.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <random>

using namespace surfacemaps;
using namespace surfacemaps::testing;

namespace
{
struct EnergyCase
{
  std::vector<PreparedInput> surfaces;
  std::unique_ptr<CommonTriangulation> T;
  std::unique_ptr<MapEnergy> energy;
  CommonTriangulation::Snapshot snapshot;
  SpherePoints points;

  explicit EnergyCase(const MapEnergyWeights& weights)
  {
    std::vector<MapInput> inputs{ icosphereInput(1, 0.0, { 1.0, 1.0, 1.0 }),
      icosphereInput(2, 0.3, { 1.4, 1.0, 0.8 }, 0.3) };
    for (MapInput& input : inputs)
    {
      setLandmarks(input, { { 0, 0, 1 }, { 1, 0, 0 } });
    }
    this->surfaces =
      prepareInputs(inputs, landmarkVertices(inputs), SurfaceMapOptions().approximationSamples);
    for (PreparedInput& s : this->surfaces)
    {
      s.sizing.assign(s.points.size(), 0.3);
    }
    this->T = std::make_unique<CommonTriangulation>(this->surfaces, mapPairs(PairScheme::Star, 2));
    this->energy = std::make_unique<MapEnergy>(*this->T, weights);
    this->T->setTrackSamples(true);
    this->T->updateTargetLengths();
    this->T->snapshot(this->snapshot, this->points, false, weights);
    // Off the input vertices, so that lifts are inside triangles.
    std::mt19937 random(3);
    std::uniform_real_distribution<double> uniform(-0.02, 0.02);
    Eigen::VectorXd step(this->points.numberOfVariables());
    for (Eigen::Index k = 0; k < step.size(); ++k)
    {
      step[k] = uniform(random);
    }
    this->points.retract(step, 1.0);
    this->points.recentreBases();
    EXPECT_TRUE(this->T->update(this->snapshot, this->points));
  }

  void expectDerivativesMatch()
  {
    Objective objective;
    this->energy->buildObjective(this->snapshot, landmarkTargets(this->surfaces), objective);
    Eigen::VectorXd g;
    Eigen::SparseMatrix<double> H;
    const double e = objective.hessian(this->points, -1.0, g, H);
    ASSERT_TRUE(std::isfinite(e));
    EXPECT_DOUBLE_EQ(e, objective.value(this->points));
    auto f = [&](const Eigen::VectorXd& x)
    {
      SpherePoints moved = this->points;
      moved.retract(x, 1.0);
      return objective.value(moved);
    };
    const Eigen::VectorXd x0 = Eigen::VectorXd::Zero(this->points.numberOfVariables());
    EXPECT_LT(relativeError(g, finiteDifferenceGradient(f, x0)), 1e-6);
    const Eigen::MatrixXd full = Eigen::MatrixXd(H).selfadjointView<Eigen::Upper>();
    EXPECT_LT(relativeError(full, finiteDifferenceHessian(f, x0)), 1e-4);
  }
};
} // namespace

TEST(MapEnergies, AllTermsMatchFiniteDifferences)
{
  MapEnergyWeights w;
  w.barrier = 0.01;
  w.mesh = 1.0;
  w.approximation = 10.0;
  w.landmark = 5.0;
  w.map = 1.0;
  EnergyCase c(w);
  c.expectDerivativesMatch();
}

TEST(MapEnergies, MeanShapeDistortionMatchesFiniteDifferences)
{
  MapEnergyWeights w;
  w.barrier = 0.01;
  w.map = 1.0;
  w.mapToMean = true;
  EnergyCase c(w);
  ASSERT_EQ(c.snapshot.meanGrams.size(), c.snapshot.triangles.size());
  c.expectDerivativesMatch();
}

// The mean shape of congruent copies is the triangle itself, where the term
// is at its minimum (the triangle's area per copy); it grows as the copies
// differ, whichever copy differs.
TEST(MapEnergies, MeanShapeTermIsMinimalForCongruentCopies)
{
  const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0), c(0.5, std::sqrt(3.0) / 2, 0);
  const std::array<double, 3> g = gramEntries(a, b, c);
  const std::array<double, 3> stretched = gramEntries<double>(a, 1.5 * b, c);
  const double area = std::sqrt(3.0) / 4;
  const auto total = [](const std::vector<std::array<double, 3>>& grams)
  {
    double sum = 0.0;
    for (const auto& gram : grams)
    {
      sum += symmetricDirichlet(meanGram(grams), gram);
    }
    return sum;
  };
  EXPECT_NEAR(total({ g, g, g }), 3.0 * area, 1e-12);
  EXPECT_GT(total({ stretched, g, g }), 3.0 * area * (1.0 + 1e-3));
  EXPECT_NEAR(total({ stretched, g, g }), total({ g, g, stretched }), 1e-12);
}

TEST(MapEnergies, CoverageMatchesFiniteDifferences)
{
  MapEnergyWeights w;
  w.barrier = 0.01;
  w.coverage = 1.0;
  EnergyCase c(w);
  ASSERT_EQ(c.snapshot.densities.size(), 2u);
  EXPECT_EQ(c.snapshot.densities[0].size(), c.snapshot.triangles.size());
  c.expectDerivativesMatch();
}

// Zero where the lifted triangle has the area its sphere triangle covers; a
// sphere sliver whose corners lift to a fat triangle (a fold of the surface
// between them) costs far more than the triangle's area.
TEST(MapEnergies, CoverageSeesSlivers)
{
  using V = Eigen::Vector3d;
  const std::array<V, 3> sphere{
    V(1, 0, 0), V(0.99, 0.1, 0).normalized(), V(0.99, 0, 0.1).normalized()
  };
  const double chord = 0.5 * (sphere[1] - sphere[0]).cross(sphere[2] - sphere[0]).norm();
  std::array<V, 3> lifted{ V(0, 0, 0), V(1, 0, 0), V(0, 1, 0) }; // area 0.5
  EXPECT_NEAR(coverageEnergy<double>(sphere, lifted, 0.5 / chord), 0.0, 1e-12);
  // Twice the area claimed: of the order of the area.
  const double twice = coverageEnergy<double>(sphere, lifted, 0.25 / chord);
  EXPECT_GT(twice, 0.05);
  EXPECT_LT(twice, 0.5);
  // The same corners' lift over a sphere triangle 1e4 times thinner.
  std::array<V, 3> sliver = sphere;
  sliver[2] = (sphere[1] + 1e-4 * (sphere[2] - sphere[1])).normalized();
  const double thin = 0.5 * (sliver[1] - sliver[0]).cross(sliver[2] - sliver[0]).norm();
  const double e = coverageEnergy<double>(sliver, lifted, 0.5 / chord);
  EXPECT_GT(e, 100.0);
  EXPECT_LT(thin, 1e-3 * chord);
  std::array<V, 3> degenerate = sphere;
  degenerate[2] = sphere[1];
  EXPECT_TRUE(std::isinf(coverageEnergy<double>(degenerate, lifted, 1.0)));
}

TEST(MapEnergies, HardApproximationBoundMatchesFiniteDifferences)
{
  MapEnergyWeights w;
  w.barrier = 0.01;
  w.approximation = 1.0;
  w.bounds = { 0.5, 0.5 };
  EnergyCase c(w);
  c.expectDerivativesMatch();
}

TEST(MapEnergies, ApproximationGaussNewtonHessian)
{
  // Values and gradients are the exact ones; the Hessian is 2 w J^T J:
  // positive semi-definite, and the exact Hessian where every sample sits on
  // its base point (zero residual).
  MapEnergyWeights w;
  w.approximation = 10.0;
  EnergyCase c(w);
  Objective objective;
  c.energy->buildObjective(c.snapshot, landmarkTargets(c.surfaces), objective);
  const ApproximationTerm* term = nullptr;
  for (std::size_t k = 0; k < objective.numberOfTerms() && !term; ++k)
  {
    term = dynamic_cast<const ApproximationTerm*>(&objective.term(k));
  }
  ASSERT_NE(term, nullptr);
  const int ne = term->numberOfElements();
  ASSERT_GT(ne, 10);
  auto derivatives =
    [&](
      double projectionEps, std::vector<double>& v, std::vector<double>& g, std::vector<double>& h)
  {
    v.assign(ne, 0.0);
    g.assign(ne * 6, 0.0);
    h.assign(ne * 36, 0.0);
    term->evaluateDerivatives(c.points, projectionEps, v.data(), g.data(), h.data());
  };
  std::vector<double> v0, g0, h0, v1, g1, h1;
  derivatives(-1.0, v0, g0, h0); // exact, not projected
  derivatives(0.0, v1, g1, h1);  // Gauss-Newton
  for (int e = 0; e < ne; ++e)
  {
    EXPECT_NEAR(v1[e], v0[e], 1e-12 * (1.0 + std::abs(v0[e])));
    const Eigen::Map<const Eigen::Matrix<double, 6, 1>> a(g0.data() + 6 * e), b(g1.data() + 6 * e);
    EXPECT_LE((a - b).norm(), 1e-10 * (1.0 + a.norm()));
    const Eigen::Map<const Eigen::Matrix<double, 6, 6>> H(h1.data() + 36 * e);
    EXPECT_LE((H - H.transpose()).norm(), 1e-12 * (1.0 + H.norm()));
    using Solver = Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>>;
    EXPECT_GE(Solver(H).eigenvalues().minCoeff(), -1e-10 * (1.0 + H.norm()));
  }
  // They differ where the residual is not zero (the test can tell them apart).
  double largest = 0.0;
  for (int e = 0; e < ne; ++e)
  {
    const Eigen::Map<const Eigen::Matrix<double, 6, 6>> exact(h0.data() + 36 * e);
    const Eigen::Map<const Eigen::Matrix<double, 6, 6>> gaussNewton(h1.data() + 36 * e);
    largest = std::max(largest, (exact - gaussNewton).norm() / (1.0 + exact.norm()));
  }
  EXPECT_GT(largest, 1e-6);
  // Every sample onto its base point: then both Hessians agree.
  const ApproximationEnergy& energy = term->energy();
  ApproximationSampleSet& samples = c.T->surface(energy.offset == 0 ? 0 : 1).samples;
  for (int e = 0; e < ne; ++e)
  {
    const std::array<int, 3> idx = energy.points(e);
    const std::array<Eigen::Vector3d, 3> p{
      c.points.position(idx[0]), c.points.position(idx[1]), c.points.position(idx[2])
    };
    samples.positions[e] -= energy.residual<double>(e, p);
  }
  derivatives(-1.0, v0, g0, h0);
  derivatives(0.0, v1, g1, h1);
  for (int e = 0; e < ne; ++e)
  {
    EXPECT_NEAR(v1[e], 0.0, 1e-20);
    const Eigen::Map<const Eigen::Matrix<double, 6, 6>> exact(h0.data() + 36 * e);
    const Eigen::Map<const Eigen::Matrix<double, 6, 6>> gaussNewton(h1.data() + 36 * e);
    EXPECT_LE((exact - gaussNewton).norm(), 1e-8 * (1.0 + exact.norm()));
  }
}

TEST(MapEnergies, TermsVanishOrAreMinimalWhereTheyShould)
{
  // Map distortion of a triangle onto a congruent one is its area (SD 1 per
  // unit area); mesh quality of an equilateral triangle of the target size too.
  const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0), c(0.5, std::sqrt(3.0) / 2, 0);
  const double area = std::sqrt(3.0) / 4;
  EXPECT_NEAR(mapDistortionEnergy<double>({ a, b, c }, { b, c, a }), area, 1e-12);
  EXPECT_NEAR(meshQualityEnergy<double>(a, b, c, 1.0), area, 1e-12);
  EXPECT_GT(meshQualityEnergy<double>(a, b, c, 0.5), area);
  EXPECT_GT(meshQualityEnergy<double>(a, b, c, 2.0), area);
  // An input vertex at its base point costs nothing; the bound is a barrier.
  const std::array<Eigen::Vector3d, 3> g{
    Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1)
  };
  const Eigen::Vector3d q = Eigen::Vector3d(1, 1, 1).normalized();
  const Eigen::Vector3d centroid = (a + b + c) / 3.0;
  EXPECT_NEAR(squaredBaseDistance<double>(q, centroid, g, { a, b, c }), 0.0, 1e-24);
  const double d2 =
    squaredBaseDistance<double>(q, centroid + Eigen::Vector3d(0, 0, 0.1), g, { a, b, c });
  EXPECT_NEAR(d2, 0.01, 1e-12);
  EXPECT_NEAR(approximationEnergy<double>(d2, 2.0, 0.0), 0.02, 1e-12);
  EXPECT_TRUE(std::isinf(approximationEnergy<double>(d2, 2.0, 0.1)));
  EXPECT_NEAR(approximationEnergy<double>(d2, 2.0, 0.2), 2.0 * 1e-3 / (8e-3 - 1e-3), 1e-12);
}

// Remeshing rejects edits on meshQualityBound before it looks up any target
// length, so the bound must stay below the energy at every length (or edits
// would be lost) and should be its minimum (or it would reject less).
TEST(MapEnergies, MeshQualityBoundIsTheSmallestValueOverLengths)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int k = 0; k < 200; ++k)
  {
    const Eigen::Vector3d a(uniform(random), uniform(random), uniform(random));
    const Eigen::Vector3d b(uniform(random), uniform(random), uniform(random));
    // Every tenth triangle a sliver.
    const Eigen::Vector3d c = k % 10 == 0
      ? Eigen::Vector3d(0.5 * (a + b) + 1e-6 * Eigen::Vector3d(uniform(random), 1.0, 0.0))
      : Eigen::Vector3d(uniform(random), uniform(random), uniform(random));
    const std::array<double, 3> gram = gramEntries(a, b, c);
    const double bound = meshQualityBound(gram);
    double smallest = std::numeric_limits<double>::infinity();
    for (double length = 1e-4; length < 1e4; length *= 1.001)
    {
      const double e = meshQualityOfGram(gram, length);
      ASSERT_LE(bound, e) << "triangle " << k << ", length " << length;
      smallest = std::min(smallest, e);
    }
    EXPECT_LE(smallest, bound * (1.0 + 1e-5)) << "triangle " << k;
    EXPECT_EQ(meshQualityOfGram(gram, 0.3), meshQualityEnergy<double>(a, b, c, 0.3));
  }
}

TEST(MapEnergies, TriangleEnergyBoundIsBelowTheEnergyAtEveryLength)
{
  MapEnergyWeights w;
  w.barrier = 0.01;
  w.mesh = 0.5;
  w.coverage = 0.1;
  w.map = 1.0;
  EnergyCase c(w);
  const CommonTriangulation& T = *c.T;
  const MapEnergy& energy = *c.energy;
  int faces = 0;
  for (auto f : T.mesh().faces())
  {
    auto fv = T.mesh().cfv_iter(f);
    const MapVertex a = T.vertex(*fv), b = T.vertex(*++fv), cc = T.vertex(*++fv);
    const MapEnergy::TriangleTerms terms = energy.triangleTerms(a, b, cc);
    const double bound = energy.triangleEnergyBound(terms);
    ASSERT_TRUE(std::isfinite(bound));
    // The same value, bit for bit, as from the vertices.
    const double length = T.targetLength(f);
    EXPECT_EQ(energy.triangleEnergy(terms, length), energy.triangleEnergy(a, b, cc, length));
    double smallest = std::numeric_limits<double>::infinity();
    for (double l = 1e-3; l < 1e2; l *= 1.01)
    {
      const double e = energy.triangleEnergy(terms, l);
      ASSERT_LE(bound, e) << "face " << f.idx() << ", length " << l;
      smallest = std::min(smallest, e);
    }
    // Each input's mesh term is bounded at its own best length, the energy
    // has one length for both: close to, not at, the smallest energy.
    EXPECT_LE(smallest - bound, 1e-2 * smallest) << "face " << f.idx();
    ++faces;
  }
  EXPECT_GT(faces, 0);
}

TEST(MapEnergies, LiftIsTheBarycentricInverseOfTheEmbedding)
{
  const Eigen::Vector3d A(0, 0, 0), B(2, 0, 0), C(0, 1, 1);
  const Eigen::Vector3d a = Eigen::Vector3d(1, 0.1, 0.2).normalized();
  const Eigen::Vector3d b = Eigen::Vector3d(0.1, 1, 0.1).normalized();
  const Eigen::Vector3d c = Eigen::Vector3d(0.2, 0.1, 1).normalized();
  const Lift lift(A, B, C, a, b, c);
  EXPECT_LT((lift(a) - A).norm(), 1e-14);
  EXPECT_LT((lift(b) - B).norm(), 1e-14);
  EXPECT_LT((lift(c) - C).norm(), 1e-14);
  const Eigen::Vector3d p = (0.2 * a + 0.3 * b + 0.5 * c).normalized();
  EXPECT_LT((lift(p) - (0.2 * A + 0.3 * B + 0.5 * C)).norm(), 1e-14);
}

namespace
{
// Values, gradients and Hessians of one term, exact (projectionEps < 0) and
// in the form the Newton step uses (projectionEps = 0).
struct TermDerivatives
{
  std::vector<double> values, gradients, hessians;
};

TermDerivatives derivativesOf(const ObjectiveTerm& term, const SpherePoints& points, double eps)
{
  const std::size_t ne = term.numberOfElements();
  const std::size_t n = 2 * term.pointsPerElement();
  TermDerivatives d;
  d.values.resize(ne);
  d.gradients.resize(ne * n);
  d.hessians.resize(ne * n * n);
  term.evaluateDerivatives(points, eps, d.values.data(), d.gradients.data(), d.hessians.data());
  return d;
}

void expectGaussNewtonForm(const ObjectiveTerm& term, const SpherePoints& points)
{
  const TermDerivatives exact = derivativesOf(term, points, -1.0);
  const TermDerivatives gn = derivativesOf(term, points, 0.0);
  const int n = 2 * term.pointsPerElement();
  for (int e = 0; e < term.numberOfElements(); ++e)
  {
    EXPECT_NEAR(gn.values[e], exact.values[e], 1e-12 * std::max(1.0, std::abs(exact.values[e])));
    for (int k = 0; k < n; ++k)
    {
      EXPECT_NEAR(gn.gradients[e * n + k],
        exact.gradients[e * n + k],
        1e-9 * std::max(1.0, std::abs(exact.gradients[e * n + k])));
    }
    const Eigen::Map<const Eigen::MatrixXd> H(gn.hessians.data() + e * n * n, n, n);
    EXPECT_LT((H - H.transpose()).cwiseAbs().maxCoeff(), 1e-12 * std::max(1.0, H.norm()));
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(H);
    EXPECT_GE(eig.eigenvalues().minCoeff(), -1e-10 * std::max(1.0, H.norm()));
  }
}
} // namespace

TEST(MapEnergies, BarrierGaussNewtonHessianIsPositiveAndMatchesTheGradient)
{
  MapEnergyWeights w;
  w.barrier = 0.01;
  EnergyCase c(w);
  Objective objective;
  c.energy->buildObjective(c.snapshot, {}, objective);
  ASSERT_EQ(objective.numberOfTerms(), 2u); // one barrier per embedding
  for (std::size_t t = 0; t < objective.numberOfTerms(); ++t)
  {
    expectGaussNewtonForm(objective.term(t), c.points);
  }
}

// An edit must not make a sliver whose rounded determinant is positive while
// the exact one is not: the certificate is exact, so a state the optimisation
// keeps has to pass it; a triangle positive both ways keeps its finite
// barrier. Chords whose third point lies on
// the great circle through the first two, up to rounding, give both signs.
TEST(MapEnergies, ExactBarrierRejectsSliversThatAreOnlyPositiveWhenRounded)
{
  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0.05, 0.95);
  int roundedPositiveOnly = 0;
  int exactlyPositive = 0;
  for (int k = 0; k < 20000; ++k)
  {
    const Eigen::Vector3d a =
      Eigen::Vector3d(normal(random), normal(random), normal(random)).normalized();
    const Eigen::Vector3d b =
      Eigen::Vector3d(normal(random), normal(random), normal(random)).normalized();
    const double s = uniform(random);
    const Eigen::Vector3d c = (s * a + (1.0 - s) * b).normalized();
    const double rounded = a.dot(b.cross(c));
    const int exact = orient3dOrigin(a, b, c);
    const double barrier = exactOrientationBarrier(a, b, c);
    if (rounded > 0.0 && exact <= 0)
    {
      ++roundedPositiveOnly;
      EXPECT_TRUE(std::isinf(barrier)) << "k " << k << ", rounded det " << rounded;
    }
    else if (exact > 0 && rounded > 0.0)
    {
      ++exactlyPositive;
      EXPECT_TRUE(std::isfinite(barrier)) << "k " << k << ", rounded det " << rounded;
    }
    else if (exact <= 0)
    {
      EXPECT_TRUE(std::isinf(barrier));
    }
    // (Positive exactly but not when rounded: -log of the rounded volume is
    // undefined, so the barrier rejects it too; the safe side.)
  }
  // The sample holds both kinds, so the test decides something.
  EXPECT_GT(roundedPositiveOnly, 100);
  EXPECT_GT(exactlyPositive, 100);
}

// A raised triangle's barrier (CommonTriangulation::raiseBarrier) is its
// plain barrier times its scale, in the value, the gradient and both
// Hessians (exact and Gauss-Newton); the Gauss-Newton one stays positive.
TEST(MapEnergies, BarrierScalesMultiplyEachTrianglesTermInEveryForm)
{
  MapEnergyWeights w;
  w.barrier = 0.01;
  EnergyCase c(w);
  BarrierEnergy plain;
  plain.triangles = c.snapshot.triangles;
  plain.offset = c.snapshot.vertices; // embedding 1
  std::vector<double> scales(plain.triangles.size());
  for (std::size_t t = 0; t < scales.size(); ++t)
  {
    scales[t] = t % 3 == 0 ? 1.0 : std::pow(4.0, static_cast<double>(t % 4));
  }
  BarrierEnergy raised = plain;
  raised.scales = scales.data();
  const BijectivityBarrierTerm plainTerm(plain), raisedTerm(raised);
  const ElementTerm<3, BarrierEnergy> plainExact("barrier", plain), raisedExact("barrier", raised);
  // The exact Hessian (projectionEps < 0) and the Gauss-Newton one (0).
  auto expectScaled = [&](const ObjectiveTerm& unscaled, const ObjectiveTerm& scaled, double eps)
  {
    const TermDerivatives a = derivativesOf(unscaled, c.points, eps);
    const TermDerivatives b = derivativesOf(scaled, c.points, eps);
    const int n = 6;
    for (std::size_t e = 0; e < scales.size(); ++e)
    {
      const double s = scales[e];
      EXPECT_NEAR(b.values[e], s * a.values[e], 1e-12 * std::abs(s * a.values[e])) << e;
      for (int k = 0; k < n; ++k)
      {
        const double g = s * a.gradients[e * n + k];
        EXPECT_NEAR(b.gradients[e * n + k], g, 1e-12 * std::max(1.0, std::abs(g))) << e;
      }
      for (int k = 0; k < n * n; ++k)
      {
        const double h = s * a.hessians[e * n * n + k];
        EXPECT_NEAR(b.hessians[e * n * n + k], h, 1e-12 * std::max(1.0, std::abs(h))) << e;
      }
    }
  };
  expectScaled(plainExact, raisedExact, -1.0);
  expectScaled(plainTerm, raisedTerm, 0.0);
  expectGaussNewtonForm(raisedTerm, c.points);
}
