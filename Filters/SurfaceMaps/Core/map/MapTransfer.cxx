#include "map/MapTransfer.h"

#include "geometry/SphereLocator.h"

#include <stdexcept>
#include <string>

namespace surfacemaps
{

namespace
{

void checkTriangles(const std::vector<std::array<int, 3>>& triangles,
  std::size_t vertices,
  const char* what)
{
  if (triangles.empty())
  {
    throw std::invalid_argument(std::string(what) + " has no triangles");
  }
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    for (int v : triangles[t])
    {
      if (v < 0 || static_cast<std::size_t>(v) >= vertices)
      {
        throw std::invalid_argument(std::string(what) + ": triangle " + std::to_string(t) +
          " uses vertex " + std::to_string(v) + " of " + std::to_string(vertices));
      }
    }
  }
}

} // namespace

SurfacePoint locateSurfacePoint(const SphereLocator& locator,
  const std::vector<Eigen::Vector3d>& sphere,
  const std::vector<std::array<int, 3>>& triangles,
  const Eigen::Vector3d& p,
  int start)
{
  const SphereLocation loc = start >= 0 ? locator.locateFrom(p, start) : locator.locate(p);
  SurfacePoint point;
  point.triangle = loc.triangle;
  point.barycentric = Eigen::Vector3d(loc.alpha, loc.beta, loc.gamma);
  const auto& tri = triangles[loc.triangle];
  for (int k = 0; k < 3; ++k)
  {
    if (sphere[tri[k]] == p)
    {
      point.barycentric = Eigen::Vector3d::Unit(k);
    }
  }
  return point;
}

std::vector<SurfacePoint> transferPoints(const std::vector<Eigen::Vector3d>& points,
  const std::vector<std::array<int, 3>>& commonTriangles,
  const std::vector<Eigen::Vector3d>& gFrom,
  const std::vector<Eigen::Vector3d>& gTo,
  const std::vector<Eigen::Vector3d>& fTo,
  const std::vector<std::array<int, 3>>& toTriangles,
  const MapTransferOptions& options)
{
  checkTriangles(toTriangles, fTo.size(), "the target input");
  std::vector<SurfacePoint> result(points.size());
  const SphereLocator onInput(fTo, toTriangles);
  if (options.identity)
  {
    for (std::size_t w = 0; w < points.size(); ++w)
    {
      result[w] = locateSurfacePoint(onInput, fTo, toTriangles, points[w], -1);
    }
    return result;
  }

  if (gFrom.size() != gTo.size())
  {
    throw std::invalid_argument("the common triangulation's two embeddings have " +
      std::to_string(gFrom.size()) + " and " + std::to_string(gTo.size()) + " vertices");
  }
  checkTriangles(commonTriangles, gFrom.size(), "the common triangulation");
  const std::vector<int>& start = options.startTriangles;
  if (!start.empty() && start.size() != gTo.size())
  {
    throw std::invalid_argument(std::to_string(start.size()) + " start triangles for " +
      std::to_string(gTo.size()) + " vertices of the common triangulation");
  }
  for (std::size_t v = 0; v < start.size(); ++v)
  {
    if (start[v] < 0 || static_cast<std::size_t>(start[v]) >= toTriangles.size())
    {
      throw std::invalid_argument("start triangle " + std::to_string(start[v]) + " of vertex " +
        std::to_string(v) + " is not a triangle of the target input");
    }
  }

  const SphereLocator onT(gFrom, commonTriangles);
  for (std::size_t w = 0; w < points.size(); ++w)
  {
    const SphereLocation loc = onT.locate(points[w]);
    const auto& tri = commonTriangles[loc.triangle];
    const Eigen::Vector3d q =
      (loc.alpha * gTo[tri[0]] + loc.beta * gTo[tri[1]] + loc.gamma * gTo[tri[2]]).normalized();
    result[w] =
      locateSurfacePoint(onInput, fTo, toTriangles, q, start.empty() ? -1 : start[tri[0]]);
  }
  return result;
}

Eigen::Vector3d evaluateSurfacePoint(const std::vector<Eigen::Vector3d>& points,
  const std::vector<std::array<int, 3>>& triangles,
  const SurfacePoint& p)
{
  const auto& tri = triangles[p.triangle];
  return p.barycentric[0] * points[tri[0]] + p.barycentric[1] * points[tri[1]] +
    p.barycentric[2] * points[tri[2]];
}

Eigen::Vector2d evaluateCornerValues(const std::vector<Eigen::Vector2d>& cornerValues,
  const SurfacePoint& p)
{
  const std::size_t c = 3 * static_cast<std::size_t>(p.triangle);
  return p.barycentric[0] * cornerValues[c] + p.barycentric[1] * cornerValues[c + 1] +
    p.barycentric[2] * cornerValues[c + 2];
}

} // namespace surfacemaps
