// Benchmark of the optimisation engine (not a test): element derivative
// throughput and one full projected-Newton iteration at the size of a typical
// common triangulation. Prints a Markdown table.
//
//   build/bin/BenchmarkEngine [--threads N] [--repeat R] [--nested-dissection]
//                             [--exact-barrier]
//
// The iteration's barrier is the map's own BijectivityBarrierTerm (Gauss-Newton
// Hessian, as in the coarse and fine phases); --exact-barrier uses the exact
// Hessian with an eigenvalue clamp per triangle instead (as in the landmark
// phase and the sphere embedding).
#include "energy/BarrierEnergy.h"
#include "energy/BijectivityBarrier.h"
#include "mesh/Primitives.h"
#include "optimisation/NewtonSolver.h"
#include "optimisation/Objective.h"

#include <omp.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

using namespace surfacemaps;

namespace
{

// Symmetric Dirichlet energy between the chord triangles of one triangle in
// two sphere embeddings (6 points, 12 variables): the shape of the map
// distortion element. With Gram matrices G = [e1 e2]^T [e1 e2] of the edge
// vectors, |J|^2 = tr(G_Q G_P^-1), |J^-1|^2 = tr(G_P G_Q^-1), area = sqrt(det G) / 2,
// so the energy is a function of 6 numbers; each triangle's 3 depend on only
// 6 of the 12 variables. Derivatives are composed from those pieces.
struct ChordDirichletEnergy
{
  std::vector<std::array<int, 3>> triangles;
  int offset = 0; // first point of the second embedding

  int numberOfElements() const { return static_cast<int>(this->triangles.size()); }
  std::array<int, 6> points(int e) const
  {
    const auto& t = this->triangles[e];
    return { t[0], t[1], t[2], t[0] + offset, t[1] + offset, t[2] + offset };
  }

  // (e1.e1, e2.e2, e1.e2) of triangle abc.
  template<typename T>
  static std::array<T, 3> gram(const Eigen::Matrix<T, 3, 1>& a,
    const Eigen::Matrix<T, 3, 1>& b,
    const Eigen::Matrix<T, 3, 1>& c)
  {
    const Eigen::Matrix<T, 3, 1> e1 = b - a, e2 = c - a;
    return { e1.dot(e1), e2.dot(e2), e1.dot(e2) };
  }

  // The energy from the Gram entries u = (P11, P22, P12, Q11, Q22, Q12).
  template<typename T>
  static T fromGram(const std::array<T, 6>& u)
  {
    const T detP = u[0] * u[1] - u[2] * u[2];
    const T detQ = u[3] * u[4] - u[5] * u[5];
    const T cross = u[3] * u[1] + u[4] * u[0] - 2.0 * (u[5] * u[2]);
    return 0.125 * (sqrt(detQ) * cross / detP + sqrt(detP) * cross / detQ);
  }

  template<typename T>
  T operator()(int, const std::array<Eigen::Matrix<T, 3, 1>, 6>& p) const
  {
    if constexpr (!IsDual<T>::value)
    {
      const auto P = gram(p[0], p[1], p[2]), Q = gram(p[3], p[4], p[5]);
      return fromGram<T>({ P[0], P[1], P[2], Q[0], Q[1], Q[2] });
    }
    else
    {
      constexpr bool H = T::HasHessian;
      using D6 = Dual<6, H>;
      std::array<T, 6> u;
      for (int t = 0; t < 2; ++t)
      {
        std::array<Eigen::Matrix<D6, 3, 1>, 3> q;
        for (int k = 0; k < 3; ++k)
        {
          for (int c = 0; c < 3; ++c)
          {
            q[k][c] = restrict<6>(p[3 * t + k][c], 6 * t);
          }
        }
        const std::array<D6, 3> g = gram(q[0], q[1], q[2]);
        for (int k = 0; k < 3; ++k)
        {
          u[3 * t + k] = embed<12>(g[k], 6 * t);
        }
      }
      std::array<D6, 6> vars;
      for (int k = 0; k < 6; ++k)
      {
        vars[k] = D6::variable(u[k].val, k);
      }
      return compose(fromGram(vars), u);
    }
  }
};

double now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

struct Settings
{
  int threads = omp_get_num_procs();
  int repeat = 10;
  LinearSolver::Ordering ordering = LinearSolver::Ordering::Amd;
  bool exactBarrier = false;
};

// The command line; false after printing the usage.
bool parseArguments(int argc, char* argv[], Settings& settings)
{
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--threads") && i + 1 < argc)
    {
      settings.threads = std::atoi(argv[++i]);
    }
    else if (!std::strcmp(argv[i], "--repeat") && i + 1 < argc)
    {
      settings.repeat = std::atoi(argv[++i]);
    }
    else if (!std::strcmp(argv[i], "--nested-dissection"))
    {
      settings.ordering = LinearSolver::Ordering::NestedDissection;
    }
    else if (!std::strcmp(argv[i], "--exact-barrier"))
    {
      settings.exactBarrier = true;
    }
    else
    {
      std::fprintf(stderr,
        "usage: BenchmarkEngine [--threads N] [--repeat R] [--nested-dissection] "
        "[--exact-barrier]\n");
      return false;
    }
  }
  return true;
}

