// SurfaceMaps engine: lifting sphere points back onto an input surface.
#pragma once

#include "optimisation/AutoDiff.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>

namespace surfacemaps
{

/// The inverse of a sphere embedding inside one of its triangles: a sphere
/// point p in the chord triangle (a, b, c) of input triangle (A, B, C) lifts to
/// alpha A + beta B + gamma C with the barycentric coordinates of DESIGN.md
/// section 1.1. alpha and beta are ratios of linear forms in p, so the lift is
/// the projective map M p / (n . p): 12 numbers per triangle, cheap to
/// differentiate, valid (and smooth) while p stays in the triangle.
struct Lift
{
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  Eigen::Vector3d n = Eigen::Vector3d::UnitX();

  Lift() = default;
  Lift(const Eigen::Vector3d& A,
    const Eigen::Vector3d& B,
    const Eigen::Vector3d& C,
    const Eigen::Vector3d& a,
    const Eigen::Vector3d& b,
    const Eigen::Vector3d& c)
  {
    // alpha = p.(c x (c - b)) / p.n, beta = p.((c - a) x c) / p.n,
    // n = (c - a) x (c - b); lift = C + alpha (A - C) + beta (B - C).
    const Eigen::Vector3d ca = c - a, cb = c - b;
    this->n = ca.cross(cb);
    const Eigen::Vector3d ua = c.cross(cb), ub = ca.cross(c);
    this->M = C * this->n.transpose() + (A - C) * ua.transpose() + (B - C) * ub.transpose();
  }

  template<typename T>
  Eigen::Matrix<T, 3, 1> operator()(const Eigen::Matrix<T, 3, 1>& p) const
  {
    const T den = this->n[0] * p[0] + this->n[1] * p[1] + this->n[2] * p[2];
    Eigen::Matrix<T, 3, 1> q;
    for (int r = 0; r < 3; ++r)
    {
      q[r] = (this->M(r, 0) * p[0] + this->M(r, 1) * p[1] + this->M(r, 2) * p[2]) / den;
    }
    return q;
  }
};

/// The lifts of three corners of an element, with derivatives. Corner c is
/// element point `first + c`, which depends on the element's variables
/// 2 (first + c) and +1 only, so each lift is computed with two variables
/// (cheap) and placed at variables 2c, 2c + 1 of a six-variable result; for
/// a plain double the lifts themselves.
template<typename T, std::size_t NV>
auto liftTriangle(const std::array<const Lift*, 3>& lifts,
  const std::array<Eigen::Matrix<T, 3, 1>, NV>& p,
  int first)
{
  if constexpr (IsDual<T>::value)
  {
    using D2 = Dual<2, T::HasHessian>;
    using D6 = Dual<6, T::HasHessian>;
    std::array<Eigen::Matrix<D6, 3, 1>, 3> lifted;
    for (int c = 0; c < 3; ++c)
    {
      Eigen::Matrix<D2, 3, 1> q;
      for (int r = 0; r < 3; ++r)
      {
        q[r] = restrict<2>(p[first + c][r], 2 * (first + c));
      }
      const Eigen::Matrix<D2, 3, 1> L = (*lifts[c])(q);
      for (int r = 0; r < 3; ++r)
      {
        embedInto(L[r], 2 * c, lifted[c][r]);
      }
    }
    return lifted;
  }
  else
  {
    return std::array<Eigen::Matrix<T, 3, 1>, 3>{
      (*lifts[0])(p[first]), (*lifts[1])(p[first + 1]), (*lifts[2])(p[first + 2])
    };
  }
}

} // namespace surfacemaps
