#include "geometry/SphericalTriangulation.h"

#include "geometry/Predicates.h"

#include <cmath>

namespace surfacemaps
{

double signedSphericalArea(const Eigen::Vector3d& a,
  const Eigen::Vector3d& b,
  const Eigen::Vector3d& c)
{
  // tan(E / 2) = det[a, b, c] / (1 + a.b + b.c + c.a) (Van Oosterom and Strackee).
  const double det = a.dot(b.cross(c));
  const double den = 1.0 + a.dot(b) + b.dot(c) + c.dot(a);
  return 2.0 * std::atan2(det, den);
}

double sphericalDegree(const std::vector<Eigen::Vector3d>& points,
  const std::vector<std::array<int, 3>>& triangles)
{
  // Called for every line-search trial: worth both cores. The summation
  // order varies with the threads, far below what rounding the degree needs.
  const long long n = static_cast<long long>(triangles.size());
  double sum = 0.0;
#pragma omp parallel for reduction(+ : sum) schedule(static) if (n > 2000)
  for (long long f = 0; f < n; ++f)
  {
    const auto& t = triangles[f];
    sum += signedSphericalArea(points[t[0]], points[t[1]], points[t[2]]);
  }
  return sum / (4.0 * M_PI);
}

std::vector<int> invertedTriangles(const std::vector<Eigen::Vector3d>& points,
  const std::vector<std::array<int, 3>>& triangles)
{
  std::vector<int> inverted;
  for (std::size_t f = 0; f < triangles.size(); ++f)
  {
    const auto& t = triangles[f];
    if (orient3dOrigin(points[t[0]], points[t[1]], points[t[2]]) <= 0)
    {
      inverted.push_back(static_cast<int>(f));
    }
  }
  return inverted;
}

BijectivityCertificate certifyBijective(const std::vector<Eigen::Vector3d>& points,
  const std::vector<std::array<int, 3>>& triangles)
{
  BijectivityCertificate c;
  for (std::size_t f = 0; f < triangles.size(); ++f)
  {
    const auto& t = triangles[f];
    if (orient3dOrigin(points[t[0]], points[t[1]], points[t[2]]) <= 0 &&
      c.nonPositiveTriangles++ == 0)
    {
      c.firstNonPositive = static_cast<int>(f);
    }
  }
  c.degree = sphericalDegree(points, triangles);
  if (c.nonPositiveTriangles > 0)
  {
    c.reason = std::to_string(c.nonPositiveTriangles) +
      " triangles are not positively oriented on the sphere (first: triangle " +
      std::to_string(c.firstNonPositive) + ")";
  }
  else if (std::lround(c.degree) != 1)
  {
    // With every triangle positive the degree is a whole number; rounding
    // errors of the area sum are many orders below 1/2.
    c.reason = "the embedding covers the sphere " + std::to_string(c.degree) + " times";
  }
  c.bijective = c.reason.empty();
  return c;
}

} // namespace surfacemaps