// Two embeddings of an icosphere of level 4 (2 562 vertices, 5 120
// triangles); the second is the first seen from a point inside the sphere (a
// bijective, smoothly non-uniform map).
struct Problem
{
  int n = 0; // vertices of one embedding
  std::vector<std::array<int, 3>> triangles;
  SpherePoints points;
  std::shared_ptr<ElementTerm<6, ChordDirichletEnergy>> distortion;
};

Problem makeProblem()
{
  Problem problem;
  const PolygonMesh mesh = makeIcosphere(4);
  problem.n = static_cast<int>(mesh.points.size());
  problem.triangles = mesh.triangles();
  std::vector<Eigen::Vector3d> all = mesh.points;
  for (const Eigen::Vector3d& p : mesh.points)
  {
    all.push_back((p + Eigen::Vector3d(0.25, -0.1, 0.3)).normalized());
  }
  problem.points = SpherePoints(all);
  problem.distortion = std::make_shared<ElementTerm<6, ChordDirichletEnergy>>(
    "map distortion", ChordDirichletEnergy{ problem.triangles, problem.n });
  return problem;
}

void printHeader(const Problem& problem)
{
  std::printf("# SurfaceMaps engine benchmark\n\n");
  std::printf("icosphere level 4: %d vertices, %d triangles, 2 embeddings (%d variables)\n\n",
    problem.n,
    problem.distortion->numberOfElements(),
    problem.points.numberOfVariables());
  std::printf("| measurement | threads | figure |\n|---|---|---|\n");
}

// Seconds per element of `evaluate`, run `repeat` times over all elements.
template<typename Evaluate>
double secondsPerElement(int repeat, int elements, const Evaluate& evaluate)
{
  const double t0 = now();
  for (int r = 0; r < repeat; ++r)
  {
    evaluate();
  }
  return (now() - t0) / (repeat * double(elements));
}

// Per-core throughput of the 12-variable element.
void measureElements(const Problem& problem, int repeat)
{
  const auto& sd = *problem.distortion;
  const SpherePoints& points = problem.points;
  const int ne = sd.numberOfElements();
  std::vector<double> values(ne), gradients(ne * 12), hessians(ne * 144);
  sd.evaluateDerivatives(points, 1e-9, values.data(), gradients.data(), hessians.data()); // warm up
  const double withHessian = secondsPerElement(repeat,
    ne,
    [&]
    { sd.evaluateDerivatives(points, 1e-9, values.data(), gradients.data(), hessians.data()); });
  const double unprojected = secondsPerElement(repeat,
    ne,
    [&]
    { sd.evaluateDerivatives(points, -1.0, values.data(), gradients.data(), hessians.data()); });
  const double gradientOnly = secondsPerElement(repeat,
    ne,
    [&] { sd.evaluateDerivatives(points, 0.0, values.data(), gradients.data(), nullptr); });
  const double valueOnly =
    secondsPerElement(10 * repeat, ne, [&] { sd.evaluateValues(points, values.data()); });
  std::printf(
    "| 12-variable symmetric Dirichlet element, value + gradient + projected Hessian | 1 | "
    "%.0f elements/s (%.2f us each) |\n",
    1.0 / withHessian,
    1e6 * withHessian);
  std::printf("| same, Hessian not projected | 1 | %.0f elements/s (%.2f us each) |\n",
    1.0 / unprojected,
    1e6 * unprojected);
  std::printf("| same, value + gradient | 1 | %.0f elements/s (%.2f us each) |\n",
    1.0 / gradientOnly,
    1e6 * gradientOnly);
  std::printf("| same, value only (line-search trial) | 1 | %.0f elements/s (%.3f us each) |\n",
    1.0 / valueOnly,
    1e6 * valueOnly);
}

// Map distortion and the barrier on both embeddings.
void addTerms(Objective& objective, const Problem& problem, bool exactBarrier)
{
  objective.addTerm(problem.distortion, 1.0);
  for (int offset : { 0, problem.n })
  {
    const BarrierEnergy barrier{ problem.triangles, offset };
    if (exactBarrier)
    {
      objective.addTerm(std::make_shared<ElementTerm<3, BarrierEnergy>>("barrier", barrier), 1e-3);
    }
    else
    {
      objective.addTerm(std::make_shared<BijectivityBarrierTerm>(barrier), 1e-3);
    }
  }
}

