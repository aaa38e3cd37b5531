// SurfaceMaps engine: the bijectivity barrier of a sphere embedding.
#pragma once

#include "geometry/Predicates.h"
#include "optimisation/AutoDiff.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace surfacemaps
{

/// -log vol with vol = det[a, b, c] / 6 (the volume of the tetrahedron with the
/// origin); +inf when vol <= 0. Rounded on purpose: a Newton step that starts
/// from a sliver the exact test calls flat can still move it back (its
/// gradient is finite); what a step may end in is decided exactly (see
/// exactOrientationBarrier and the trial check of CommonTriangulation::update).
template<typename T>
T orientationBarrier(const Eigen::Matrix<T, 3, 1>& a,
  const Eigen::Matrix<T, 3, 1>& b,
  const Eigen::Matrix<T, 3, 1>& c)
{
  const T volume = a.dot(b.cross(c)) / 6.0;
  if (!(volume > 0.0))
  {
    return T(std::numeric_limits<double>::infinity());
  }
  using std::log;
  return -log(volume);
}

/// orientationBarrier for a state that is to be accepted (an edit of T): also
/// +inf where the rounded determinant is positive but the exact one is not,
/// so every state the optimisation keeps is one the exact certificate
/// accepts. Rounding error of det[a, b, c] for points near the unit sphere is
/// below 1e-15; below 1e-12 the exact predicate decides.
inline double exactOrientationBarrier(const Eigen::Vector3d& a,
  const Eigen::Vector3d& b,
  const Eigen::Vector3d& c)
{
  const double barrier = orientationBarrier<double>(a, b, c);
  if (barrier > -std::log(1e-12 / 6.0) && orient3dOrigin(a, b, c) <= 0)
  {
    return std::numeric_limits<double>::infinity();
  }
  return barrier;
}

/// -log vol(t) per triangle t = (a, b, c) of an embedding, vol(t) = det[a, b, c] / 6
/// (the volume of the tetrahedron with the origin); +inf when vol(t) <= 0. Keeps
/// every triangle positively oriented during optimisation. `offset` is added to
/// the vertex indices (the embedding's first point among all sphere points).
struct BarrierEnergy
{
  std::vector<std::array<int, 3>> triangles;
  int offset = 0;
  /// Optional: per triangle, a multiplier of its term (the caller's array,
  /// which must outlive the energy's use); null: 1 for every triangle.
  const double* scales = nullptr;

  int numberOfElements() const { return static_cast<int>(this->triangles.size()); }
  std::array<int, 3> points(int e) const
  {
    const auto& t = this->triangles[e];
    return { t[0] + this->offset, t[1] + this->offset, t[2] + this->offset };
  }
  template<typename T>
  T operator()(int e, const std::array<Eigen::Matrix<T, 3, 1>, 3>& p) const
  {
    const T barrier = orientationBarrier<T>(p[0], p[1], p[2]);
    return this->scales ? this->scales[e] * barrier : barrier;
  }
};

} // namespace surfacemaps
