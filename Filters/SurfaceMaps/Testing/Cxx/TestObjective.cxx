#include "energy/BarrierEnergy.h"
#include "FiniteDifferences.h"
#include "optimisation/HessianProjection.h"
#include "optimisation/Objective.h"
#include "mesh/Primitives.h"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>
#include <omp.h>

#include <cstring>
#include <memory>
#include <random>
#include <stdexcept>

using namespace surfacemaps;
using namespace surfacemaps::testing;

namespace
{

// Squared deviation of each triangle's det from a target: pulls towards equal areas.
struct EqualDetEnergy
{
  std::vector<std::array<int, 3>> triangles;
  double target = 1.0;
  int numberOfElements() const { return static_cast<int>(this->triangles.size()); }
  std::array<int, 3> points(int e) const { return this->triangles[e]; }
  template<typename T>
  T operator()(int, const std::array<Eigen::Matrix<T, 3, 1>, 3>& p) const
  {
    const T d = p[0].dot(p[1].cross(p[2])) / this->target - 1.0;
    return d * d;
  }
};

// An EqualDetEnergy term over the triangles, towards det 0.05.
std::shared_ptr<ObjectiveTerm> equalDetTerm(std::vector<std::array<int, 3>> triangles)
{
  return std::make_shared<ElementTerm<3, EqualDetEnergy>>(
    "area", EqualDetEnergy{ std::move(triangles), 0.05 });
}

SpherePoints perturbedSphere(const PolygonMesh& m, double amount, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amount, amount);
  std::vector<Eigen::Vector3d> p = m.points;
  for (auto& x : p)
  {
    x += Eigen::Vector3d(u(rng), u(rng), u(rng));
  }
  return SpherePoints(p);
}

// Energy as a function of the tangent variables, for finite differences.
double energyAtStep(const Objective& objective,
  const SpherePoints& points,
  const Eigen::VectorXd& x)
{
  SpherePoints moved = points;
  moved.retract(x, 1.0);
  return objective.value(moved);
}
} // namespace

TEST(SpherePoints, RetractionStaysOnTheSphereAndStartsAlongTheBasis)
{
  SpherePoints points(makeIcosphere(1).points);
  for (int i = 0; i < points.size(); ++i)
  {
    const auto& B = points.basis(i);
    EXPECT_NEAR(B.col(0).dot(points.position(i)), 0.0, 1e-15);
    EXPECT_NEAR(B.col(1).dot(points.position(i)), 0.0, 1e-15);
    EXPECT_NEAR(B.col(0).dot(B.col(1)), 0.0, 1e-15);
    EXPECT_NEAR(B.col(0).norm(), 1.0, 1e-15);
    // det[p, B1, B2] = +1: the basis is oriented like the outward normal.
    EXPECT_NEAR(points.position(i).dot(B.col(0).cross(B.col(1))), 1.0, 1e-14);
    const Eigen::Vector3d q = SpherePoints::retraction(points.position(i), B, 0.3, -2.0);
    EXPECT_NEAR(q.norm(), 1.0, 1e-15);
    const Dual<2> x = Dual<2>::variable(0.0, 0), y = Dual<2>::variable(0.0, 1);
    const auto r = SpherePoints::retraction(points.position(i), B, x, y);
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_NEAR(r[k].grad[0], B(k, 0), 1e-15);
      EXPECT_NEAR(r[k].grad[1], B(k, 1), 1e-15);
      EXPECT_NEAR(r[k].Hess(0, 0), -points.position(i)[k], 1e-15);
    }
  }
}

TEST(SpherePoints, SeededPointsEqualTheRetractionAtZero)
{
  SpherePoints points(makeIcosphere(1).points);
  for (int i = 0; i < points.size(); ++i)
  {
    using D = Dual<6>;
    const auto seeded = points.seeded<D>(i, 2);
    const auto retracted = SpherePoints::retraction(
      points.position(i), points.basis(i), D::variable(0.0, 2), D::variable(0.0, 3));
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_EQ(seeded[k].val, points.position(i)[k]); // exactly the stored point
      EXPECT_NEAR(seeded[k].val, retracted[k].val, 1e-15);
      EXPECT_LT((seeded[k].grad - retracted[k].grad).cwiseAbs().maxCoeff(), 1e-15);
      EXPECT_LT((seeded[k].Hess - retracted[k].Hess).cwiseAbs().maxCoeff(), 1e-15);
    }
    // In place, into a default-constructed point: the same scalars.
    Eigen::Matrix<D, 3, 1> inPlace;
    points.seedInto(i, 2, inPlace);
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_EQ(inPlace[k].val, seeded[k].val);
      EXPECT_EQ(inPlace[k].grad, seeded[k].grad);
      EXPECT_EQ(inPlace[k].Hess, seeded[k].Hess);
    }
  }
}

