// SurfaceMaps engine: whether a triangle of T covers as much of an input as
// its lift claims.
#pragma once

#include "energy/LiftedPoint.h"

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace surfacemaps
{

/// A triangle of T on input i has two areas that must agree: its lifted
/// triangle's (the flat triangle through its lifted corners, which the map
/// and mesh terms see) and the area of input i it covers on the sphere,
/// estimated as its chord triangle's area times `density` (input area per
/// sphere area where its corners lie). They disagree a thousandfold where T's
/// triangle is a sliver on sphere i but its corners lift to a fat triangle:
/// the input surface between the corners is folded into the sliver, and the
/// exact map squeezes everything inside the triangle into it, while no other
/// term sees it (corners only; input i may have no sample in the sliver).
/// Energy 1/2 (L + E) (L / E + E / L - 2) = (L - E)^2 (L + E) / (2 L E), with L
/// the lifted area and E the covered area: 0 where they agree, of the order of
/// the triangle's area for a mismatch of a few times, a barrier as either
/// goes to 0. +inf for a degenerate triangle.
template<typename T>
T coverageEnergy(const std::array<Eigen::Matrix<T, 3, 1>, 3>& sphere,
  const std::array<Eigen::Matrix<T, 3, 1>, 3>& lifted,
  double density)
{
  const Eigen::Matrix<T, 3, 1> cs = (sphere[1] - sphere[0]).cross(sphere[2] - sphere[0]);
  const Eigen::Matrix<T, 3, 1> cl = (lifted[1] - lifted[0]).cross(lifted[2] - lifted[0]);
  const T s2 = cs.squaredNorm();
  const T l2 = cl.squaredNorm();
  if (!(s2 > 0.0) || !(l2 > 0.0) || !(density > 0.0))
  {
    return T(std::numeric_limits<double>::infinity());
  }
  const T E = 0.5 * density * sqrt(s2);
  const T L = 0.5 * sqrt(l2);
  const T d = L - E;
  return d * d * (L + E) / (2.0 * L * E);
}

/// Element functor (see ElementTerm): one element per triangle of T, on the
/// embedding whose points start at `offset`; corners lifted through the
/// per-point lifts, the density per triangle held constant within a step.
struct CoverageEnergy
{
  const std::vector<std::array<int, 3>>* triangles = nullptr;
  const std::vector<const Lift*>* lifts = nullptr;
  /// Per triangle of T on this input.
  const double* densities = nullptr;
  int offset = 0;

  int numberOfElements() const { return static_cast<int>(this->triangles->size()); }
  std::array<int, 3> points(int e) const
  {
    const auto& t = (*this->triangles)[e];
    return { t[0] + this->offset, t[1] + this->offset, t[2] + this->offset };
  }
  template<typename T>
  T operator()(int e, const std::array<Eigen::Matrix<T, 3, 1>, 3>& p) const
  {
    const std::array<int, 3> idx = this->points(e);
    const auto& L = *this->lifts;
    const auto lifted = liftTriangle<T>({ L[idx[0]], L[idx[1]], L[idx[2]] }, p, 0);
    // For derivatives T has six variables, the lifts' form (see MeshQualityEnergy).
    return coverageEnergy<T>(p, lifted, this->densities[e]);
  }
};

} // namespace surfacemaps
