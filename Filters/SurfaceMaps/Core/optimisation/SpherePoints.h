// SurfaceMaps engine: points on the unit sphere as optimisation variables.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "optimisation/AutoDiff.h"

#include <vector>

namespace surfacemaps
{

/// A set of points on the unit sphere (e.g. the vertices of several sphere
/// embeddings, one after the other), each with an orthonormal tangent basis
/// and two tangent-coordinate variables. A step x moves point p to
/// normalize(p + x_1 B_1 + x_2 B_2) (a retraction); the bases are then
/// re-centred at the new points. Locked points have no variables.
class SpherePoints
{
public:
  SpherePoints() = default;
  /// Points are normalised; all unlocked.
  explicit SpherePoints(std::vector<Eigen::Vector3d> points);

  int size() const { return static_cast<int>(this->Positions.size()); }
  const Eigen::Vector3d& position(int i) const { return this->Positions[i]; }
  const std::vector<Eigen::Vector3d>& positions() const { return this->Positions; }
  /// Tangent basis of point i (columns B_1, B_2), orthonormal, orthogonal to p_i.
  const Eigen::Matrix<double, 3, 2>& basis(int i) const { return this->Bases[i]; }

  /// Locks or unlocks points; renumbers the variables.
  void setLocked(int i, bool locked);
  /// Locks exactly the points with a non-zero entry; renumbers once.
  void setLocked(const std::vector<char>& locked);
  bool locked(int i) const { return this->FirstVariable[i] < 0; }
  /// Index of point i's first variable (its second is that + 1), -1 if locked.
  int variable(int i) const { return this->FirstVariable[i]; }
  int numberOfVariables() const { return this->NumberOfVariables; }

  /// Moves every unlocked point by the tangent step `t * step` (retraction)
  /// without re-centring the bases; use for line-search trials.
  void retract(const Eigen::VectorXd& step, double t);
  /// Restores positions saved by positions() and recomputes nothing else.
  void setPositions(const std::vector<Eigen::Vector3d>& positions);
  /// Recomputes the tangent bases at the current positions.
  void recentreBases();

  /// The retraction itself: normalize(p + x_1 B_1 + x_2 B_2).
  template<typename T>
  static Eigen::Matrix<T, 3, 1> retraction(const Eigen::Vector3d& p,
    const Eigen::Matrix<double, 3, 2>& B,
    const T& x1,
    const T& x2)
  {
    Eigen::Matrix<T, 3, 1> q;
    for (int k = 0; k < 3; ++k)
    {
      q[k] = p[k] + x1 * B(k, 0) + x2 * B(k, 1);
    }
    using std::sqrt;
    const T norm = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    return q / norm;
  }

  /// Point i as a function of its own two tangent variables, which are
  /// variables `first` and `first + 1` of T: the retraction's value, first and
  /// second derivatives at x = 0 (p, B and -p I), seeded directly. The value
  /// is p exactly, so derivative and value evaluations agree to the last bit.
  template<typename T>
  Eigen::Matrix<T, 3, 1> seeded(int i, int first) const
  {
    Eigen::Matrix<T, 3, 1> q;
    this->seedInto(i, first, q);
    return q;
  }

  /// seeded() written into q, whose derivatives must be zero (as a
  /// default-constructed one's are): no temporaries. A Dual with a Hessian
  /// is large (N + N^2 doubles), and every element seeds one per coordinate
  /// of each of its points, so the copies of seeded() cost more than the
  /// element's own arithmetic.
  template<typename T>
  void seedInto(int i, int first, Eigen::Matrix<T, 3, 1>& q) const
  {
    const Eigen::Vector3d& p = this->Positions[i];
    if constexpr (IsDual<T>::value)
    {
      const Eigen::Matrix<double, 3, 2>& B = this->Bases[i];
      for (int k = 0; k < 3; ++k)
      {
        q[k].val = p[k];
        q[k].grad[first] = B(k, 0);
        q[k].grad[first + 1] = B(k, 1);
        if constexpr (T::HasHessian)
        {
          q[k].Hess(first, first) = -p[k];
          q[k].Hess(first + 1, first + 1) = -p[k];
        }
      }
    }
    else
    {
      q = p.template cast<T>();
    }
  }

  /// An orthonormal tangent basis at the unit vector p.
  static Eigen::Matrix<double, 3, 2> tangentBasis(const Eigen::Vector3d& p);

private:
  void renumber();

  std::vector<Eigen::Vector3d> Positions;
  std::vector<Eigen::Matrix<double, 3, 2>> Bases;
  std::vector<int> FirstVariable;
  std::vector<char> Locked;
  int NumberOfVariables = 0;
};

} // namespace surfacemaps
