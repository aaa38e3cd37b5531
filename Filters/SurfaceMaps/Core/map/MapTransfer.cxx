#include "map/MapTransfer.h"

#include "geometry/SphereLocator.h"

#include <algorithm>
#include <complex>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <unordered_map>

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

// Per source triangle, its texture chart (a representative triangle): the
// components of the triangles joined across edges whose two vertices have
// equal corner values on both sides.
std::vector<int> textureCharts(const std::vector<std::array<int, 3>>& triangles,
  const std::vector<Eigen::Vector2d>& cornerValues)
{
  std::vector<int> parent(triangles.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&parent](int t)
  {
    while (parent[t] != t)
    {
      parent[t] = parent[parent[t]];
      t = parent[t];
    }
    return t;
  };
  // Undirected edge -> the first triangle seen with it.
  std::unordered_map<std::uint64_t, int> edges;
  edges.reserve(3 * triangles.size());
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int a = triangles[t][k], b = triangles[t][(k + 1) % 3];
      const std::uint64_t key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) |
        static_cast<std::uint32_t>(std::max(a, b));
      const auto found = edges.emplace(key, t);
      if (found.second)
      {
        continue;
      }
      const int u = found.first->second;
      // The cornerValues entries of vertex `v` in triangle `s`.
      auto value = [&](int s, int v) -> const Eigen::Vector2d&
      {
        const int c = triangles[s][0] == v ? 0 : (triangles[s][1] == v ? 1 : 2);
        return cornerValues[3 * static_cast<std::size_t>(s) + c];
      };
      if (value(t, a) == value(u, a) && value(t, b) == value(u, b))
      {
        parent[find(t)] = find(u);
      }
    }
  }
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
  {
    parent[t] = find(t);
  }
  return parent;
}

// The triangles around each vertex (compressed rows).
class VertexTriangles
{
public:
  VertexTriangles(const std::vector<std::array<int, 3>>& triangles, std::size_t vertices)
    : Offsets(vertices + 1, 0)
  {
    for (const auto& t : triangles)
    {
      for (int v : t)
      {
        ++this->Offsets[v + 1];
      }
    }
    for (std::size_t v = 0; v < vertices; ++v)
    {
      this->Offsets[v + 1] += this->Offsets[v];
    }
    this->Triangles.resize(this->Offsets.back());
    std::vector<int> next(this->Offsets.begin(), this->Offsets.end() - 1);
    for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
    {
      for (int v : triangles[t])
      {
        this->Triangles[next[v]++] = t;
      }
    }
  }

  struct Range
  {
    const int* first;
    const int* last;
    const int* begin() const { return this->first; }
    const int* end() const { return this->last; }
  };
  Range of(int v) const
  {
    return { this->Triangles.data() + this->Offsets[v],
      this->Triangles.data() + this->Offsets[v + 1] };
  }

private:
  std::vector<int> Offsets;
  std::vector<int> Triangles;
};

// The value the affine map of source triangle `s` (its corner values) gives
// to `x` projected onto the triangle's plane; `fallback` when s is degenerate.
Eigen::Vector2d extrapolateCornerValues(const std::vector<Eigen::Vector3d>& points,
  const std::array<int, 3>& s,
  const Eigen::Vector2d* values,
  const Eigen::Vector3d& x,
  const Eigen::Vector2d& fallback)
{
  const Eigen::Vector3d e1 = points[s[1]] - points[s[0]], e2 = points[s[2]] - points[s[0]];
  const Eigen::Vector3d d = x - points[s[0]];
  const double a = e1.dot(e1), b = e1.dot(e2), c = e2.dot(e2);
  const double det = a * c - b * b;
  if (!(det > 1e-24 * a * c))
  {
    return fallback;
  }
  const double w1 = (c * e1.dot(d) - b * e2.dot(d)) / det;
  const double w2 = (a * e2.dot(d) - b * e1.dot(d)) / det;
  return values[0] + w1 * (values[1] - values[0]) + w2 * (values[2] - values[0]);
}

// Per-corner values of a source mesh, carried onto the triangles of another
// mesh whose vertices lie on it (transferCornerValues).
class CornerValueCarrier
{
public:
  CornerValueCarrier(const std::vector<Eigen::Vector3d>& points,
    const std::vector<std::array<int, 3>>& triangles,
    const std::vector<Eigen::Vector2d>& values)
    : Points(points)
    , Triangles(triangles)
    , Values(values)
    , Chart(textureCharts(triangles, values))
    , Around(triangles, points.size())
  {
  }

