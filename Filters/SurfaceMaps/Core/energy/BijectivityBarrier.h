// SurfaceMaps engine: the bijectivity barrier of T's embeddings as an
// objective term with a cheap positive semi-definite Hessian.
#pragma once

#include "energy/BarrierEnergy.h"
#include "optimisation/Objective.h"

namespace surfacemaps
{

/// The BarrierEnergy term (-log vol per triangle of one embedding) whose
/// projected Hessian is the Gauss-Newton part grad(vol) grad(vol)^T / vol^2
/// (+ eps I) instead of an eigenvalue clamp of the exact Hessian
/// grad grad^T / vol^2 - Hess(vol) / vol: positive semi-definite by
/// construction, equal to the exact one up to the term that matters least
/// where the barrier matters most (vol -> 0), and without an
/// eigendecomposition per triangle. Values, gradients alone and the exact
/// Hessian (projectionEps < 0, for derivative checks) are ElementTerm's.
class BijectivityBarrierTerm : public GaussNewtonTerm<3, BarrierEnergy>
{
public:
  explicit BijectivityBarrierTerm(BarrierEnergy energy)
    : GaussNewtonTerm<3, BarrierEnergy>("barrier", std::move(energy))
  {
  }

protected:
  double gaussNewton(const SpherePoints& points,
    int e,
    Eigen::Map<Eigen::Matrix<double, 6, 1>>& gradient,
    Eigen::Map<Eigen::Matrix<double, 6, 6>>& H) const override;
};

} // namespace surfacemaps