TEST(SpherePoints, LockingRemovesVariables)
{
  SpherePoints points(makeOctahedron().points);
  EXPECT_EQ(points.numberOfVariables(), 12);
  points.setLocked(2, true);
  EXPECT_EQ(points.numberOfVariables(), 10);
  EXPECT_EQ(points.variable(2), -1);
  EXPECT_EQ(points.variable(3), 4);
  Eigen::VectorXd step = Eigen::VectorXd::Constant(10, 0.1);
  const Eigen::Vector3d before = points.position(2);
  points.retract(step, 1.0);
  EXPECT_EQ(points.position(2), before);
}

TEST(Objective, GradientAndHessianMatchFiniteDifferences)
{
  const PolygonMesh ico = makeIcosphere(1);
  SpherePoints points = perturbedSphere(ico, 0.05, 7);
  points.setLocked(5, true);
  Objective objective;
  objective.addTerm(
    std::make_shared<ElementTerm<3, BarrierEnergy>>("barrier", BarrierEnergy{ ico.triangles(), 0 }),
    0.1);
  objective.addTerm(std::make_shared<ElementTerm<3, EqualDetEnergy>>(
                      "area", EqualDetEnergy{ ico.triangles(), 0.1 }),
    2.0);

  Eigen::VectorXd g;
  Eigen::SparseMatrix<double> H;
  const double e = objective.hessian(points, -1.0, g, H); // unprojected
  EXPECT_DOUBLE_EQ(e, objective.value(points));
  ASSERT_EQ(g.size(), points.numberOfVariables());
  const Eigen::VectorXd x0 = Eigen::VectorXd::Zero(points.numberOfVariables());
  auto f = [&](const Eigen::VectorXd& x) { return energyAtStep(objective, points, x); };
  EXPECT_LT(relativeError(g, finiteDifferenceGradient(f, x0)), 1e-6);

  const Eigen::MatrixXd full = Eigen::MatrixXd(H).selfadjointView<Eigen::Upper>();
  EXPECT_LT(relativeError(full, finiteDifferenceHessian(f, x0)), 1e-4);

  Eigen::VectorXd g2;
  EXPECT_DOUBLE_EQ(objective.gradient(points, g2), e);
  EXPECT_LT((g2 - g).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(Objective, ProjectedHessianIsPositiveDefinite)
{
  const PolygonMesh ico = makeIcosphere(1);
  SpherePoints points = perturbedSphere(ico, 0.1, 3);
  Objective objective;
  objective.addTerm(equalDetTerm(ico.triangles()));
  Eigen::VectorXd g;
  Eigen::SparseMatrix<double> H;
  objective.hessian(points, 1e-9, g, H);
  const Eigen::MatrixXd full = Eigen::MatrixXd(H).selfadjointView<Eigen::Upper>();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(full);
  EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0);
  objective.hessian(points, -1.0, g, H);
  const Eigen::MatrixXd raw = Eigen::MatrixXd(H).selfadjointView<Eigen::Upper>();
  EXPECT_LT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(raw).eigenvalues().minCoeff(), 0.0)
    << "test setup: the raw Hessian should be indefinite";
}

TEST(Objective, ReportsWhetherTheHessianPatternChanged)
{
  const PolygonMesh ico = makeIcosphere(1);
  SpherePoints points = perturbedSphere(ico, 0.1, 3);
  Objective objective;
  objective.addTerm(equalDetTerm(ico.triangles()));
  Eigen::VectorXd g;
  Eigen::SparseMatrix<double> H;
  bool changed = false;
  objective.hessian(points, 1e-9, g, H, &changed);
  EXPECT_TRUE(changed); // first pattern
  objective.hessian(points, 1e-9, g, H, &changed);
  EXPECT_FALSE(changed);
  // Rebuilt from the same elements (e.g. the next iteration without edits).
  objective.clear();
  objective.addTerm(equalDetTerm(ico.triangles()));
  objective.hessian(points, 1e-9, g, H, &changed);
  EXPECT_FALSE(changed);
  // Fewer elements: fewer couplings.
  auto fewer = ico.triangles();
  fewer.resize(fewer.size() / 2);
  objective.clear();
  objective.addTerm(equalDetTerm(fewer));
  objective.hessian(points, 1e-9, g, H, &changed);
  EXPECT_TRUE(changed);
  // A locked point removes variables.
  points.setLocked(0, true);
  objective.hessian(points, 1e-9, g, H, &changed);
  EXPECT_TRUE(changed);
}

