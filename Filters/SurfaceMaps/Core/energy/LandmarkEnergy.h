// SurfaceMaps engine: soft landmark constraints on the sphere.
#pragma once

#include <Eigen/Core>

#include <array>
#include <vector>

namespace surfacemaps
{

/// Element functor (see ElementTerm): one element per landmark, the squared
/// distance on the sphere between the landmark's T vertex (point index) and
/// the input's landmark vertex on the input's embedding (target).
struct LandmarkEnergy
{
  std::vector<int> points_;
  std::vector<Eigen::Vector3d> targets;

  int numberOfElements() const { return static_cast<int>(this->points_.size()); }
  std::array<int, 1> points(int e) const { return { this->points_[e] }; }
  template<typename T>
  T operator()(int e, const std::array<Eigen::Matrix<T, 3, 1>, 1>& p) const
  {
    T energy(0.0);
    for (int r = 0; r < 3; ++r)
    {
      const T d = p[0][r] - this->targets[e][r];
      energy += d * d;
    }
    return energy;
  }
};

} // namespace surfacemaps
