// SurfaceMaps engine: TrialSearch and the first step's cap.
#include "optimisation/TrialSearch.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace surfacemaps
{

double firstStep(const SpherePoints& points, const Eigen::VectorXd& direction, double maxPointStep)
{
  double largest = 0.0;
  for (int i = 0; maxPointStep > 0.0 && i < points.size(); ++i)
  {
    const int v = points.variable(i);
    if (v >= 0)
    {
      largest = std::max(largest, std::hypot(direction[v], direction[v + 1]));
    }
  }
  return largest > maxPointStep ? maxPointStep / largest : 1.0;
}

TrialSearch::TrialSearch(NewtonProblem& problem, SpherePoints& points)
  : Problem(problem)
  , Points(points)
  , Start(points.positions())
{
}

double TrialSearch::trial(const Eigen::VectorXd& direction, double step, int tag)
{
  this->Points.setPositions(this->Start);
  this->Points.retract(direction, step);
  this->Last.tag = tag;
  this->Last.step = step;
  this->Last.accepted = this->Problem.accept(this->Points);
  if (!this->Last.accepted)
  {
    return std::numeric_limits<double>::infinity();
  }
  return this->Problem.objective().value(this->Points);
}

LineSearchResult TrialSearch::search(const Eigen::VectorXd& direction,
  double f0,
  double slope,
  double firstStep,
  int tag,
  const LineSearchOptions& options)
{
  return armijoBacktracking([&](double t) { return this->trial(direction, t, tag); },
    f0,
    slope,
    firstStep,
    options);
}

void TrialSearch::take(const Eigen::VectorXd& direction, double step, int tag)
{
  this->Points.setPositions(this->Start);
  this->Points.retract(direction, step);
  const bool lastIsTaken = this->Last.accepted && this->Last.tag == tag && this->Last.step == step;
  this->Points.recentreBases();
  if (!lastIsTaken)
  {
    this->acceptAgain();
  }
}

void TrialSearch::restore()
{
  this->Points.setPositions(this->Start);
  this->acceptAgain();
}

void TrialSearch::acceptAgain()
{
  if (!this->Problem.accept(this->Points))
  {
    throw std::logic_error("a Newton step's points failed their trial check again");
  }
}

} // namespace surfacemaps
