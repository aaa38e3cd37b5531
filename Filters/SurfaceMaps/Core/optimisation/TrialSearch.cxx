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

TrialSearch::TrialSearch(NewtonProblem& problem, SpherePoints& points, int slots)
  : Problem(problem)
  , Points(points)
  , Start(points.positions())
{
  for (int s = 1; s < slots; ++s)
  {
    std::unique_ptr<NewtonProblem> copy = problem.trialCopy();
    if (!copy)
    {
      break;
    }
    this->Copies.push_back(std::move(copy));
  }
  // Copies retract their own points (with the same bases as slot 0's).
  this->CopyPoints.assign(this->Copies.size(), points);
  this->Last.resize(this->Copies.size() + 1);
}

double TrialSearch::trial(int slot, const Eigen::VectorXd& direction, double step, int tag)
{
  SpherePoints& points = slot == 0 ? this->Points : this->CopyPoints[slot - 1];
  NewtonProblem& problem = slot == 0 ? this->Problem : *this->Copies[slot - 1];
  points.setPositions(this->Start);
  points.retract(direction, step);
  LastTrial& record = this->Last[slot];
  record.tag = tag;
  record.step = step;
  record.accepted = problem.accept(points);
  if (!record.accepted)
  {
    return std::numeric_limits<double>::infinity();
  }
  return problem.objective().value(points);
}

LineSearchResult TrialSearch::search(const Eigen::VectorXd& direction,
  double f0,
  double slope,
  double firstStep,
  int tag,
  const LineSearchOptions& options)
{
  return armijoBacktracking([&](int slot, double t)
    { return this->trial(slot, direction, t, tag); },
    static_cast<int>(this->Last.size()),
    f0,
    slope,
    firstStep,
    options);
}

void TrialSearch::take(const Eigen::VectorXd& direction, double step, int tag)
{
  this->Points.setPositions(this->Start);
  this->Points.retract(direction, step);
  int taken = -1;
  for (int slot = 0; slot < static_cast<int>(this->Last.size()); ++slot)
  {
    const LastTrial& record = this->Last[slot];
    if (record.accepted && record.tag == tag && record.step == step)
    {
      taken = slot;
    }
  }
  this->Points.recentreBases();
  // Slot 0's problem holds the taken trial's state already.
  if (taken != 0 && !(taken > 0 && this->Problem.adopt(*this->Copies[taken - 1], this->Points)))
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
