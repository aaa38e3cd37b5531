// SurfaceMaps engine: distortion of the map between two inputs through T.
#pragma once

#include "energy/LiftedPoint.h"
#include "energy/SymmetricDirichlet.h"

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace surfacemaps
{

/// Symmetric Dirichlet distortion of the linear map from the lifted triangle
/// (pa, pb, pc) on input i to (qa, qb, qc) on input j (DESIGN.md section 1.3,
/// both inputs at unit area): 1/4 (area_Q |J|_F^2 + area_P |J^-1|_F^2).
template<typename T>
T mapDistortionEnergy(const std::array<Eigen::Matrix<T, 3, 1>, 3>& P,
  const std::array<Eigen::Matrix<T, 3, 1>, 3>& Q)
{
  return symmetricDirichlet(gramEntries(P[0], P[1], P[2]), gramEntries(Q[0], Q[1], Q[2]));
}

/// Element functor (see ElementTerm): one element per triangle of T, six
/// points: its corners on the embedding starting at offsetP (input i), then on
/// the one starting at offsetQ (input j).
struct MapDistortionEnergy
{
  const std::vector<std::array<int, 3>>* triangles = nullptr;
  const std::vector<const Lift*>* lifts = nullptr;
  int offsetP = 0;
  int offsetQ = 0;

  int numberOfElements() const { return static_cast<int>(this->triangles->size()); }
  std::array<int, 6> points(int e) const
  {
    const auto& t = (*this->triangles)[e];
    return { t[0] + this->offsetP,
      t[1] + this->offsetP,
      t[2] + this->offsetP,
      t[0] + this->offsetQ,
      t[1] + this->offsetQ,
      t[2] + this->offsetQ };
  }
  /// Derivatives: the six Gram entries (three per side) with six variables
  /// each, the distortion as a function of those six, composed at the end
  /// (far cheaper than carrying twelve variables through every operation).
  template<typename T>
  T operator()(int e, const std::array<Eigen::Matrix<T, 3, 1>, 6>& p) const
  {
    const std::array<int, 6> idx = this->points(e);
    const auto& L = *this->lifts;
    const auto P = liftTriangle<T>({ L[idx[0]], L[idx[1]], L[idx[2]] }, p, 0);
    const auto Q = liftTriangle<T>({ L[idx[3]], L[idx[4]], L[idx[5]] }, p, 3);
    const auto gP = gramEntries(P[0], P[1], P[2]);
    const auto gQ = gramEntries(Q[0], Q[1], Q[2]);
    if constexpr (IsDual<T>::value)
    {
      using D6 = Dual<6, T::HasHessian>;
      std::array<D6, 3> vP, vQ;
      std::array<T, 6> u;
      for (int k = 0; k < 3; ++k)
      {
        vP[k] = D6::variable(gP[k].val, k);
        vQ[k] = D6::variable(gQ[k].val, 3 + k);
        embedInto(gP[k], 0, u[k]);
        embedInto(gQ[k], 6, u[3 + k]);
      }
      const D6 f = symmetricDirichlet(vP, vQ);
      if (!std::isfinite(f.val))
      {
        return T(std::numeric_limits<double>::infinity());
      }
      return compose(f, u);
    }
    else
    {
      return symmetricDirichlet(gP, gQ);
    }
  }
};

/// Element functor (see ElementTerm): the distortion from the inputs' mean
/// shape to input i (PairScheme::Mean), one element per triangle of T on the
/// embedding starting at `offset`: symmetricDirichlet from the triangle's
/// reference Gram entries (the mean over the inputs of its lifted triangles',
/// held constant within a Newton step like the target lengths) to its lifted
/// triangle on input i.
struct MeanShapeDistortionEnergy
{
  const std::vector<std::array<int, 3>>* triangles = nullptr;
  const std::vector<const Lift*>* lifts = nullptr;
  const std::vector<std::array<double, 3>>* references = nullptr;
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
    return symmetricDirichlet((*this->references)[e], gramEntries(lifted[0], lifted[1], lifted[2]));
  }
};

/// The mean of the Gram entries of one triangle's lifted copies: a mean of
/// positive definite matrices, so a valid triangle shape whenever every copy
/// is one (MeanShapeDistortionEnergy's reference).
template<typename Grams>
std::array<double, 3> meanGram(const Grams& grams)
{
  std::array<double, 3> mean{ 0.0, 0.0, 0.0 };
  for (const auto& g : grams)
  {
    for (int k = 0; k < 3; ++k)
    {
      mean[k] += g[k] / static_cast<double>(grams.size());
    }
  }
  return mean;
}

} // namespace surfacemaps
