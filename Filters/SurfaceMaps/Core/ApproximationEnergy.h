// SurfaceMaps engine: how well T approximates an input surface.
#pragma once

#include "LiftedPoint.h"

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace surfacemaps
{

/// One input vertex x with sphere point q, inside the T triangle whose
/// corners are (ga, gb, gc) on that input's sphere and (La, Lb, Lc) lifted:
/// its base point is alpha La + beta Lb + gamma Lc with q's barycentric
/// coordinates in (ga, gb, gc) (DESIGN.md section 1.3). Returns the squared
/// distance x - base point.
template<typename T>
T squaredBaseDistance(const Eigen::Vector3d& q,
  const Eigen::Vector3d& x,
  const std::array<Eigen::Matrix<T, 3, 1>, 3>& g,
  const std::array<Eigen::Matrix<T, 3, 1>, 3>& L)
{
  // Barycentric coordinates of the ray 0 -> q in the chord triangle g: the
  // DESIGN.md formula with q fixed and the corners moving, rewritten as
  // alpha = det[q, b, c] / S, beta = det[q, c, a] / S, S = the sum of the
  // three (det[q, c, c - b] = det[q, b, c], ...). Each det is q x b (linear in
  // the corner) dotted with the other corner: few products of derivatives.
  const Eigen::Vector3d& qq = q;
  auto det = [&qq](const Eigen::Matrix<T, 3, 1>& b, const Eigen::Matrix<T, 3, 1>& c)
  {
    // q . (b x c) = (q x b) . c
    const T w0 = qq[1] * b[2] - qq[2] * b[1];
    const T w1 = qq[2] * b[0] - qq[0] * b[2];
    const T w2 = qq[0] * b[1] - qq[1] * b[0];
    return w0 * c[0] + w1 * c[1] + w2 * c[2];
  };
  const T da = det(g[1], g[2]), db = det(g[2], g[0]), dc = det(g[0], g[1]);
  const T den = da + db + dc;
  const T alpha = da / den;
  const T beta = db / den;
  T distance2(0.0);
  for (int r = 0; r < 3; ++r)
  {
    const T base = L[2][r] + alpha * (L[0][r] - L[2][r]) + beta * (L[1][r] - L[2][r]);
    const T d = x[r] - base;
    distance2 += d * d;
  }
  return distance2;
}

/// The approximation energy of one input vertex: weight * d^2 (soft term,
/// weight = area / eps^2), or with a hard bound eps > 0 the barrier
/// weight * d^3 / (bound^3 - d^3), infinite for d >= bound (DESIGN.md 1.3).
template<typename T>
T approximationEnergy(const T& distance2, double weight, double bound)
{
  if (bound <= 0.0)
  {
    return weight * distance2;
  }
  if (!(distance2 > 1e-300))
  {
    return T(0.0) * distance2; // d = 0: the barrier and its derivatives vanish
  }
  using std::sqrt;
  const T d3 = distance2 * sqrt(distance2);
  const double b3 = bound * bound * bound;
  if (!(d3 < b3))
  {
    return T(std::numeric_limits<double>::infinity());
  }
  return weight * d3 / (b3 - d3);
}

/// The approximation samples of one input: sphere point, position and
/// weight (vertex area, normalised so the weights sum to 1).
struct ApproximationSamples
{
  /// The input vertex each sample is.
  std::vector<int> vertices;
  std::vector<Eigen::Vector3d> spherePoints;
  std::vector<Eigen::Vector3d> positions;
  std::vector<double> weights;
};

/// Element functor (see ElementTerm): one element per sample, the three T
/// corners (on the embedding starting at `offset`) of the triangle that
/// contains the sample's sphere point.
struct ApproximationEnergy
{
  const ApproximationSamples* samples = nullptr;
  const std::vector<int>* sampleTriangle = nullptr;
  const std::vector<std::array<int, 3>>* triangles = nullptr;
  const std::vector<const Lift*>* lifts = nullptr;
  int offset = 0;
  /// Multiplies the sample weights (1 / eps^2 for the soft term).
  double scale = 1.0;
  /// Hard bound (> 0) or 0 for the soft quadratic term.
  double bound = 0.0;

  int numberOfElements() const { return static_cast<int>(this->sampleTriangle->size()); }
  std::array<int, 3> points(int e) const
  {
    const auto& t = (*this->triangles)[(*this->sampleTriangle)[e]];
    return { t[0] + this->offset, t[1] + this->offset, t[2] + this->offset };
  }
  template<typename T>
  T operator()(int e, const std::array<Eigen::Matrix<T, 3, 1>, 3>& p) const
  {
    const std::array<int, 3> idx = this->points(e);
    const auto& L = *this->lifts;
    // For derivatives T has six variables: the lifts' own form is T's.
    const std::array<Eigen::Matrix<T, 3, 1>, 3> lifted =
      liftTriangle<T>({ L[idx[0]], L[idx[1]], L[idx[2]] }, p, 0);
    const T d2 = squaredBaseDistance<T>(
      this->samples->spherePoints[e], this->samples->positions[e], p, lifted);
    return approximationEnergy<T>(d2, this->scale * this->samples->weights[e], this->bound);
  }
};

} // namespace surfacemaps
