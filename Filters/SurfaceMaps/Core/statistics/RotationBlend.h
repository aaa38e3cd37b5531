// SurfaceMaps engine: blends of shapes of one connectivity that follow the
// rotations of their triangles (bending, rolling) instead of cutting across
// them.
#pragma once

#include "statistics/Procrustes.h"

#include <array>
#include <memory>
#include <vector>

namespace surfacemaps
{

/// sum_k c_k x_k taken triangle by triangle in rotation and stretch, then
/// integrated back into one surface (in the spirit of Alexa, Cohen-Or and
/// Levin 2000, "As-rigid-as-possible shape interpolation", and Xu et al.
/// 2005, "Poisson shape interpolation").
///
/// Why: a vertex-wise blend of two poses of a bent or turned part moves every
/// point along the chord between its positions, so the part shortens and
/// thins on the way (a tube bent by 180 degrees collapses half-way; a shape
/// turned by 90 degrees keeps cos 45 = 71 % of its width). Blending each
/// triangle's rotation by its angle keeps lengths.
///
/// Per triangle t and shape k: A_kt, the linear map taking shape 0's
/// triangle (two edges and the unit normal) onto shape k's, polar-decomposed
/// A_kt = R_kt S_kt (det R = +1, S symmetric). The rotation vectors w_kt of
/// R_kt are unwrapped (a rotation by theta about a is also one by
/// theta - 2 pi about a): over the mesh first (neighbouring triangles turn
/// alike), then along k (each shape's near what the previous one plus the
/// step between them predicts), so a part that turns past 180 degrees keeps
/// turning the same way. The blend for coefficients c is
///   A_t = exp(sum_k c_k w_kt) sum_k c_k S_kt,
/// and the points x minimise
///   sum_t area_0(t) sum_{edges ij of t} |x_j - x_i - A_t (x0_j - x0_i)|^2
///     + eps sum_v |x_v - xl_v|^2,
/// xl = sum_k c_k x_k (eps is 1e-12 of the mean stiffness: it only fixes the
/// translation, each connected part's, and points in no triangle), shifted
/// so that the centroid is xl's. With c the k-th unit vector the result is
/// shape k exactly (returned as given); a rigid motion between two shapes is
/// blended into the rigid motion by the blended angle; a blend of shapes
/// that differ by stretch alone is the vertex-wise one.
///
/// Shape 0 is the reference: its degenerate triangles (zero area) carry no
/// weight. Cost: the constructor decomposes every triangle of every shape
/// and factors one sparse matrix (the reference's edge Laplacian); blend()
/// solves with it (linear in the points).
class RotationBlend
{
public:
  /// Throws std::invalid_argument when `shapes` is empty, their sizes differ
  /// or a triangle uses a vertex outside them; std::runtime_error when the
  /// factorisation fails.
  RotationBlend(const std::vector<ShapePoints>& shapes,
    const std::vector<std::array<int, 3>>& triangles);
  ~RotationBlend();
  RotationBlend(const RotationBlend&) = delete;
  RotationBlend& operator=(const RotationBlend&) = delete;

  /// The blend for one coefficient per shape (summing to 1 for an affine
  /// blend; the interpolator's linear and Hermite weights do).
  ShapePoints blend(const std::vector<double>& c) const;

  /// The decomposition and the factored system (opaque).
  struct Data;

private:
  std::unique_ptr<Data> D;
};

} // namespace surfacemaps
