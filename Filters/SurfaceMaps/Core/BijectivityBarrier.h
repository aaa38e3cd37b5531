// SurfaceMaps engine: the bijectivity barrier of T's embeddings as an
// objective term with a cheap positive semi-definite Hessian.
#pragma once

#include "Objective.h"

#include <array>
#include <string>
#include <vector>

namespace surfacemaps
{

/// -log vol(t) per triangle t = (a, b, c), vol = det[a, b, c] / 6, +inf when
/// vol <= 0 (DESIGN.md section 1.3), for one embedding whose points start at
/// `offset`. Same energy as BarrierEnergy; the projected Hessian is the
/// Gauss-Newton part grad(vol) grad(vol)^T / vol^2 (+ eps I) instead of an
/// eigenvalue clamp of the exact Hessian grad grad^T / vol^2 - Hess(vol) / vol:
/// positive semi-definite by construction, equal to the exact one up to the
/// term that matters least where the barrier matters most (vol -> 0), and
/// without an eigendecomposition per triangle. With projectionEps < 0 the
/// exact Hessian is returned (for derivative checks).
class BijectivityBarrierTerm : public ObjectiveTerm
{
public:
  BijectivityBarrierTerm(const std::vector<std::array<int, 3>>* triangles, int offset)
    : Triangles(triangles)
    , Offset(offset)
  {
  }

  std::string name() const override { return "barrier"; }
  int numberOfElements() const override { return static_cast<int>(this->Triangles->size()); }
  int pointsPerElement() const override { return 3; }
  void elementPoints(int e, int* points) const override;
  void evaluateValues(const SpherePoints& points, double* values) const override;
  void evaluateDerivatives(const SpherePoints& points,
    double projectionEps,
    double* values,
    double* gradients,
    double* hessians) const override;

private:
  const std::vector<std::array<int, 3>>* Triangles;
  int Offset;
};

} // namespace surfacemaps
