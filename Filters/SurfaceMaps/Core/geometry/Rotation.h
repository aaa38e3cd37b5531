// SurfaceMaps engine: the best rotation between two point sets.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace surfacemaps
{

/// The rotation R (det +1) minimising sum |R a_k - b_k|^2 (Kabsch), e.g. to
/// turn one embedding's landmark points onto another's. Written here rather
/// than taken from vtkLandmarkTransform because the engine has no VTK types.
Eigen::Matrix3d bestRotation(const std::vector<Eigen::Vector3d>& from,
  const std::vector<Eigen::Vector3d>& to);

} // namespace surfacemaps
