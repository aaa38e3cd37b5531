#include "energy/BijectivityBarrier.h"

#include <cmath>
#include <limits>

namespace surfacemaps
{

double BijectivityBarrierTerm::gaussNewton(const SpherePoints& points,
  int e,
  Eigen::Map<Eigen::Matrix<double, 6, 1>>& gradient,
  Eigen::Map<Eigen::Matrix<double, 6, 6>>& H) const
{
  using D = Dual<6, false>;
  const std::array<Eigen::Matrix<D, 3, 1>, 3> p = this->seededPoints<D>(points, e);
  const D volume = p[0].dot(p[1].cross(p[2])) / 6.0;
  if (!(volume.val > 0.0))
  {
    gradient.setZero();
    H.setZero();
    return std::numeric_limits<double>::infinity();
  }
  gradient = -volume.grad / volume.val;
  H.noalias() = gradient * gradient.transpose();
  const double* scales = this->energy().scales;
  if (scales)
  {
    gradient *= scales[e];
    H *= scales[e];
    return -scales[e] * std::log(volume.val);
  }
  return -std::log(volume.val);
}

} // namespace surfacemaps
