#include "BijectivityBarrier.h"

#include <cmath>
#include <limits>

namespace surfacemaps
{

namespace
{
constexpr int ParallelThreshold = 2000;
}

void BijectivityBarrierTerm::elementPoints(int e, int* points) const
{
  for (int k = 0; k < 3; ++k)
  {
    points[k] = (*this->Triangles)[e][k] + this->Offset;
  }
}

void BijectivityBarrierTerm::evaluateValues(const SpherePoints& points, double* values) const
{
  const int ne = this->numberOfElements();
#pragma omp parallel for schedule(static) if (ne > 20 * ParallelThreshold)
  for (int e = 0; e < ne; ++e)
  {
    const auto& t = (*this->Triangles)[e];
    const double volume =
      points.position(t[0] + this->Offset)
        .dot(points.position(t[1] + this->Offset).cross(points.position(t[2] + this->Offset))) /
      6.0;
    values[e] = volume > 0.0 ? -std::log(volume) : std::numeric_limits<double>::infinity();
  }
}

void BijectivityBarrierTerm::evaluateDerivatives(const SpherePoints& points,
  double projectionEps,
  double* values,
  double* gradients,
  double* hessians) const
{
  const int ne = this->numberOfElements();
  const bool exact = projectionEps < 0.0;
#pragma omp parallel for schedule(static) if (ne > ParallelThreshold)
  for (int e = 0; e < ne; ++e)
  {
    using D = Dual<6, false>;
    using DH = Dual<6, true>;
    const auto& t = (*this->Triangles)[e];
    double* g = gradients + static_cast<std::size_t>(e) * 6;
    if (exact && hessians)
    {
      std::array<Eigen::Matrix<DH, 3, 1>, 3> p;
      for (int k = 0; k < 3; ++k)
      {
        p[k] = points.seeded<DH>(t[k] + this->Offset, 2 * k);
      }
      const DH volume = p[0].dot(p[1].cross(p[2])) / 6.0;
      const DH energy =
        volume.val > 0.0 ? DH(-log(volume)) : DH(std::numeric_limits<double>::infinity());
      values[e] = energy.val;
      Eigen::Map<Eigen::Matrix<double, 6, 1>> gradient(g);
      gradient = energy.grad;
      Eigen::Map<Eigen::Matrix<double, 6, 6>>(hessians + static_cast<std::size_t>(e) * 36) =
        energy.Hess;
      continue;
    }
    std::array<Eigen::Matrix<D, 3, 1>, 3> p;
    for (int k = 0; k < 3; ++k)
    {
      p[k] = points.seeded<D>(t[k] + this->Offset, 2 * k);
    }
    const D volume = p[0].dot(p[1].cross(p[2])) / 6.0;
    Eigen::Map<Eigen::Matrix<double, 6, 1>> gradient(g);
    if (!(volume.val > 0.0))
    {
      values[e] = std::numeric_limits<double>::infinity();
      gradient.setZero();
      if (hessians)
      {
        Eigen::Map<Eigen::Matrix<double, 6, 6>>(hessians + static_cast<std::size_t>(e) * 36)
          .setZero();
      }
      continue;
    }
    values[e] = -std::log(volume.val);
    gradient = -volume.grad / volume.val;
    if (hessians)
    {
      Eigen::Map<Eigen::Matrix<double, 6, 6>> H(hessians + static_cast<std::size_t>(e) * 36);
      H.noalias() = gradient * gradient.transpose();
      H.diagonal().array() += projectionEps;
    }
  }
}

} // namespace surfacemaps