  /// The three corner values of a triangle whose corners lie at `corners`.
  std::array<Eigen::Vector2d, 3> triangle(const std::array<SurfacePoint, 3>& corners) const
  {
    std::array<Eigen::Vector2d, 3> own;
    std::array<int, 3> charts;
    for (int k = 0; k < 3; ++k)
    {
      own[k] = evaluateCornerValues(this->Values, corners[k]);
      charts[k] = this->Chart[corners[k].triangle];
    }
    if (charts[0] == charts[1] && charts[1] == charts[2])
    {
      return own;
    }
    std::array<Eigen::Vector3d, 3> x;
    for (int k = 0; k < 3; ++k)
    {
      x[k] = evaluateSurfacePoint(this->Points, this->Triangles, corners[k]);
    }
    // Of the corners' charts, the one the triangle is least stretched in.
    double best = std::numeric_limits<double>::infinity();
    std::array<Eigen::Vector2d, 3> chosen = own;
    for (int k = 0; k < 3; ++k)
    {
      if (k > 0 && (charts[k] == charts[0] || (k == 2 && charts[2] == charts[1])))
      {
        continue;
      }
      const std::array<Eigen::Vector2d, 3> values = this->inChart(charts[k], corners, own, x);
      const Eigen::Vector2d lo = values[0].cwiseMin(values[1]).cwiseMin(values[2]);
      const Eigen::Vector2d hi = values[0].cwiseMax(values[1]).cwiseMax(values[2]);
      if ((hi - lo).maxCoeff() < best)
      {
        best = (hi - lo).maxCoeff();
        chosen = values;
      }
    }
    return chosen;
  }

private:
  // The triangle's values in chart `home`: the corners of other charts
  // carried into it, across a seam edge where there is one near the corner,
  // else by the affine map of a nearby triangle of the chart.
  std::array<Eigen::Vector2d, 3> inChart(int home,
    const std::array<SurfacePoint, 3>& corners,
    const std::array<Eigen::Vector2d, 3>& own,
    const std::array<Eigen::Vector3d, 3>& x) const
  {
    std::array<Eigen::Vector2d, 3> values = own;
    for (int k = 0; k < 3; ++k)
    {
      if (this->Chart[corners[k].triangle] == home ||
        this->acrossSeam(corners[k], x[k], home, values[k]))
      {
        continue;
      }
      const int s = this->homeTriangleNear(corners[k], x[k], home, corners, x);
      values[k] = extrapolateCornerValues(this->Points, this->Triangles[s],
        &this->Values[3 * static_cast<std::size_t>(s)], x[k], values[k]);
    }
    return values;
  }

  std::complex<double> at(int s, int v) const
  {
    const std::array<int, 3>& t = this->Triangles[s];
    const Eigen::Vector2d& c =
      this->Values[3 * static_cast<std::size_t>(s) + (t[0] == v ? 0 : (t[1] == v ? 1 : 2))];
    return { c.x(), c.y() };
  }

  bool positiveInTexture(int s) const
  {
    const std::array<int, 3>& t = this->Triangles[s];
    const std::complex<double> e1 = this->at(s, t[1]) - this->at(s, t[0]);
    const std::complex<double> e2 = this->at(s, t[2]) - this->at(s, t[0]);
    return std::imag(std::conj(e1) * e2) > 0.0;
  }

