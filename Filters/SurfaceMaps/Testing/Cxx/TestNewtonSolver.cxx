#include "geometry/SphericalTriangulation.h"
#include "mesh/Primitives.h"
#include "optimisation/NewtonSolver.h"

#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <numeric>
#include <random>

using namespace surfacemaps;

namespace
{

// d / target - log d with d = det[a, b, c]: the log barrier of each chord
// triangle plus a linear pull, smallest where the triangle has d = target;
// +inf for an inverted triangle.
struct AreaBarrierEnergy
{
  std::vector<std::array<int, 3>> triangles;
  std::vector<double> targets;
  int numberOfElements() const { return static_cast<int>(this->triangles.size()); }
  std::array<int, 3> points(int e) const { return this->triangles[e]; }
  template<typename T>
  T operator()(int e, const std::array<Eigen::Matrix<T, 3, 1>, 3>& p) const
  {
    const T d = p[0].dot(p[1].cross(p[2]));
    if (!(d > 0.0))
    {
      return T(std::numeric_limits<double>::infinity());
    }
    return d / this->targets[e] - log(d);
  }
};

// A randomly perturbed icosphere pulled back towards the icosphere's nearly
// equal triangle areas (a minimum isolated up to rotations).
struct Problem
{
  PolygonMesh mesh = makeIcosphere(2);
  SpherePoints points;
  Objective objective;

  explicit Problem(double perturbation)
  {
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> u(-perturbation, perturbation);
    std::vector<Eigen::Vector3d> p = this->mesh.points;
    for (auto& x : p)
    {
      x += Eigen::Vector3d(u(rng), u(rng), u(rng));
    }
    this->points = SpherePoints(p);
    const auto t = this->mesh.triangles();
    std::vector<double> targets;
    for (const auto& f : t)
    {
      const auto& q = this->mesh.points;
      targets.push_back(q[f[0]].dot(q[f[1]].cross(q[f[2]])));
    }
    this->objective.addTerm(std::make_shared<ElementTerm<3, AreaBarrierEnergy>>(
      "area barrier", AreaBarrierEnergy{ t, targets }));
  }

  /// Largest |det / target - 1| over the triangles.
  double areaError() const
  {
    double worst = 0.0;
    const auto& q = this->mesh.points;
    for (const auto& f : this->mesh.triangles())
    {
      const auto& p = this->points;
      const double d = p.position(f[0]).dot(p.position(f[1]).cross(p.position(f[2])));
      worst = std::max(worst, std::abs(d / q[f[0]].dot(q[f[1]].cross(q[f[2]])) - 1.0));
    }
    return worst;
  }
};

// weight |p - target|^2 for one point: smooth.
struct PullEnergy
{
  std::vector<Eigen::Vector3d> targets;
  double weight = 10.0;
  int numberOfElements() const { return static_cast<int>(this->targets.size()); }
  std::array<int, 1> points(int e) const { return { e }; }
  template<typename T>
  T operator()(int e, const std::array<Eigen::Matrix<T, 3, 1>, 1>& p) const
  {
    const Eigen::Matrix<T, 3, 1> d = p[0] - this->targets[e].template cast<T>();
    return this->weight * d.squaredNorm();
  }
};

// A problem over an objective whose trial check remembers the points of the
// last trial it passed, as a caller's point location would; optionally names
// blocking points.
struct CheckedProblem : NewtonProblem
{
  Objective& energy;
  std::function<bool(const SpherePoints&)> check;
  std::function<std::vector<int>(const SpherePoints&)> blocking;
  std::vector<Eigen::Vector3d> lastPassed;

