// SurfaceMaps engine: the bijectivity barrier of a sphere embedding.
#pragma once

#include "geometry/Predicates.h"
#include "optimisation/AutoDiff.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <limits>
#include <vector>

namespace surfacemaps
{

/// -log vol with vol = det[a, b, c] / 6 (the volume of the tetrahedron with the
/// origin); +inf when the triangle is not positively oriented. Where the
/// rounded determinant is small enough for its sign to be wrong, the exact
/// predicate decides, so every state the optimisation accepts is positive as
/// the exact certificate sees it (a sliver that is positive only in floating
/// point would otherwise pass every line search and fail certification).
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
  // Rounding error of det[a, b, c] for points near the unit sphere is below
  // 1e-15; 1e-12 leaves a margin and still sends only slivers to the exact test.
  if (valueOf(volume) < 1e-12 / 6.0)
  {
    const auto primal = [](const Eigen::Matrix<T, 3, 1>& p)
    { return Eigen::Vector3d(valueOf(p[0]), valueOf(p[1]), valueOf(p[2])); };
    if (orient3dOrigin(primal(a), primal(b), primal(c)) <= 0)
    {
      return T(std::numeric_limits<double>::infinity());
    }
  }
  using std::log;
  return -log(volume);
}

/// -log vol(t) per triangle t = (a, b, c) of an embedding, vol(t) = det[a, b, c] / 6
/// (the volume of the tetrahedron with the origin); +inf when vol(t) <= 0. Keeps
/// every triangle positively oriented during optimisation. `offset` is added to
/// the vertex indices (the embedding's first point among all sphere points).
struct BarrierEnergy
{
  std::vector<std::array<int, 3>> triangles;
  int offset = 0;

  int numberOfElements() const { return static_cast<int>(this->triangles.size()); }
  std::array<int, 3> points(int e) const
  {
    const auto& t = this->triangles[e];
    return { t[0] + this->offset, t[1] + this->offset, t[2] + this->offset };
  }
  template<typename T>
  T operator()(int, const std::array<Eigen::Matrix<T, 3, 1>, 3>& p) const
  {
    return orientationBarrier<T>(p[0], p[1], p[2]);
  }
};

} // namespace surfacemaps
