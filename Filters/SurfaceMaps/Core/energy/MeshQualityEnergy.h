// SurfaceMaps engine: mesh quality of the common triangulation on one input.
#pragma once

#include "energy/LiftedPoint.h"
#include "energy/SymmetricDirichlet.h"

#include <array>
#include <vector>

namespace surfacemaps
{

/// Symmetric Dirichlet distortion (DESIGN.md section 6 form) from an
/// equilateral triangle of edge `length` to the lifted triangle (a, b, c):
/// smallest (= the triangle's area) when the lifted triangle is equilateral
/// with that edge length, so it drives both shape and size.
template<typename T>
T meshQualityEnergy(const Eigen::Matrix<T, 3, 1>& a,
  const Eigen::Matrix<T, 3, 1>& b,
  const Eigen::Matrix<T, 3, 1>& c,
  double length)
{
  const double l2 = length * length;
  const std::array<double, 3> equilateral{ l2, l2, 0.5 * l2 };
  return symmetricDirichlet(equilateral, gramEntries(a, b, c));
}

/// Element functor (see ElementTerm): one element per triangle of T, on the
/// embedding whose points start at `offset`; corners lifted through the
/// per-point lifts, target lengths per triangle held constant.
struct MeshQualityEnergy
{
  const std::vector<std::array<int, 3>>* triangles = nullptr;
  const std::vector<const Lift*>* lifts = nullptr;
  const std::vector<double>* lengths = nullptr;
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
    // For derivatives T has six variables: the lifts' own form is T's.
    return meshQualityEnergy<T>(lifted[0], lifted[1], lifted[2], (*this->lengths)[e]);
  }
};

} // namespace surfacemaps