  CheckedProblem(Objective& objective, std::function<bool(const SpherePoints&)> check)
    : energy(objective)
    , check(std::move(check))
  {
  }
  Objective& objective() override { return this->energy; }
  bool accept(const SpherePoints& trial) override
  {
    const bool ok = this->check(trial);
    if (ok)
    {
      this->lastPassed = trial.positions();
    }
    return ok;
  }
  std::vector<int> blockingPoints(const SpherePoints& trial) override
  {
    return this->blocking ? this->blocking(trial) : std::vector<int>{};
  }
};

// Whether a trial moved point 0 farther than `fraction` of the move one
// unconstrained Newton step gives it on a fresh problem: a constraint that
// only point 0 runs into.
std::function<bool(const SpherePoints&)> pointZeroMovesBeyond(double fraction)
{
  Problem problem(0.05);
  const Eigen::Vector3d start = problem.points.position(0);
  LinearSolver solver;
  ObjectiveProblem plain(problem.objective);
  newtonStep(plain, problem.points, solver);
  const double limit = fraction * (problem.points.position(0) - start).norm();
  EXPECT_GT(limit, 0.0);
  return [start, limit](const SpherePoints& trial)
  { return (trial.position(0) - start).norm() > limit; };
}

} // namespace

TEST(NewtonSolver, EqualAreasUnderTheBarrier)
{
  Problem problem(0.05);
  ASSERT_TRUE(certifyBijective(problem.points.positions(), problem.mesh.triangles()).bijective)
    << "test setup: the perturbed start must be a valid embedding";
  const double errorBefore = problem.areaError();
  EXPECT_GT(errorBefore, 0.1);

  std::vector<double> energies{ problem.objective.value(problem.points) };
  int inversions = 0;
  MinimizeOptions options;
  options.maxIterations = 30;
  options.decrementTolerance = 1e-4; // the schedule's convergence threshold
  options.callback = [&](int, const NewtonStepResult& step)
  {
    energies.push_back(step.energyAfter);
    if (!certifyBijective(problem.points.positions(), problem.mesh.triangles()).bijective)
    {
      ++inversions;
    }
    return true;
  };
  ObjectiveProblem newton(problem.objective);
  const MinimizeResult result = minimize(newton, problem.points, options);

  EXPECT_TRUE(result.converged);
  // Measured: 14 steps (the decrement falls from 3.3 to 8e-5; the energy
  // settles to 1e-11 relative after 12).
  EXPECT_LE(result.iterations, 20);
  EXPECT_EQ(inversions, 0);
  for (std::size_t i = 1; i < energies.size(); ++i)
  {
    EXPECT_LE(energies[i], energies[i - 1]) << "iteration " << i;
  }
  EXPECT_LT(problem.areaError(), 1e-3);
}

TEST(NewtonSolver, StepCapScalesTheWholeStep)
{
  Problem problem(0.05);
  LinearSolver solver;
  NewtonOptions options;
  options.maxPointStep = 1e-3;
  const std::vector<Eigen::Vector3d> before = problem.points.positions();
  ObjectiveProblem newton(problem.objective);
  const NewtonStepResult step = newtonStep(newton, problem.points, solver, options);
  ASSERT_TRUE(step.moved);
  EXPECT_LT(step.energyAfter, step.energyBefore);
  double largest = 0.0;
  for (int i = 0; i < problem.points.size(); ++i)
  {
    largest = std::max(largest, (problem.points.position(i) - before[i]).norm());
  }
  EXPECT_LE(largest, 1e-3 * (1 + 1e-9));
  EXPECT_GT(largest, 1e-4);
}

