#include "statistics/RotationBlend.h"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <numeric>
#include <queue>
#include <stdexcept>
#include <string>
#include <utility>

namespace surfacemaps
{

struct RotationBlend::Data
{
  std::vector<ShapePoints> shapes;
  std::vector<std::array<int, 3>> triangles;
  std::vector<double> weights; // area of the triangle on shape 0, 0 if degenerate
  std::vector<std::vector<Eigen::Vector3d>> rotations; // [k][t]: unwrapped rotation vectors
  std::vector<std::vector<Eigen::Matrix3d>> stretches; // [k][t]
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  double eps = 0.0;
};

namespace
{

constexpr double TwoPi = 2.0 * M_PI;

// [e1 e2 n] of triangle t on x: the edges from corner 0 and the unit normal
// (zero when the triangle is degenerate).
Eigen::Matrix3d triangleFrame(const ShapePoints& x, const std::array<int, 3>& t)
{
  const Eigen::Vector3d e1 = x[t[1]] - x[t[0]], e2 = x[t[2]] - x[t[0]];
  const Eigen::Vector3d n = e1.cross(e2);
  const double length = n.norm();
  Eigen::Matrix3d frame;
  frame.col(0) = e1;
  frame.col(1) = e2;
  frame.col(2) = length > 0.0 ? Eigen::Vector3d(n / length) : Eigen::Vector3d::Zero();
  return frame;
}

// A = R S with det R = +1 and S symmetric (a reflection goes into S).
void polar(const Eigen::Matrix3d& A, Eigen::Matrix3d& R, Eigen::Matrix3d& S)
{
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(A, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d U = svd.matrixU();
  Eigen::Vector3d sigma = svd.singularValues();
  if (U.determinant() * svd.matrixV().determinant() < 0.0)
  {
    U.col(2) *= -1.0;
    sigma(2) *= -1.0;
  }
  R = U * svd.matrixV().transpose();
  S = svd.matrixV() * sigma.asDiagonal() * svd.matrixV().transpose();
}

// The rotation vector of R with angle in [0, pi].
Eigen::Vector3d rotationVector(const Eigen::Matrix3d& R)
{
  const Eigen::AngleAxisd angleAxis(R);
  return angleAxis.angle() * angleAxis.axis();
}

Eigen::Matrix3d rotationMatrix(const Eigen::Vector3d& w)
{
  const double angle = w.norm();
  return angle > 0.0 ? Eigen::AngleAxisd(angle, w / angle).toRotationMatrix()
                     : Eigen::Matrix3d::Identity();
}

// Of the rotation vectors of w's rotation ((angle + 2 pi m) about w's axis;
// about any axis for the identity), the one nearest to `target`.
Eigen::Vector3d nearestEquivalent(const Eigen::Vector3d& w, const Eigen::Vector3d& target)
{
  const double angle = w.norm();
  if (!(angle > 0.0))
  {
    const double along = target.norm();
    return along > 0.0 ? Eigen::Vector3d(std::round(along / TwoPi) * TwoPi * target / along) : w;
  }
  const Eigen::Vector3d axis = w / angle;
  const double m = std::round((axis.dot(target) - angle) / TwoPi);
  return (angle + TwoPi * m) * axis;
}

// Triangles sharing an edge, among those of positive weight.
std::vector<std::vector<int>> neighbours(const std::vector<std::array<int, 3>>& triangles,
  const std::vector<double>& weights)
{
  std::map<std::pair<int, int>, std::vector<int>> byEdge;
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    for (int e = 0; e < 3 && weights[t] > 0.0; ++e)
    {
      const int a = triangles[t][e], b = triangles[t][(e + 1) % 3];
      byEdge[{ std::min(a, b), std::max(a, b) }].push_back(static_cast<int>(t));
    }
  }
  std::vector<std::vector<int>> result(triangles.size());
  for (const auto& [edge, around] : byEdge)
  {
    for (int t : around)
    {
      for (int u : around)
      {
        if (u != t)
        {
          result[t].push_back(u);
        }
      }
    }
  }
  return result;
}

// Makes rotation vectors continuous over the mesh: breadth first from the
// triangle that turns least (in each connected part), each triangle's
// replaced by its equivalent nearest to the one it was reached from.
void unwrapOverMesh(std::vector<Eigen::Vector3d>& w, const std::vector<std::vector<int>>& next)
{
  std::vector<int> order(w.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(),
    order.end(),
    [&w](int a, int b) { return w[a].squaredNorm() < w[b].squaredNorm(); });
  std::vector<char> reached(w.size(), 0);
  for (int seed : order)
  {
    if (reached[seed])
    {
      continue;
    }
    reached[seed] = 1;
    std::queue<int> front;
    front.push(seed);
    while (!front.empty())
    {
      const int t = front.front();
      front.pop();
      for (int u : next[t])
      {
        if (!reached[u])
        {
          reached[u] = 1;
          w[u] = nearestEquivalent(w[u], w[t]);
          front.push(u);
        }
      }
    }
  }
}

// Per shape and triangle: the polar factors of the map from shape 0's
// triangle; the rotations as unwrapped rotation vectors (see the class).
void decompose(RotationBlend::Data& d)
{
  const std::size_t nk = d.shapes.size(), nt = d.triangles.size();
  std::vector<std::vector<Eigen::Matrix3d>> R(nk, std::vector<Eigen::Matrix3d>(nt));
  d.stretches.assign(nk, std::vector<Eigen::Matrix3d>(nt));
  for (std::size_t t = 0; t < nt; ++t)
  {
    const Eigen::Matrix3d reference = triangleFrame(d.shapes[0], d.triangles[t]);
    const Eigen::Matrix3d inverse =
      d.weights[t] > 0.0 ? Eigen::Matrix3d(reference.inverse()) : Eigen::Matrix3d::Identity();
    for (std::size_t k = 0; k < nk; ++k)
    {
      polar(triangleFrame(d.shapes[k], d.triangles[t]) * inverse, R[k][t], d.stretches[k][t]);
    }
  }
  const std::vector<std::vector<int>> next = neighbours(d.triangles, d.weights);
  d.rotations.assign(nk, std::vector<Eigen::Vector3d>(nt));
  for (std::size_t t = 0; t < nt; ++t)
  {
    d.rotations[0][t] = rotationVector(R[0][t]);
  }
  for (std::size_t k = 1; k < nk; ++k)
  {
    std::vector<Eigen::Vector3d> step(nt);
    for (std::size_t t = 0; t < nt; ++t)
    {
      step[t] = rotationVector(R[k][t] * R[k - 1][t].transpose());
    }
    unwrapOverMesh(step, next);
    for (std::size_t t = 0; t < nt; ++t)
    {
      d.rotations[k][t] =
        nearestEquivalent(rotationVector(R[k][t]), d.rotations[k - 1][t] + step[t]);
    }
  }
}

const int Edges[3][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 } };

// The edge Laplacian of shape 0 weighted by triangle area, plus eps on the
// diagonal, factored.
void factor(RotationBlend::Data& d)
{
  const int n = static_cast<int>(d.shapes[0].size());
  std::vector<Eigen::Triplet<double>> entries;
  double diagonal = 0.0;
  for (std::size_t t = 0; t < d.triangles.size(); ++t)
  {
    const double w = d.weights[t];
    for (int e = 0; e < 3 && w > 0.0; ++e)
    {
      const int i = d.triangles[t][Edges[e][0]], j = d.triangles[t][Edges[e][1]];
      entries.emplace_back(i, i, w);
      entries.emplace_back(j, j, w);
      entries.emplace_back(i, j, -w);
      entries.emplace_back(j, i, -w);
      diagonal += 2.0 * w;
    }
  }
  // Small enough to leave the fit unbiased where the Laplacian holds (it
  // pulls towards the vertex-wise blend at eps / stiffness), large enough
  // for a stable factorisation: the translation it holds is set exactly
  // afterwards.
  d.eps = 1e-12 * (diagonal > 0.0 ? diagonal / n : 1.0);
  for (int v = 0; v < n; ++v)
  {
    entries.emplace_back(v, v, d.eps);
  }
  Eigen::SparseMatrix<double> L(n, n);
  L.setFromTriplets(entries.begin(), entries.end());
  d.solver.compute(L);
  if (d.solver.info() != Eigen::Success)
  {
    throw std::runtime_error("the rotation-aware blend could not factor its system");
  }
}

void checkShapes(const std::vector<ShapePoints>& shapes,
  const std::vector<std::array<int, 3>>& triangles)
{
  if (shapes.empty())
  {
    throw std::invalid_argument("no shapes to blend");
  }
  const std::size_t n = shapes[0].size();
  for (std::size_t k = 1; k < shapes.size(); ++k)
  {
    if (shapes[k].size() != n)
    {
      throw std::invalid_argument("shape " + std::to_string(k) + " has " +
        std::to_string(shapes[k].size()) + " points instead of " + std::to_string(n));
    }
  }
  for (const std::array<int, 3>& t : triangles)
  {
    for (int v : t)
    {
      if (v < 0 || static_cast<std::size_t>(v) >= n)
      {
        throw std::invalid_argument(
          "a triangle uses point " + std::to_string(v) + " of " + std::to_string(n));
      }
    }
  }
}

} // namespace

