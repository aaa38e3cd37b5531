#include "map/MappingOrder.h"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <tuple>

namespace surfacemaps
{

namespace
{

/// FNV-1a over the input's bytes (points, triangles, embedding, landmarks,
/// sizing): a tie-break that follows the content, not the place.
std::uint64_t contentHash(const MapInput& input)
{
  std::uint64_t hash = 1469598103934665603ull;
  const auto add = [&hash](const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < bytes; ++k)
    {
      hash = (hash ^ p[k]) * 1099511628211ull;
    }
  };
  for (const Eigen::Vector3d& x : input.mesh.points)
  {
    add(x.data(), 3 * sizeof(double));
  }
  for (const auto& t : input.mesh.triangles())
  {
    add(t.data(), sizeof t);
  }
  for (const Eigen::Vector3d& x : input.spherePositions)
  {
    add(x.data(), 3 * sizeof(double));
  }
  add(input.landmarks.data(), input.landmarks.size() * sizeof(int));
  add(input.sizing.data(), input.sizing.size() * sizeof(double));
  return hash;
}

/// The landmark configuration (rows in id order), centred, of unit norm;
/// empty with fewer than three landmarks.
Eigen::MatrixX3d landmarkShape(const MapInput& input)
{
  std::vector<std::pair<int, int>> byId;
  for (std::size_t v = 0; v < input.landmarks.size(); ++v)
  {
    if (input.landmarks[v] >= 0)
    {
      byId.emplace_back(input.landmarks[v], static_cast<int>(v));
    }
  }
  if (byId.size() < 3)
  {
    return {};
  }
  std::sort(byId.begin(), byId.end());
  Eigen::MatrixX3d shape(static_cast<Eigen::Index>(byId.size()), 3);
  for (std::size_t k = 0; k < byId.size(); ++k)
  {
    shape.row(static_cast<Eigen::Index>(k)) = input.mesh.points[byId[k].second].transpose();
  }
  shape.rowwise() -= shape.colwise().mean();
  const double norm = shape.norm();
  return norm > 0.0 ? Eigen::MatrixX3d(shape / norm) : Eigen::MatrixX3d();
}

/// The principal second moments of the surface scaled to unit area, about
/// its area centroid (ascending).
Eigen::Vector3d secondMoments(const MapInput& input)
{
  double area = 0.0;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Matrix3d moments = Eigen::Matrix3d::Zero();
  for (const auto& t : input.mesh.triangles())
  {
    const Eigen::Vector3d& a = input.mesh.points[t[0]];
    const Eigen::Vector3d& b = input.mesh.points[t[1]];
    const Eigen::Vector3d& c = input.mesh.points[t[2]];
    const double A = 0.5 * (b - a).cross(c - a).norm();
    area += A;
    centre += A * (a + b + c) / 3.0;
    // The exact second moment of a triangle: A/12 (sum x x^T + (sum x)(sum x)^T).
    const Eigen::Vector3d s = a + b + c;
    moments += A / 12.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  if (!(area > 0.0))
  {
    return Eigen::Vector3d::Zero();
  }
  centre /= area;
  // About the centroid, then at unit area (lengths scale by 1/sqrt(area), moments by 1/area^2).
  moments = (moments / area - centre * centre.transpose()) / area;
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(moments, Eigen::EigenvaluesOnly).eigenvalues();
}

/// Procrustes distance between two centred unit-norm configurations (rotations only).
double procrustesDistance(const Eigen::MatrixX3d& a, const Eigen::MatrixX3d& b)
{
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(a.transpose() * b, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Vector3d sigma = svd.singularValues();
  if ((svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0)
  {
    sigma[2] = -sigma[2]; // no reflection
  }
  return std::sqrt(std::max(0.0, 2.0 - 2.0 * sigma.sum()));
}

} // namespace

std::vector<int> mappingOrder(const std::vector<MapInput>& inputs, PairScheme pairs)
{
  const int n = static_cast<int>(inputs.size());
  std::vector<int> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  if (n < 3 || (pairs != PairScheme::All && pairs != PairScheme::Mean))
  {
    return order;
  }
  std::vector<std::uint64_t> hash;
  std::vector<Eigen::MatrixX3d> shapes;
  std::vector<Eigen::Vector3d> moments;
  bool landmarks = true;
  for (const MapInput& input : inputs)
  {
    hash.push_back(contentHash(input));
    shapes.push_back(landmarkShape(input));
    landmarks = landmarks && shapes.back().rows() > 0 && shapes.back().rows() == shapes[0].rows();
    moments.push_back(secondMoments(input));
  }
  // Each distance computed with its two inputs in content order, each sum
  // over its distances in ascending order: the same bits for any permutation.
  const auto distance = [&](int i, int j) {
    const auto [a, b] = std::minmax(i, j, [&hash](int x, int y) { return hash[x] < hash[y]; });
    return landmarks ? procrustesDistance(shapes[a], shapes[b]) : (moments[a] - moments[b]).norm();
  };
  std::vector<double> typicality(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
  {
    std::vector<double> d;
    for (int j = 0; j < n; ++j)
    {
      if (j != i)
      {
        d.push_back(distance(i, j));
      }
    }
    std::sort(d.begin(), d.end());
    typicality[i] = std::accumulate(d.begin(), d.end(), 0.0);
  }
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return std::tie(typicality[a], hash[a]) < std::tie(typicality[b], hash[b]);
  });
  return order;
}

} // namespace surfacemaps
