// SurfaceMaps engine: symmetric Dirichlet distortion between two triangles.
#pragma once

#include "optimisation/AutoDiff.h"

#include <Eigen/Core>

#include <array>

namespace surfacemaps
{

/// Gram entries (e1.e1, e2.e2, e1.e2) of the edges e1 = b - a, e2 = c - a:
/// all a triangle's intrinsic shape, independent of its placement in space.
template<typename T>
std::array<T, 3> gramEntries(const Eigen::Matrix<T, 3, 1>& a,
  const Eigen::Matrix<T, 3, 1>& b,
  const Eigen::Matrix<T, 3, 1>& c)
{
  const Eigen::Matrix<T, 3, 1> e1 = b - a, e2 = c - a;
  return { e1.dot(e1), e2.dot(e2), e1.dot(e2) };
}

/// The symmetric Dirichlet term of DESIGN.md section 6 for one triangle mapped
/// from P to Q: 1/4 (area_Q (s1^2 + s2^2) + area_P (s1^-2 + s2^-2)), with s1, s2
/// the singular values of the map's Jacobian J. From the Gram matrices G of the
/// two triangles' edges: s1^2 + s2^2 = tr(G_Q G_P^-1), s1^-2 + s2^-2 =
/// tr(G_P G_Q^-1), area = sqrt(det G) / 2. Orientation-blind: flips are kept
/// out by a barrier. +inf (or NaN) for a degenerate triangle.
template<typename T, typename U>
T symmetricDirichlet(const std::array<U, 3>& P, const std::array<T, 3>& Q)
{
  const U detP = P[0] * P[1] - P[2] * P[2];
  const T detQ = Q[0] * Q[1] - Q[2] * Q[2];
  if (!(detQ > 0.0) || !(detP > 0.0))
  {
    return T(std::numeric_limits<double>::infinity());
  }
  // tr(G_Q adj(G_P)) = tr(G_P adj(G_Q)) for 2x2 symmetric matrices.
  const T cross = Q[0] * P[1] + Q[1] * P[0] - 2.0 * (Q[2] * P[2]);
  using std::sqrt;
  return 0.125 * (sqrt(detQ) * cross / detP + sqrt(detP) * cross / detQ);
}

} // namespace surfacemaps