TEST(NewtonSolver, StallWhenTheLineSearchCutsTheStep)
{
  // A full Newton step is not stalled; one whose trials are rejected until
  // the step is a thousandth of the first (a kink's effect) is, and so is a
  // failed line search.
  Problem free(0.05);
  const std::vector<Eigen::Vector3d> start = free.points.positions();
  auto largestMove = [&](const SpherePoints& points)
  {
    double largest = 0.0;
    for (int i = 0; i < points.size(); ++i)
    {
      largest = std::max(largest, (points.position(i) - start[i]).norm());
    }
    return largest;
  };
  LinearSolver solver;
  ObjectiveProblem plain(free.objective);
  NewtonStepResult step = newtonStep(plain, free.points, solver);
  ASSERT_TRUE(step.moved);
  EXPECT_FALSE(step.stalled);
  const double freeMove = largestMove(free.points);
  ASSERT_GT(freeMove, 0.0);

  Problem kinked(0.05);
  ObjectiveProblem kink(kinked.objective,
    [&](const SpherePoints& trial) { return largestMove(trial) < 1e-3 * freeMove; });
  LinearSolver other;
  step = newtonStep(kink, kinked.points, other);
  EXPECT_TRUE(step.moved);
  EXPECT_TRUE(step.stalled);

  // Every trial that moves a point is rejected.
  Problem rejected(0.05);
  ObjectiveProblem wall(
    rejected.objective, [&](const SpherePoints& trial) { return trial.positions() == start; });
  LinearSolver third;
  step = newtonStep(wall, rejected.points, third);
  EXPECT_FALSE(step.moved);
  EXPECT_TRUE(step.stalled);
  EXPECT_EQ(rejected.points.positions(), start);
}

TEST(NewtonSolver, PointsThatBlockTheStepAreHeld)
{
  // Every trial that moves point 0 noticeably is rejected (a constraint only
  // point 0 runs into). Without knowing which point blocks, the whole step is
  // cut to almost nothing; told, the step holds point 0 and moves the others.
  Problem free(0.05);
  const std::vector<Eigen::Vector3d> start = free.points.positions();
  LinearSolver solver;
  ObjectiveProblem unconstrained(free.objective);
  newtonStep(unconstrained, free.points, solver);
  const double freeMove = (free.points.position(0) - start[0]).norm();
  ASSERT_GT(freeMove, 0.0);
  auto pointZeroMoved = [&](const SpherePoints& trial)
  { return (trial.position(0) - start[0]).norm() > 1e-3 * freeMove; };
  auto passes = [&](const SpherePoints& trial) { return !pointZeroMoved(trial); };

  Problem cut(0.05);
  CheckedProblem unknown(cut.objective, passes);
  LinearSolver other;
  const NewtonStepResult plain = newtonStep(unknown, cut.points, other);
  EXPECT_TRUE(plain.stalled);
  EXPECT_EQ(plain.heldPoints, 0);

  Problem held(0.05);
  CheckedProblem told(held.objective, passes);
  told.blocking = [&](const SpherePoints& trial)
  { return pointZeroMoved(trial) ? std::vector<int>{ 0 } : std::vector<int>{}; };
  LinearSolver third;
  const NewtonStepResult step = newtonStep(told, held.points, third);
  ASSERT_TRUE(step.moved);
  EXPECT_FALSE(step.stalled);
  EXPECT_EQ(step.heldPoints, 1);
  EXPECT_LT(step.energyAfter, plain.energyAfter);
  EXPECT_LT((held.points.position(0) - start[0]).norm(), 1e-14);
  double largest = 0.0;
  for (int i = 1; i < held.points.size(); ++i)
  {
    largest = std::max(largest, (held.points.position(i) - start[i]).norm());
  }
  EXPECT_GT(largest, 0.1 * freeMove);
}

TEST(NewtonSolver, TrialCheckAndAbort)
{
  Problem problem(0.05);
  const std::vector<Eigen::Vector3d> start = problem.points.positions();
  ObjectiveProblem wall(
    problem.objective, [&](const SpherePoints& trial) { return trial.positions() == start; });
  MinimizeOptions options;
  MinimizeResult result = minimize(wall, problem.points, options);
  EXPECT_FALSE(result.converged);
  EXPECT_EQ(result.iterations, 1);
  EXPECT_NEAR(result.finalEnergy, result.initialEnergy, 1e-12 * result.initialEnergy);

  Problem other(0.05);
  MinimizeOptions abort;
  int calls = 0;
  abort.callback = [&](int, const NewtonStepResult&) { return ++calls < 2; };
  ObjectiveProblem free(other.objective);
  result = minimize(free, other.points, abort);
  EXPECT_TRUE(result.aborted);
  EXPECT_EQ(result.iterations, 2);
}