  // `value` of point p (at x, in another chart than `home`) carried into
  // chart `home` across the seam edge between the two charts nearest to x
  // among the edges at p's triangle's corners: the similarity (with a mirror
  // where the charts' orientations differ) that takes the edge's two values
  // on p's side to those on the home side, exact on the seam and at the
  // charts' own scale nearby. False (value untouched) when there is no such
  // edge: p lies deeper in its chart.
  bool acrossSeam(const SurfacePoint& p, const Eigen::Vector3d& x, int home,
    Eigen::Vector2d& value) const
  {
    using Complex = std::complex<double>;
    const int side = this->Chart[p.triangle];
    const Complex z(value.x(), value.y());
    bool found = false;
    double nearest = 0.0;
    Complex carried;
    for (int a : this->Triangles[p.triangle])
    {
      for (int u : this->Around.of(a))
      {
        for (int w : this->Around.of(a))
        {
          if (this->Chart[u] != home || this->Chart[w] != side)
          {
            continue;
          }
          for (int b : this->Triangles[w])
          {
            const std::array<int, 3>& tu = this->Triangles[u];
            if (b == a || (tu[0] != b && tu[1] != b && tu[2] != b))
            {
              continue;
            }
            const double d = ((this->Points[a] + this->Points[b]) / 2.0 - x).squaredNorm();
            const Complex wa = this->at(w, a), wb = this->at(w, b);
            const Complex ua = this->at(u, a), ub = this->at(u, b);
            if ((found && d >= nearest) || wb == wa)
            {
              continue;
            }
            carried = this->positiveInTexture(u) != this->positiveInTexture(w)
              ? ua + (ub - ua) / std::conj(wb - wa) * std::conj(z - wa)
              : ua + (ub - ua) / (wb - wa) * (z - wa);
            found = true;
            nearest = d;
          }
        }
      }
    }
    if (found)
    {
      value = Eigen::Vector2d(carried.real(), carried.imag());
    }
    return found;
  }

  // The triangle of chart `home` whose affine map best continues the chart
  // to x, the position of point p: the one nearest to x among the triangles
  // around p's triangle's corners, else the triangle of the triangle's
  // corner in `home` nearest to x.
  int homeTriangleNear(const SurfacePoint& p,
    const Eigen::Vector3d& x,
    int home,
    const std::array<SurfacePoint, 3>& corners,
    const std::array<Eigen::Vector3d, 3>& positions) const
  {
    int best = -1;
    double nearest = 0.0;
    auto consider = [&](int s, const Eigen::Vector3d& at)
    {
      if (best < 0 || (at - x).squaredNorm() < nearest)
      {
        best = s;
        nearest = (at - x).squaredNorm();
      }
    };
    for (int v : this->Triangles[p.triangle])
    {
      for (int s : this->Around.of(v))
      {
        const std::array<int, 3>& t = this->Triangles[s];
        if (this->Chart[s] == home)
        {
          consider(s, (this->Points[t[0]] + this->Points[t[1]] + this->Points[t[2]]) / 3.0);
        }
      }
    }
    if (best >= 0)
    {
      return best;
    }
    for (int k = 0; k < 3; ++k)
    {
      if (this->Chart[corners[k].triangle] == home)
      {
        consider(corners[k].triangle, positions[k]);
      }
    }
    return best;
  }

  const std::vector<Eigen::Vector3d>& Points;
  const std::vector<std::array<int, 3>>& Triangles;
  const std::vector<Eigen::Vector2d>& Values;
  const std::vector<int> Chart;
  const VertexTriangles Around;
};

} // namespace

std::vector<Eigen::Vector2d> transferCornerValues(const std::vector<Eigen::Vector3d>& sourcePoints,
  const std::vector<std::array<int, 3>>& sourceTriangles,
  const std::vector<Eigen::Vector2d>& cornerValues,
  const std::vector<std::array<int, 3>>& triangles,
  const std::vector<SurfacePoint>& points)
{
  checkTriangles(sourceTriangles, sourcePoints.size(), "the source");
  checkTriangles(triangles, points.size(), "the mesh");
  if (cornerValues.size() != 3 * sourceTriangles.size())
  {
    throw std::invalid_argument("corner values: " + std::to_string(cornerValues.size()) +
      " for " + std::to_string(sourceTriangles.size()) + " source triangles");
  }
  for (const SurfacePoint& p : points)
  {
    if (p.triangle < 0 || static_cast<std::size_t>(p.triangle) >= sourceTriangles.size())
    {
      throw std::invalid_argument("a point lies in source triangle " +
        std::to_string(p.triangle) + " of " + std::to_string(sourceTriangles.size()));
    }
  }
  const CornerValueCarrier carrier(sourcePoints, sourceTriangles, cornerValues);
  std::vector<Eigen::Vector2d> result(3 * triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    const std::array<Eigen::Vector2d, 3> values = carrier.triangle(
      { points[triangles[t][0]], points[triangles[t][1]], points[triangles[t][2]] });
    std::copy(values.begin(), values.end(), result.begin() + 3 * t);
  }
  return result;
}

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
