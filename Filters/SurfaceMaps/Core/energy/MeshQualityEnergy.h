// SurfaceMaps engine: mesh quality of the common triangulation on one input.
#pragma once

#include "energy/LiftedPoint.h"
#include "energy/SymmetricDirichlet.h"

#include <array>
#include <cmath>
#include <vector>

namespace surfacemaps
{

/// meshQualityEnergy of a triangle given by its Gram entries (gramEntries).
template<typename T>
T meshQualityOfGram(const std::array<T, 3>& gram, double length)
{
  const double l2 = length * length;
  const std::array<double, 3> equilateral{ l2, l2, 0.5 * l2 };
  return symmetricDirichlet(equilateral, gram);
}

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
  return meshQualityOfGram<T>(gramEntries(a, b, c), length);
}

/// A lower bound of meshQualityOfGram(gram, length) over every length > 0,
/// below the smallest value by a relative margin (1e-12) far larger than the
/// rounding of either, so that it stays below the computed value too.
/// With x = length^2, G = (g0, g1, g2) and d = g0 g1 - g2^2, the energy is
/// 1/8 k (4 sqrt(d) / (3 x) + sqrt(3) x^2 / (2 d)) with k = g0 + g1 - g2
/// (half the sum of the squared edge lengths); its minimum over x is
/// 1/8 C k with C = 3 sqrt(3/4) / (3/2 sqrt(3/4))^(2/3), whatever d.
inline double meshQualityBound(const std::array<double, 3>& gram)
{
  static const double C = 3.0 * std::sqrt(0.75) / std::cbrt(2.25 * 0.75);
  return 0.125 * C * (gram[0] + gram[1] - gram[2]) * (1.0 - 1e-12);
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
