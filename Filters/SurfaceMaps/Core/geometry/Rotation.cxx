#include "geometry/Rotation.h"

#include <Eigen/LU>
#include <Eigen/SVD>

namespace surfacemaps
{

Eigen::Matrix3d bestRotation(const std::vector<Eigen::Vector3d>& from,
  const std::vector<Eigen::Vector3d>& to)
{
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  for (std::size_t k = 0; k < from.size() && k < to.size(); ++k)
  {
    M += to[k] * from[k].transpose();
  }
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
  if ((svd.matrixU() * svd.matrixV().transpose()).determinant() < 0)
  {
    D(2, 2) = -1.0;
  }
  return svd.matrixU() * D * svd.matrixV().transpose();
}

} // namespace surfacemaps