// `iterations` full Newton iterations: their mean time and its parts.
void measureIterations(Objective& objective,
  SpherePoints& points,
  LinearSolver& solver,
  const NewtonOptions& options,
  int iterations,
  int threads)
{
  double total = 0, derivatives = 0, solve = 0, lineSearch = 0, trials = 0;
  int regularised = 0, fallbacks = 0;
  for (int it = 0; it < iterations; ++it)
  {
    const double t0 = now();
    ObjectiveProblem problem(objective);
    const NewtonStepResult step = newtonStep(problem, points, solver, options);
    total += now() - t0;
    derivatives += step.derivativeSeconds;
    solve += step.solveSeconds;
    lineSearch += step.lineSearchSeconds;
    trials += step.lineSearchTrials;
    regularised += step.regularised ? 1 : 0;
    fallbacks += step.gradientFallback ? 1 : 0;
  }
  std::printf(
    "| full Newton iteration (derivatives + projection + assembly + solve + line search), "
    "mean of %d | %d | %.4f s |\n",
    iterations,
    threads,
    total / iterations);
  std::printf("| of which derivatives, projection and assembly | %d | %.4f s |\n",
    threads,
    derivatives / iterations);
  std::printf("| of which CHOLMOD solve | %d | %.4f s |\n", threads, solve / iterations);
  std::printf("| of which line search (%.1f trials on average) | %d | %.4f s |\n",
    trials / iterations,
    threads,
    lineSearch / iterations);
  std::printf(
    "| iterations that needed a regularised solve / a gradient fallback | %d | %d / %d |\n",
    threads,
    regularised,
    fallbacks);
}

// Where the derivative time goes, at the current points: each term's element
// derivatives with projection (parallel), then the whole objective.hessian
// (the difference is gradient and Hessian assembly, serial).
void measureDerivatives(Objective& objective, const SpherePoints& points, int repeat, int threads)
{
  double termSeconds[3] = { 0.0, 0.0, 0.0 }, hessianSeconds = 0.0;
  Eigen::VectorXd g;
  Eigen::SparseMatrix<double> H;
  for (int r = 0; r < repeat; ++r)
  {
    for (std::size_t t = 0; t < objective.numberOfTerms(); ++t)
    {
      ObjectiveTerm& term = objective.term(t);
      const std::size_t m = term.numberOfElements();
      const std::size_t k = 2 * term.pointsPerElement();
      std::vector<double> v(m), gr(m * k), he(m * k * k);
      const double t0 = now();
      term.evaluateDerivatives(points, 1e-9, v.data(), gr.data(), he.data());
      termSeconds[t] += now() - t0;
    }
    const double t0 = now();
    objective.hessian(points, 1e-9, g, H);
    hessianSeconds += now() - t0;
  }
  std::printf("| of the derivatives: symmetric Dirichlet elements / barrier elements "
              "(with projection) | %d | %.4f s / %.4f s |\n",
    threads,
    termSeconds[0] / repeat,
    (termSeconds[1] + termSeconds[2]) / repeat);
  std::printf("| of the derivatives: gradient and Hessian assembly | 1 | %.4f s |\n",
    (hessianSeconds - termSeconds[0] - termSeconds[1] - termSeconds[2]) / repeat);
}

} // namespace

int main(int argc, char* argv[])
{
  Settings settings;
  if (!parseArguments(argc, argv, settings))
  {
    return 2;
  }
  Problem problem = makeProblem();
  printHeader(problem);
  omp_set_num_threads(1);
  measureElements(problem, settings.repeat);

  omp_set_num_threads(settings.threads);
  Objective objective;
  addTerms(objective, problem, settings.exactBarrier);
  LinearSolver solver(settings.ordering);
  NewtonOptions options;
  options.maxPointStep = std::tan(75.0 * M_PI / 180.0);
  ObjectiveProblem newtonProblem(objective);
  const NewtonStepResult first =
    newtonStep(newtonProblem, problem.points, solver, options); // builds the pattern
  measureIterations(objective, problem.points, solver, options, settings.repeat, settings.threads);
  measureDerivatives(objective, problem.points, settings.repeat, settings.threads);
  std::printf("| first iteration (pattern, symbolic analysis) | %d | %.4f s |\n",
    settings.threads,
    first.derivativeSeconds + first.solveSeconds + first.lineSearchSeconds);
  return 0;
}