RotationBlend::RotationBlend(const std::vector<ShapePoints>& shapes,
  const std::vector<std::array<int, 3>>& triangles)
  : D(new Data)
{
  checkShapes(shapes, triangles);
  this->D->shapes = shapes;
  this->D->triangles = triangles;
  this->D->weights.resize(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    const Eigen::Matrix3d frame = triangleFrame(shapes[0], triangles[t]);
    this->D->weights[t] = 0.5 * frame.col(0).cross(frame.col(1)).norm();
  }
  decompose(*this->D);
  factor(*this->D);
}

RotationBlend::~RotationBlend() = default;

ShapePoints RotationBlend::blend(const std::vector<double>& c) const
{
  const Data& d = *this->D;
  const std::size_t nk = d.shapes.size(), n = d.shapes[0].size();
  if (c.size() != nk)
  {
    throw std::invalid_argument(
      std::to_string(c.size()) + " coefficients for " + std::to_string(nk) + " shapes");
  }
  std::vector<std::size_t> used;
  for (std::size_t k = 0; k < nk; ++k)
  {
    if (c[k] != 0.0)
    {
      used.push_back(k);
    }
  }
  if (used.size() == 1 && c[used[0]] == 1.0)
  {
    return d.shapes[used[0]];
  }
  Eigen::MatrixX3d linear = Eigen::MatrixX3d::Zero(n, 3);
  for (std::size_t k : used)
  {
    for (std::size_t v = 0; v < n; ++v)
    {
      linear.row(v) += c[k] * d.shapes[k][v].transpose();
    }
  }
  Eigen::MatrixX3d rhs = d.eps * linear;
  for (std::size_t t = 0; t < d.triangles.size(); ++t)
  {
    if (!(d.weights[t] > 0.0))
    {
      continue;
    }
    Eigen::Vector3d w = Eigen::Vector3d::Zero();
    Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
    for (std::size_t k : used)
    {
      w += c[k] * d.rotations[k][t];
      S += c[k] * d.stretches[k][t];
    }
    const Eigen::Matrix3d A = rotationMatrix(w) * S;
    for (const auto& edge : Edges)
    {
      const int i = d.triangles[t][edge[0]], j = d.triangles[t][edge[1]];
      const Eigen::Vector3d target = d.weights[t] * (A * (d.shapes[0][j] - d.shapes[0][i]));
      rhs.row(j) += target.transpose();
      rhs.row(i) -= target.transpose();
    }
  }
  Eigen::MatrixX3d x = d.solver.solve(rhs);
  // The translation is held by eps alone: set it exactly.
  const Eigen::RowVector3d shift = linear.colwise().mean() - x.colwise().mean();
  ShapePoints result(n);
  for (std::size_t v = 0; v < n; ++v)
  {
    result[v] = (x.row(v) + shift).transpose();
  }
  return result;
}

} // namespace surfacemaps
