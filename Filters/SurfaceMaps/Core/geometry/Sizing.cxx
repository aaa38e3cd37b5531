#include "geometry/Sizing.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace surfacemaps
{

namespace
{

double targetEdgeLength(double kappa, const SizingOptions& options)
{
  if (kappa == 0.0)
  {
    return options.maxEdgeLength;
  }
  const double eps = options.targetError;
  // Test in the form that also sends +inf and NaN to the minimum.
  if (!(kappa <= 2.0 / eps))
  {
    return options.minEdgeLength;
  }
  // Tiny kappa overflows to +inf, which the clamp takes care of.
  const double squared = 6.0 * eps / kappa - 3.0 * eps * eps;
  const double length = std::sqrt(std::max(squared, 0.0));
  return std::clamp(length, options.minEdgeLength, options.maxEdgeLength);
}

// Triangle f's vertex indices lie in [0, n).
void checkVertexIndices(std::size_t f, const std::array<int, 3>& t, std::size_t n)
{
  for (const int v : t)
  {
    if (v < 0 || static_cast<std::size_t>(v) >= n)
    {
      throw std::invalid_argument("triangle " + std::to_string(f) + " uses vertex " +
        std::to_string(v) + ", but the mesh has " + std::to_string(n) + " vertices");
    }
  }
}

// Per vertex: mixed area, cotangent Laplacian of the positions (the area
// gradient, 2 A H n) and the angle sum, scattered from the triangles.
struct CurvatureSums
{
  explicit CurvatureSums(std::size_t n)
    : area(n, 0.0)
    , angleSum(n, 0.0)
    , laplacian(n, Eigen::Vector3d::Zero())
  {
  }

  void addTriangle(const std::vector<Eigen::Vector3d>& points, const std::array<int, 3>& t)
  {
    const Eigen::Vector3d* p[3] = { &points[t[0]], &points[t[1]], &points[t[2]] };
    // One doubled area for all three corners, so the angles sum to pi.
    const double doubleArea = (*p[1] - *p[0]).cross(*p[2] - *p[0]).norm();
    double dot[3], cot[3];
    bool usable = doubleArea > 0.0 && std::isfinite(doubleArea);
    for (int c = 0; c < 3; ++c)
    {
      dot[c] = (*p[(c + 1) % 3] - *p[c]).dot(*p[(c + 2) % 3] - *p[c]);
      // atan2 is accurate for tiny and near-straight angles, and gives 0 or
      // pi (never NaN) on degenerate triangles, so the angle defect stays
      // well defined.
      this->angleSum[t[c]] += std::atan2(doubleArea, dot[c]);
      cot[c] = usable ? dot[c] / doubleArea : 0.0;
      usable = usable && std::isfinite(cot[c]);
    }
    if (!usable)
    {
      return;
    }
    const double triangleArea = 0.5 * doubleArea;
    const int obtuse = dot[0] < 0.0 ? 0 : dot[1] < 0.0 ? 1 : dot[2] < 0.0 ? 2 : -1;
    for (int c = 0; c < 3; ++c)
    {
      const int a = (c + 1) % 3, b = (c + 2) % 3;
      // Edge a-b, opposite corner c.
      const Eigen::Vector3d e = *p[a] - *p[b];
      const Eigen::Vector3d w = 0.5 * cot[c] * e;
      this->laplacian[t[a]] += w;
      this->laplacian[t[b]] -= w;
      // Mixed area (Meyer et al. 2003, Fig. 4): the Voronoi region of a
      // non-obtuse triangle, otherwise half / a quarter of the triangle.
      if (obtuse < 0)
      {
        const double voronoi = 0.125 * e.squaredNorm() * cot[c];
        this->area[t[a]] += voronoi;
        this->area[t[b]] += voronoi;
      }
      else
      {
        this->area[t[c]] += c == obtuse ? 0.5 * triangleArea : 0.25 * triangleArea;
      }
    }
  }

  std::vector<double> area, angleSum;
  std::vector<Eigen::Vector3d> laplacian;
};

} // namespace

std::vector<double> maxAbsCurvature(const std::vector<Eigen::Vector3d>& points,
  const std::vector<std::array<int, 3>>& triangles)
{
  const std::size_t n = points.size();
  CurvatureSums sums(n);
  // Serial scatter from the triangles: deterministic and O(n).
  for (std::size_t f = 0; f < triangles.size(); ++f)
  {
    checkVertexIndices(f, triangles[f], n);
    sums.addTriangle(points, triangles[f]);
  }

  std::vector<double> kappa(n, 0.0);
  const long long nv = static_cast<long long>(n);
#pragma omp parallel for schedule(static) if (nv > 2000)
  for (long long v = 0; v < nv; ++v)
  {
    const double A = sums.area[v];
    if (!(A > 0.0) || !std::isfinite(A))
    {
      continue;
    }
    const double H = sums.laplacian[v].norm() / (2.0 * A);
    const double K = (2.0 * M_PI - sums.angleSum[v]) / A;
    const double k = std::abs(H) + std::sqrt(std::max(H * H - K, 0.0));
    kappa[v] = std::isnan(k) ? 0.0 : k;
  }
  return kappa;
}

std::vector<double> curvatureSizing(const std::vector<Eigen::Vector3d>& points,
  const std::vector<std::array<int, 3>>& triangles,
  const SizingOptions& options)
{
  if (!(options.targetError > 0.0) || !std::isfinite(options.targetError))
  {
    throw std::invalid_argument("sizing: the target error must be finite and > 0");
  }
  if (!(options.minEdgeLength > 0.0) || !std::isfinite(options.minEdgeLength) ||
    !(options.minEdgeLength <= options.maxEdgeLength))
  {
    throw std::invalid_argument("sizing: the edge length bounds must satisfy 0 < min <= max");
  }
  std::vector<double> sizing = maxAbsCurvature(points, triangles);
  for (double& s : sizing)
  {
    s = targetEdgeLength(s, options);
  }
  return sizing;
}

} // namespace surfacemaps