TEST(NewtonSolver, LockedPointsStayPut)
{
  Problem problem(0.05);
  problem.points.setLocked(0, true);
  problem.points.setLocked(17, true);
  problem.objective.structureChanged();
  const Eigen::Vector3d p0 = problem.points.position(0), p17 = problem.points.position(17);
  MinimizeOptions options;
  options.maxIterations = 5;
  ObjectiveProblem newton(problem.objective);
  minimize(newton, problem.points, options);
  EXPECT_EQ(problem.points.position(0), p0);
  EXPECT_EQ(problem.points.position(17), p17);
}

TEST(NewtonSolver, TheProblemsLastCheckIsOfTheFinalPoints)
{
  // The problem remembers the points of the last trial its check passed, as
  // a caller's point location would: after the step they must be the final
  // points bit for bit, whichever trial the step took.
  int calls = 0;
  int rejectCall = -1;
  auto check = [&](const SpherePoints&) { return ++calls != rejectCall; };
  std::function<std::vector<int>(const SpherePoints&)> blocking;
  auto stepOnce = [&]()
  {
    calls = 0;
    Problem problem(0.05);
    CheckedProblem newton(problem.objective, check);
    newton.blocking = blocking;
    LinearSolver solver;
    const NewtonStepResult step = newtonStep(newton, problem.points, solver);
    EXPECT_EQ(newton.lastPassed, problem.points.positions());
    return step;
  };

  // The full step at the first trial.
  NewtonStepResult step = stepOnce();
  ASSERT_TRUE(step.moved);
  EXPECT_EQ(step.lineSearchTrials, 1);

  // The first trial rejected, so the plain search takes a shorter step and a
  // second search runs with points held. Holding point 0 gives the better
  // step: taken, and its trial was the last.
  rejectCall = 1;
  blocking = [](const SpherePoints&) { return std::vector<int>{ 0 }; };
  step = stepOnce();
  ASSERT_TRUE(step.moved);
  EXPECT_EQ(step.heldPoints, 1);

  // Holding half of the points gives the worse step: the plain one is taken,
  // although the held search's trials came after it.
  blocking = [](const SpherePoints& trial)
  {
    std::vector<int> half(trial.size() / 2);
    std::iota(half.begin(), half.end(), 0);
    return half;
  };
  step = stepOnce();
  ASSERT_TRUE(step.moved);
  EXPECT_EQ(step.heldPoints, 0);
}

TEST(NewtonSolver, TheProblemEndsWithTheFinalPoints)
{
  // Trials that move point 0 farther than a fraction of its free move are
  // rejected, so the searches run many trials (plain, then held). The
  // problem remembers the points of its last passed trial; it must end with
  // the final points, whichever search took the step.
  const auto blocked = pointZeroMovesBeyond(0.05);
  auto passes = [&](const SpherePoints& trial) { return !blocked(trial); };

  struct Run
  {
    NewtonStepResult step;
    std::vector<Eigen::Vector3d> final;
    std::vector<Eigen::Vector3d> remembered;
  };
  auto runWith = [&](bool hold)
  {
    Problem problem(0.05);
    CheckedProblem newton(problem.objective, passes);
    if (hold)
    {
      newton.blocking = [&](const SpherePoints& trial)
      { return passes(trial) ? std::vector<int>{} : std::vector<int>{ 0 }; };
    }
    LinearSolver solver;
    Run run;
    run.step = newtonStep(newton, problem.points, solver);
    run.final = problem.points.positions();
    run.remembered = newton.lastPassed;
    return run;
  };

  for (const bool hold : { false, true })
  {
    const Run run = runWith(hold);
    ASSERT_TRUE(run.step.moved);
    ASSERT_GT(run.step.lineSearchTrials, 4);
    EXPECT_EQ(run.step.heldPoints > 0, hold);
    EXPECT_EQ(run.remembered, run.final) << "hold " << hold;
  }
}
