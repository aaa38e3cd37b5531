#include "geometry/SphereLocator.h"

#include "geometry/Predicates.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace surfacemaps
{

std::vector<std::array<int, 3>> triangleNeighbours(const std::vector<std::array<int, 3>>& triangles)
{
  const std::size_t nt = triangles.size();
  // Directed edges sorted by (from, to), each with its triangle.
  std::vector<std::pair<std::pair<int, int>, int>> edges;
  edges.reserve(3 * nt);
  for (std::size_t t = 0; t < nt; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      edges.push_back(
        { { triangles[t][(k + 1) % 3], triangles[t][(k + 2) % 3] }, static_cast<int>(t) });
    }
  }
  std::sort(edges.begin(), edges.end());
  std::vector<std::array<int, 3>> neighbours(nt, { -1, -1, -1 });
  for (std::size_t t = 0; t < nt; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::pair<int, int> opposite{ triangles[t][(k + 2) % 3], triangles[t][(k + 1) % 3] };
      const auto it = std::lower_bound(
        edges.begin(), edges.end(), std::pair<std::pair<int, int>, int>{ opposite, -1 });
      if (it == edges.end() || it->first != opposite)
      {
        throw std::invalid_argument("the triangulation is not closed");
      }
      neighbours[t][k] = it->second;
    }
  }
  return neighbours;
}

SphereLocator::SphereLocator(const std::vector<Eigen::Vector3d>& points,
  const std::vector<std::array<int, 3>>& triangles)
  : Points(points)
  , Triangles(triangles)
{
  this->VertexTriangle.assign(points.size(), -1);
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->VertexTriangle[triangles[t][k]] = static_cast<int>(t);
    }
  }
  try
  {
    this->Neighbours = triangleNeighbours(triangles);
  }
  catch (const std::invalid_argument&)
  {
    throw std::invalid_argument("SphereLocator needs a closed triangulation");
  }
  // About two vertices per cube-map cell.
  this->Resolution = std::max(1, static_cast<int>(std::sqrt(points.size() / 12.0)));
  this->Cells.assign(6 * this->Resolution * this->Resolution, {});
  for (std::size_t v = 0; v < points.size(); ++v)
  {
    if (this->VertexTriangle[v] >= 0)
    {
      this->Cells[this->cell(points[v])].push_back(static_cast<int>(v));
    }
  }
}

int SphereLocator::cell(const Eigen::Vector3d& p) const
{
  Eigen::Index axis;
  p.cwiseAbs().maxCoeff(&axis);
  const int face = 2 * static_cast<int>(axis) + (p[axis] < 0 ? 1 : 0);
  const double u = p[(axis + 1) % 3] / std::abs(p[axis]);
  const double w = p[(axis + 2) % 3] / std::abs(p[axis]);
  const int r = this->Resolution;
  const int i = std::clamp(static_cast<int>((u + 1.0) * 0.5 * r), 0, r - 1);
  const int j = std::clamp(static_cast<int>((w + 1.0) * 0.5 * r), 0, r - 1);
  return (face * r + i) * r + j;
}

int SphereLocator::nearestVertexTriangle(const Eigen::Vector3d& p) const
{
  // The nearest vertex in p's cell (or any vertex: the walk fixes the rest).
  const std::vector<int>& candidates = this->Cells[this->cell(p)];
  int best = -1;
  double bestDot = -2.0;
  for (int v : candidates)
  {
    const double d = this->Points[v].dot(p);
    if (d > bestDot)
    {
      bestDot = d;
      best = v;
    }
  }
  if (best < 0)
  {
    return 0;
  }
  return this->VertexTriangle[best];
}

SphereLocation SphereLocator::locate(const Eigen::Vector3d& p) const
{
  return this->locateFrom(p, this->nearestVertexTriangle(p));
}

SphereLocation SphereLocator::locateFrom(const Eigen::Vector3d& p, int start) const
{
  return walkOnSphere(
    p, start, this->Triangles, this->Neighbours, this->Points.data(), &this->Visited);
}

SphereLocation walkOnSphere(const Eigen::Vector3d& p,
  int start,
  const std::vector<std::array<int, 3>>& triangles,
  const std::vector<std::array<int, 3>>& neighbours,
  const Eigen::Vector3d* points,
  long long* visited)
{
  // Leave the triangle across an edge that has p on its outer side (exact
  // orientation), choosing among several such edges in rotating order so
  // that the walk rarely circles.
  auto locationIn = [&](int t)
  {
    const auto& tri = triangles[t];
    SphereLocation location;
    location.triangle = t;
    const auto w = SphereLocator::barycentric(p, points[tri[0]], points[tri[1]], points[tri[2]]);
    location.alpha = w[0];
    location.beta = w[1];
    location.gamma = w[2];
    return location;
  };
  int t = start;
  int rotate = 0;
  const long long limit = 4 * static_cast<long long>(triangles.size()) + 16;
  for (long long step = 0; step < limit; ++step)
  {
    if (visited)
    {
      ++*visited;
    }
    const auto& tri = triangles[t];
    int exit = -1;
    for (int m = 0; m < 3 && exit < 0; ++m)
    {
      const int k = (m + rotate) % 3;
      // p is on the inner side of edge ab when (a, b, p) is positively oriented.
      if (orient3dOrigin(points[tri[(k + 1) % 3]], points[tri[(k + 2) % 3]], p) < 0)
      {
        exit = k;
      }
    }
    if (exit < 0)
    {
      return locationIn(t);
    }
    t = neighbours[t][exit];
    rotate = (rotate + 1) % 3;
  }
  // A visibility walk can circle on a triangulation far from Delaunay (seen
  // on a strongly compressed embedding); every point lies in some triangle's
  // cone, so scan them all.
  for (std::size_t k = 0; k < triangles.size(); ++k)
  {
    const auto& tri = triangles[k];
    if (rayMeetsTriangle(points[tri[0]], points[tri[1]], points[tri[2]], p))
    {
      if (visited)
      {
        *visited += static_cast<long long>(k) + 1;
      }
      return locationIn(static_cast<int>(k));
    }
  }
  throw std::runtime_error("no triangle of the sphere embedding contains the point (is the "
                           "embedding bijective, the point finite?)");
}

std::array<double, 3> SphereLocator::barycentric(const Eigen::Vector3d& p,
  const Eigen::Vector3d& a,
  const Eigen::Vector3d& b,
  const Eigen::Vector3d& c)
{
  // Ray 0 -> p through the plane of abc (DESIGN.md section 1.1):
  // alpha = det[p, c, c-b] / det[p, c-a, c-b], beta = det[p, c-a, c] / det[p, c-a, c-b].
  const Eigen::Vector3d ca = c - a, cb = c - b;
  const double den = p.dot(ca.cross(cb));
  const double alpha = p.dot(c.cross(cb)) / den;
  const double beta = p.dot(ca.cross(c)) / den;
  return { alpha, beta, 1.0 - alpha - beta };
}

} // namespace surfacemaps
