#include "BijectivityBarrier.h"

#include <cmath>
#include <limits>

namespace surfacemaps
{

void BijectivityBarrierTerm::evaluateDerivatives(const SpherePoints& points,
  double projectionEps,
  double* values,
  double* gradients,
  double* hessians) const
{
  if (!hessians || projectionEps < 0.0)
  {
    ElementTerm<3, BarrierEnergy>::evaluateDerivatives(
      points, projectionEps, values, gradients, hessians);
    return;
  }
  const int ne = this->numberOfElements();
#pragma omp parallel for schedule(static) if (ne > ParallelDerivativeThreshold)
  for (int e = 0; e < ne; ++e)
  {
    using D = Dual<6, false>;
    const std::array<Eigen::Matrix<D, 3, 1>, 3> p = this->seededPoints<D>(points, e);
    const D volume = p[0].dot(p[1].cross(p[2])) / 6.0;
    Eigen::Map<Eigen::Matrix<double, 6, 1>> gradient(gradients + static_cast<std::size_t>(e) * 6);
    Eigen::Map<Eigen::Matrix<double, 6, 6>> H(hessians + static_cast<std::size_t>(e) * 36);
    if (!(volume.val > 0.0))
    {
      values[e] = std::numeric_limits<double>::infinity();
      gradient.setZero();
      H.setZero();
      continue;
    }
    values[e] = -std::log(volume.val);
    gradient = -volume.grad / volume.val;
    H.noalias() = gradient * gradient.transpose();
    H.diagonal().array() += projectionEps;
  }
}

} // namespace surfacemaps