TEST(Objective, NewPatternIsHandedOverOnceAndTheHessianStaysTheSame)
{
  const PolygonMesh ico = makeIcosphere(2);
  SpherePoints points = perturbedSphere(ico, 0.1, 5);
  Objective objective;
  objective.addTerm(equalDetTerm(ico.triangles()));
  Eigen::VectorXd g, gPlain;
  Eigen::SparseMatrix<double> H, HPlain;
  int calls = 0;
  Eigen::Index handedNonZeros = -1;
  auto newPattern = [&](const Eigen::SparseMatrix<double>& pattern)
  {
    ++calls;
    handedNonZeros = pattern.nonZeros();
  };
  bool changed = false;
  const double e = objective.hessian(points, 1e-9, g, H, &changed, newPattern);
  EXPECT_TRUE(changed);
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(handedNonZeros, H.nonZeros());
  objective.structureChanged(); // rebuilt, but the same pattern
  objective.hessian(points, 1e-9, g, H, &changed, newPattern);
  EXPECT_FALSE(changed);
  EXPECT_EQ(calls, 1);

  // Evaluated without the hand-over (derivatives on their own): the same
  // energy, gradient and Hessian bit for bit.
  Objective plain;
  plain.addTerm(equalDetTerm(ico.triangles()));
  EXPECT_EQ(plain.hessian(points, 1e-9, gPlain, HPlain), e);
  ASSERT_EQ(gPlain.size(), g.size());
  EXPECT_EQ(0, std::memcmp(gPlain.data(), g.data(), sizeof(double) * g.size()));
  ASSERT_EQ(HPlain.nonZeros(), H.nonZeros());
  EXPECT_EQ(0, std::memcmp(HPlain.valuePtr(), H.valuePtr(), sizeof(double) * H.nonZeros()));

  // An exception on the pattern's side leaves the parallel region and
  // reaches the caller.
  objective.structureChanged();
  points.setLocked(0, true);
  EXPECT_THROW(objective.hessian(points,
                 1e-9,
                 g,
                 H,
                 &changed,
                 [](const Eigen::SparseMatrix<double>&) { throw std::runtime_error("analysis"); }),
    std::runtime_error);
}

TEST(Objective, InvalidElementMakesTheEnergyInfinite)
{
  const PolygonMesh ico = makeIcosphere(1);
  std::vector<Eigen::Vector3d> p = ico.points;
  p[0] = -p[0]; // folds the triangles around vertex 0
  SpherePoints points(p);
  Objective objective;
  objective.addTerm(std::make_shared<ElementTerm<3, BarrierEnergy>>(
    "barrier", BarrierEnergy{ ico.triangles(), 0 }));
  EXPECT_EQ(objective.value(points), std::numeric_limits<double>::infinity());
  Eigen::VectorXd g;
  EXPECT_EQ(objective.gradient(points, g), std::numeric_limits<double>::infinity());
}

TEST(Objective, SameResultForAnyThreadCount)
{
  // Enough element Hessian entries (5 120 triangles, 36 each) for the
  // threads to share the assembly into the matrix too.
  const PolygonMesh ico = makeIcosphere(4);
  SpherePoints points = perturbedSphere(ico, 0.01, 11);
  Objective objective;
  objective.addTerm(std::make_shared<ElementTerm<3, BarrierEnergy>>(
    "barrier", BarrierEnergy{ ico.triangles(), 0 }));
  auto run = [&](int threads, Eigen::VectorXd& g, Eigen::SparseMatrix<double>& H)
  {
    omp_set_num_threads(threads);
    const double v = objective.hessian(points, 1e-9, g, H);
    omp_set_num_threads(omp_get_num_procs());
    return v;
  };
  Eigen::VectorXd g1, g2;
  Eigen::SparseMatrix<double> H1, H2;
  const double v1 = run(1, g1, H1);
  for (const int threads : { 2, 3 })
  {
    SCOPED_TRACE("threads " + std::to_string(threads));
    const double v2 = run(threads, g2, H2);
    EXPECT_EQ(v1, v2);
    EXPECT_EQ(g1, g2);
    ASSERT_EQ(H1.nonZeros(), H2.nonZeros());
    for (Eigen::Index k = 0; k < H1.nonZeros(); ++k)
    {
      ASSERT_EQ(H1.valuePtr()[k], H2.valuePtr()[k]);
    }
  }
}

TEST(HessianProjection, ClampsEigenvaluesAndKeepsDefiniteMatrices)
{
  std::mt19937 rng(5);
  std::normal_distribution<double> n;
  Eigen::Matrix<double, 6, 6> A;
  for (int i = 0; i < 36; ++i)
  {
    A.data()[i] = n(rng);
  }
  Eigen::Matrix<double, 6, 6> S = A + A.transpose();
  const Eigen::Matrix<double, 6, 6> original = S;
  EXPECT_TRUE(projectToPositiveDefinite<6>(S, 1e-3));
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(S);
  EXPECT_GE(eig.eigenvalues().minCoeff(), 1e-3 - 1e-12);
  // Eigenvalues above the threshold are kept, eigenvectors too.
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> before(original);
  EXPECT_NEAR(eig.eigenvalues().maxCoeff(), before.eigenvalues().maxCoeff(), 1e-10);

  Eigen::Matrix<double, 6, 6> P = A * A.transpose() + Eigen::Matrix<double, 6, 6>::Identity();
  const Eigen::Matrix<double, 6, 6> copy = P;
  EXPECT_FALSE(projectToPositiveDefinite<6>(P, 1e-9));
  EXPECT_EQ(P, copy);
}
