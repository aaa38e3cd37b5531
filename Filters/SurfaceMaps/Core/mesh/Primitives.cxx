#include "mesh/Primitives.h"

#include <array>
#include <cmath>
#include <map>
#include <utility>

namespace surfacemaps
{

PolygonMesh makeTetrahedron()
{
  PolygonMesh mesh;
  const double s = 1.0 / std::sqrt(3.0);
  mesh.points = { { s, s, s }, { s, -s, -s }, { -s, s, -s }, { -s, -s, s } };
  mesh.addFace({ 0, 1, 2 });
  mesh.addFace({ 0, 3, 1 });
  mesh.addFace({ 0, 2, 3 });
  mesh.addFace({ 1, 3, 2 });
  return mesh;
}

PolygonMesh makeOctahedron()
{
  PolygonMesh mesh;
  mesh.points = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } };
  for (auto t : { std::array<int, 3>{ 0, 2, 4 },
         { 2, 1, 4 },
         { 1, 3, 4 },
         { 3, 0, 4 },
         { 2, 0, 5 },
         { 1, 2, 5 },
         { 3, 1, 5 },
         { 0, 3, 5 } })
  {
    mesh.addFace(t.begin(), t.end());
  }
  return mesh;
}

PolygonMesh makeIcosphere(int level)
{
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> points = { { -1, t, 0 },
    { 1, t, 0 },
    { -1, -t, 0 },
    { 1, -t, 0 },
    { 0, -1, t },
    { 0, 1, t },
    { 0, -1, -t },
    { 0, 1, -t },
    { t, 0, -1 },
    { t, 0, 1 },
    { -t, 0, -1 },
    { -t, 0, 1 } };
  for (auto& p : points)
  {
    p.normalize();
  }
  std::vector<std::array<int, 3>> faces = { { 0, 11, 5 },
    { 0, 5, 1 },
    { 0, 1, 7 },
    { 0, 7, 10 },
    { 0, 10, 11 },
    { 1, 5, 9 },
    { 5, 11, 4 },
    { 11, 10, 2 },
    { 10, 7, 6 },
    { 7, 1, 8 },
    { 3, 9, 4 },
    { 3, 4, 2 },
    { 3, 2, 6 },
    { 3, 6, 8 },
    { 3, 8, 9 },
    { 4, 9, 5 },
    { 2, 4, 11 },
    { 6, 2, 10 },
    { 8, 6, 7 },
    { 9, 8, 1 } };
  for (int l = 0; l < level; ++l)
  {
    std::map<std::pair<int, int>, int> midpoints;
    auto midpoint = [&](int a, int b)
    {
      const auto key = std::minmax(a, b);
      auto it = midpoints.find(key);
      if (it != midpoints.end())
      {
        return it->second;
      }
      points.push_back((points[a] + points[b]).normalized());
      const int index = static_cast<int>(points.size()) - 1;
      midpoints.emplace(key, index);
      return index;
    };
    std::vector<std::array<int, 3>> next;
    next.reserve(4 * faces.size());
    for (const auto& f : faces)
    {
      const int ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
      next.push_back({ f[0], ab, ca });
      next.push_back({ f[1], bc, ab });
      next.push_back({ f[2], ca, bc });
      next.push_back({ ab, bc, ca });
    }
    faces.swap(next);
  }
  PolygonMesh mesh;
  mesh.points = std::move(points);
  for (const auto& f : faces)
  {
    mesh.addFace(f.begin(), f.end());
  }
  return mesh;
}

PolygonMesh makeTorus(int majorSegments, int minorSegments, double R, double r)
{
  PolygonMesh mesh;
  for (int i = 0; i < majorSegments; ++i)
  {
    const double u = 2.0 * M_PI * i / majorSegments;
    for (int j = 0; j < minorSegments; ++j)
    {
      const double w = 2.0 * M_PI * j / minorSegments;
      mesh.points.emplace_back(
        (R + r * std::cos(w)) * std::cos(u), (R + r * std::cos(w)) * std::sin(u), r * std::sin(w));
    }
  }
  for (int i = 0; i < majorSegments; ++i)
  {
    for (int j = 0; j < minorSegments; ++j)
    {
      const int a = i * minorSegments + j;
      const int b = ((i + 1) % majorSegments) * minorSegments + j;
      const int c = ((i + 1) % majorSegments) * minorSegments + (j + 1) % minorSegments;
      const int d = i * minorSegments + (j + 1) % minorSegments;
      mesh.addFace({ a, b, c });
      mesh.addFace({ a, c, d });
    }
  }
  return mesh;
}

} // namespace surfacemaps
