#include "geometry/MapMetrics.h"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace surfacemaps
{

namespace
{

// Mesh centred at its area-weighted centroid and scaled to unit total area.
std::vector<Eigen::Vector3d> normalised(const std::vector<Eigen::Vector3d>& x,
  const std::vector<std::array<int, 3>>& triangles)
{
  double area = 0.0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& t : triangles)
  {
    const double a = 0.5 * (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).norm();
    area += a;
    centroid += a * (x[t[0]] + x[t[1]] + x[t[2]]) / 3.0;
  }
  std::vector<Eigen::Vector3d> y(x.size());
  if (!(area > 0.0))
  {
    return x;
  }
  centroid /= area;
  const double scale = 1.0 / std::sqrt(area);
  for (std::size_t i = 0; i < x.size(); ++i)
  {
    y[i] = scale * (x[i] - centroid);
  }
  return y;
}

// The triangle's edges b - a, c - a in an orthonormal frame of its plane
// (first edge along x): an upper triangular 2x2 matrix, columns = edges.
Eigen::Matrix2d frame(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  const Eigen::Vector3d e1 = b - a, e2 = c - a;
  const double l1 = e1.norm();
  Eigen::Matrix2d M;
  M(0, 0) = l1;
  M(1, 0) = 0.0;
  M(0, 1) = l1 > 0.0 ? e1.dot(e2) / l1 : 0.0;
  M(1, 1) = l1 > 0.0 ? e1.cross(e2).norm() / l1 : 0.0;
  return M;
}

} // namespace

Eigen::Vector2d singularValues2x2(const Eigen::Matrix2d& J)
{
  // With J = [a b; c d]: s1,2 = (|(a+d, c-b)| +- |(a-d, c+b)|) / 2, which
  // stays accurate for nearly conformal J (where the textbook formula
  // sqrt((|J|^2 +- sqrt(|J|^4 - 4 det^2)) / 2) loses half the digits).
  const double p = std::hypot(J(0, 0) + J(1, 1), J(1, 0) - J(0, 1));
  const double q = std::hypot(J(0, 0) - J(1, 1), J(1, 0) + J(0, 1));
  return { 0.5 * (p + q), 0.5 * std::abs(p - q) };
}

MapMetrics measureMap(const std::vector<Eigen::Vector3d>& Pin,
  const std::vector<Eigen::Vector3d>& Qin,
  const std::vector<std::array<int, 3>>& triangles,
  const MapMetricsOptions& options)
{
  const std::vector<Eigen::Vector3d> P = normalised(Pin, triangles);
  const std::vector<Eigen::Vector3d> Q = normalised(Qin, triangles);
  const std::size_t n = triangles.size();
  MapMetrics m;
  m.s1.resize(n);
  m.s2.resize(n);
  m.distortion.resize(n);
  m.areaP.resize(n);
  m.areaQ.resize(n);
  const double inf = std::numeric_limits<double>::infinity();
  double sd = 0.0;
  for (std::size_t f = 0; f < n; ++f)
  {
    const auto& t = triangles[f];
    const Eigen::Matrix2d FP = frame(P[t[0]], P[t[1]], P[t[2]]);
    const Eigen::Matrix2d FQ = frame(Q[t[0]], Q[t[1]], Q[t[2]]);
    m.areaP[f] = 0.5 * FP(0, 0) * FP(1, 1);
    m.areaQ[f] = 0.5 * FQ(0, 0) * FQ(1, 1);
    if (!(m.areaP[f] > 0.0) || !(m.areaQ[f] > 0.0))
    {
      ++m.degenerateTriangles;
      m.s1[f] = inf;
      m.s2[f] = 0.0;
      m.distortion[f] = inf;
      sd = inf;
      continue;
    }
    const Eigen::Vector2d s = singularValues2x2(FQ * FP.inverse());
    m.s1[f] = s[0];
    m.s2[f] = s[1];
    m.distortion[f] = std::max(s[0], 1.0 / s[1]);
    sd += 0.25 *
      (m.areaQ[f] * (s[0] * s[0] + s[1] * s[1]) +
        m.areaP[f] * (1.0 / (s[0] * s[0]) + 1.0 / (s[1] * s[1])));
  }
  m.symmetricDirichlet = sd;
  m.maxDistortion = n > 0 ? *std::max_element(m.distortion.begin(), m.distortion.end()) : 0.0;
  m.thresholds = options.thresholds;
  m.fractionBelow = m.cumulativeCurve(options.thresholds);
  return m;
}

double MapMetrics::areaFractionBelow(double threshold) const
{
  double below = 0.0, total = 0.0;
  for (std::size_t f = 0; f < this->distortion.size(); ++f)
  {
    total += this->areaP[f];
    if (this->distortion[f] < threshold)
    {
      below += this->areaP[f];
    }
  }
  return total > 0.0 ? below / total : 0.0;
}

std::vector<double> MapMetrics::cumulativeCurve(const std::vector<double>& thresholds) const
{
  std::vector<double> curve;
  curve.reserve(thresholds.size());
  for (double x : thresholds)
  {
    curve.push_back(this->areaFractionBelow(x));
  }
  return curve;
}

double boundingBoxDiagonal(const std::vector<Eigen::Vector3d>& points)
{
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (const Eigen::Vector3d& p : points)
  {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

} // namespace surfacemaps
