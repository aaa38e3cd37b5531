// SurfaceMaps engine: the line search of a Newton step over a problem's
// points. Owns the step's start points, the first trial step's cap, and
// leaving the problem's state that of the points the step ends at.
#pragma once

#include "optimisation/LineSearch.h"
#include "optimisation/NewtonProblem.h"
#include "optimisation/SpherePoints.h"

#include <Eigen/Core>

#include <vector>

namespace surfacemaps
{

/// The first trial step along `direction`: 1, or less where a point would
/// move farther than `maxPointStep` (0: no cap). The whole step is scaled,
/// never clamped per point (which would change its direction).
double firstStep(const SpherePoints& points, const Eigen::VectorXd& direction, double maxPointStep);

/// Armijo searches from the points' positions at construction along one or
/// more directions, then take() or restore(). Trials run one after the
/// other (evaluating two at once on two threads saved under 5 % of the
/// corpus' time: Testing/Benchmarks/README.md, tricks on and off).
class TrialSearch
{
public:
  TrialSearch(NewtonProblem& problem, SpherePoints& points);

  const std::vector<Eigen::Vector3d>& start() const { return this->Start; }

  /// Backtracking from `firstStep` along `direction` (slope: its
  /// directional derivative at energy f0). `tag` names the direction for
  /// take().
  LineSearchResult search(const Eigen::VectorXd& direction,
    double f0,
    double slope,
    double firstStep,
    int tag,
    const LineSearchOptions& options);

  /// Moves the points to the trial at `step` along the direction searched
  /// with `tag` (the same operations, so the same points bit for bit),
  /// re-centres their bases and leaves the problem's state theirs: that of
  /// the last trial when it was this one, else a fresh accept().
  void take(const Eigen::VectorXd& direction, double step, int tag);

  /// Puts the points back at the start, the problem's state theirs.
  void restore();

private:
  /// The last trial: along which direction, its step, and whether its check
  /// passed (so what the check computed holds for those points).
  struct LastTrial
  {
    int tag = -1;
    double step = 0.0;
    bool accepted = false;
  };

  double trial(const Eigen::VectorXd& direction, double step, int tag);
  /// accept() on the points as they are; throws if it fails (it passed
  /// before, so the problem is broken).
  void acceptAgain();

  NewtonProblem& Problem;
  SpherePoints& Points;
  const std::vector<Eigen::Vector3d> Start;
  LastTrial Last;
};

} // namespace surfacemaps
