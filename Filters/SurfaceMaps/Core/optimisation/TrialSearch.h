// SurfaceMaps engine: the line search of a Newton step over a problem's
// points. Owns the step's start points, the first trial step's cap, the
// trial slots (the problem and its trial copies, each with its own points,
// evaluating trials at once) and leaving the problem's state that of the
// points the step ends at.
#pragma once

#include "optimisation/LineSearch.h"
#include "optimisation/NewtonProblem.h"
#include "optimisation/SpherePoints.h"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace surfacemaps
{

/// The first trial step along `direction`: 1, or less where a point would
/// move farther than `maxPointStep` (0: no cap). The whole step is scaled,
/// never clamped per point (which would change its direction).
double firstStep(const SpherePoints& points, const Eigen::VectorXd& direction, double maxPointStep);

/// Armijo searches from the points' positions at construction along one or
/// more directions, then take() or restore(). Trials run in up to `slots`
/// slots at once: slot 0 is the problem with `points`, slot s >= 1 a
/// NewtonProblem::trialCopy() with its own copy of the points (fewer slots
/// when the problem has no copies). The first trial in order that passes is
/// taken whatever the slot count, so the step is the one-by-one search's
/// (bit for bit when the copies compute what the problem would).
class TrialSearch
{
public:
  TrialSearch(NewtonProblem& problem, SpherePoints& points, int slots);

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
  /// re-centres their bases and leaves the problem's state theirs: the state
  /// of the slot whose last trial that was, or a fresh accept().
  void take(const Eigen::VectorXd& direction, double step, int tag);

  /// Puts the points back at the start, the problem's state theirs.
  void restore();

private:
  /// Slot s's last trial: along which direction, its step, and whether its
  /// check passed (so what the check computed holds for those points).
  struct LastTrial
  {
    int tag = -1;
    double step = 0.0;
    bool accepted = false;
  };

  double trial(int slot, const Eigen::VectorXd& direction, double step, int tag);
  /// accept() on the points as they are; throws if it fails (it passed
  /// before, so the problem is broken).
  void acceptAgain();

  NewtonProblem& Problem;
  SpherePoints& Points;
  const std::vector<Eigen::Vector3d> Start;
  std::vector<std::unique_ptr<NewtonProblem>> Copies;
  std::vector<SpherePoints> CopyPoints;
  std::vector<LastTrial> Last;
};

} // namespace surfacemaps
