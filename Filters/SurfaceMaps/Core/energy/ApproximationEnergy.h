// SurfaceMaps engine: how well T approximates an input surface.
#pragma once

#include "energy/LiftedPoint.h"
#include "optimisation/Objective.h"

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace surfacemaps
{

/// One input vertex x with sphere point q, inside the T triangle whose
/// corners are (ga, gb, gc) on that input's sphere and (La, Lb, Lc) lifted:
/// its base point is alpha La + beta Lb + gamma Lc with q's barycentric
/// coordinates in (ga, gb, gc) (DESIGN.md section 1.3). Returns x - base point.
template<typename T>
Eigen::Matrix<T, 3, 1> baseResidual(const Eigen::Vector3d& q,
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
  Eigen::Matrix<T, 3, 1> r;
  for (int k = 0; k < 3; ++k)
  {
    r[k] = x[k] - (L[2][k] + alpha * (L[0][k] - L[2][k]) + beta * (L[1][k] - L[2][k]));
  }
  return r;
}

/// The squared distance x - base point (see baseResidual).
template<typename T>
T squaredBaseDistance(const Eigen::Vector3d& q,
  const Eigen::Vector3d& x,
  const std::array<Eigen::Matrix<T, 3, 1>, 3>& g,
  const std::array<Eigen::Matrix<T, 3, 1>, 3>& L)
{
  const Eigen::Matrix<T, 3, 1> r = baseResidual<T>(q, x, g, L);
  return r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
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
struct ApproximationSampleSet
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
  const ApproximationSampleSet* samples = nullptr;
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
  /// Sample e's residual x - base point.
  template<typename T>
  Eigen::Matrix<T, 3, 1> residual(int e, const std::array<Eigen::Matrix<T, 3, 1>, 3>& p) const
  {
    const std::array<int, 3> idx = this->points(e);
    const auto& L = *this->lifts;
    // For derivatives T has six variables: the lifts' own form is T's.
    const std::array<Eigen::Matrix<T, 3, 1>, 3> lifted =
      liftTriangle<T>({ L[idx[0]], L[idx[1]], L[idx[2]] }, p, 0);
    return baseResidual<T>(this->samples->spherePoints[e], this->samples->positions[e], p, lifted);
  }
  /// Weight of sample e's squared distance (soft term).
  double weight(int e) const { return this->scale * this->samples->weights[e]; }
  template<typename T>
  T operator()(int e, const std::array<Eigen::Matrix<T, 3, 1>, 3>& p) const
  {
    const Eigen::Matrix<T, 3, 1> r = this->residual<T>(e, p);
    return approximationEnergy<T>(
      r[0] * r[0] + r[1] * r[1] + r[2] * r[2], this->weight(e), this->bound);
  }
};

/// The ApproximationEnergy term whose projected Hessian, for the soft term,
/// is the Gauss-Newton part 2 w J^T J (J the Jacobian of the base point; + eps
/// I) instead of an eigenvalue clamp of the exact Hessian: positive
/// semi-definite by construction, without an eigendecomposition per sample,
/// and exact where the base point fits (the residual's curvature term is
/// what it drops). The hard bound, values, gradients alone and the exact
/// Hessian (projectionEps < 0) are ElementTerm's.
class ApproximationTerm : public GaussNewtonTerm<3, ApproximationEnergy>
{
public:
  explicit ApproximationTerm(ApproximationEnergy energy)
    : GaussNewtonTerm<3, ApproximationEnergy>("approximation", std::move(energy))
  {
  }

protected:
  bool useGaussNewton() const override { return !(this->energy().bound > 0.0); }
  double gaussNewton(const SpherePoints& points,
    int e,
    Eigen::Map<Eigen::Matrix<double, 6, 1>>& gradient,
    Eigen::Map<Eigen::Matrix<double, 6, 6>>& H) const override
  {
    using D = Dual<6, false>;
    const ApproximationEnergy& approximation = this->energy();
    const Eigen::Matrix<D, 3, 1> r =
      approximation.residual<D>(e, this->template seededPoints<D>(points, e));
    const double w = approximation.weight(e);
    gradient = 2.0 * w * (r[0].val * r[0].grad + r[1].val * r[1].grad + r[2].val * r[2].grad);
    H.noalias() = 2.0 * w *
      (r[0].grad * r[0].grad.transpose() + r[1].grad * r[1].grad.transpose() +
        r[2].grad * r[2].grad.transpose());
    return w * (r[0].val * r[0].val + r[1].val * r[1].val + r[2].val * r[2].val);
  }
};

} // namespace surfacemaps
