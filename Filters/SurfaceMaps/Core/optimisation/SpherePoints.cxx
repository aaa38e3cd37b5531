#include "optimisation/SpherePoints.h"

#include <cmath>

namespace surfacemaps
{

SpherePoints::SpherePoints(std::vector<Eigen::Vector3d> points)
  : Positions(std::move(points))
  , Locked(this->Positions.size(), 0)
{
  for (Eigen::Vector3d& p : this->Positions)
  {
    p.normalize();
  }
  this->recentreBases();
  this->renumber();
}

Eigen::Matrix<double, 3, 2> SpherePoints::tangentBasis(const Eigen::Vector3d& p)
{
  // Cross with the coordinate axis least aligned with p: well conditioned.
  Eigen::Index axis;
  p.cwiseAbs().minCoeff(&axis);
  const Eigen::Vector3d b1 = p.cross(Eigen::Vector3d::Unit(axis)).normalized();
  Eigen::Matrix<double, 3, 2> B;
  B.col(0) = b1;
  B.col(1) = p.cross(b1);
  return B;
}

void SpherePoints::recentreBases()
{
  this->Bases.resize(this->Positions.size());
  for (std::size_t i = 0; i < this->Positions.size(); ++i)
  {
    this->Bases[i] = tangentBasis(this->Positions[i]);
  }
}

void SpherePoints::setLocked(int i, bool locked)
{
  this->Locked[i] = locked ? 1 : 0;
  this->renumber();
}

void SpherePoints::setLocked(const std::vector<char>& locked)
{
  this->Locked = locked;
  this->Locked.resize(this->Positions.size(), 0);
  this->renumber();
}

void SpherePoints::renumber()
{
  this->FirstVariable.assign(this->Positions.size(), -1);
  int next = 0;
  for (std::size_t i = 0; i < this->Positions.size(); ++i)
  {
    if (!this->Locked[i])
    {
      this->FirstVariable[i] = next;
      next += 2;
    }
  }
  this->NumberOfVariables = next;
}

void SpherePoints::retract(const Eigen::VectorXd& step, double t)
{
  for (std::size_t i = 0; i < this->Positions.size(); ++i)
  {
    const int v = this->FirstVariable[i];
    if (v >= 0)
    {
      this->Positions[i] =
        retraction(this->Positions[i], this->Bases[i], t * step[v], t * step[v + 1]);
    }
  }
}

void SpherePoints::setPositions(const std::vector<Eigen::Vector3d>& positions)
{
  this->Positions = positions;
}

} // namespace surfacemaps
