// SurfaceMaps engine: projection of element Hessians to positive definite.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

namespace surfacemaps
{

/// Replaces the symmetric matrix H by the nearest matrix whose eigenvalues are
/// all >= eps (eigenvalue clamping). A matrix that already satisfies this is
/// recognised by a Cholesky factorisation of H - eps I and left untouched,
/// which skips the eigendecomposition for most elements. Returns true if H
/// was changed.
template<int N>
bool projectToPositiveDefinite(Eigen::Matrix<double, N, N>& H, double eps = 1e-9)
{
  using Matrix = Eigen::Matrix<double, N, N>;
  Matrix shifted = H;
  shifted.diagonal().array() -= eps;
  Eigen::LLT<Matrix> llt(shifted);
  if (llt.info() == Eigen::Success)
  {
    return false;
  }
  Eigen::SelfAdjointEigenSolver<Matrix> eig(H);
  Eigen::Matrix<double, N, 1> values = eig.eigenvalues().cwiseMax(eps);
  H = eig.eigenvectors() * values.asDiagonal() * eig.eigenvectors().transpose();
  return true;
}

} // namespace surfacemaps
