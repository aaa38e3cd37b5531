#include "statistics/Procrustes.h"

#include <Eigen/Dense>

#include <cmath>
#include <cstddef>

namespace surfacemaps
{

namespace
{

Eigen::Vector3d weightedCentroid(const ShapePoints& x, const std::vector<double>& w)
{
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (std::size_t v = 0; v < x.size(); ++v)
  {
    c += w[v] * x[v];
  }
  return c;
}

// sqrt(sum_v w_v |x_v - c|^2), c the weighted centroid.
double weightedRadius(const ShapePoints& x, const std::vector<double>& w)
{
  const Eigen::Vector3d c = weightedCentroid(x, w);
  double sum = 0.0;
  for (std::size_t v = 0; v < x.size(); ++v)
  {
    sum += w[v] * (x[v] - c).squaredNorm();
  }
  return std::sqrt(sum);
}

// x -> s (x - c) + c: a uniform scale about c.
Similarity scalingAbout(const Eigen::Vector3d& c, double s)
{
  Similarity scaling;
  scaling.Scale = s;
  scaling.Translation = c - s * c;
  return scaling;
}

ShapePoints transformed(const ShapePoints& x, const Similarity& T)
{
  ShapePoints y(x.size());
  for (std::size_t v = 0; v < x.size(); ++v)
  {
    y[v] = T.apply(x[v]);
  }
  return y;
}

// sum_i w_i T_i(x_i), skipping shapes of weight 0.
ShapePoints weightedMean(const std::vector<ShapePoints>& shapes,
  const std::vector<double>& weights,
  const std::vector<Similarity>& transforms)
{
  ShapePoints mean(shapes[0].size(), Eigen::Vector3d::Zero());
  for (std::size_t i = 0; i < shapes.size(); ++i)
  {
    if (weights[i] == 0.0)
    {
      continue;
    }
    for (std::size_t v = 0; v < mean.size(); ++v)
    {
      mean[v] += weights[i] * transforms[i].apply(shapes[i][v]);
    }
  }
  return mean;
}

} // namespace

Similarity Similarity::after(const Similarity& first) const
{
  Similarity composed;
  composed.Rotation = this->Rotation * first.Rotation;
  composed.Scale = this->Scale * first.Scale;
  composed.Translation = this->apply(first.Translation);
  return composed;
}

std::vector<double> vertexAreaWeights(const ShapePoints& x,
  const std::vector<std::array<int, 3>>& triangles)
{
  std::vector<double> area(x.size(), 0.0);
  double total = 0.0;
  for (const std::array<int, 3>& t : triangles)
  {
    const double a = 0.5 * (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).norm();
    for (int v : t)
    {
      area[v] += a / 3.0;
    }
    total += a;
  }
  if (!(total > 0.0) || !std::isfinite(total))
  {
    return std::vector<double>(x.size(), x.empty() ? 0.0 : 1.0 / x.size());
  }
  for (double& a : area)
  {
    a /= total;
  }
  return area;
}

Similarity fitSimilarity(const ShapePoints& x,
  const ShapePoints& y,
  const std::vector<double>& w,
  bool withScale)
{
  const Eigen::Vector3d mx = weightedCentroid(x, w), my = weightedCentroid(y, w);
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  double varianceX = 0.0;
  for (std::size_t v = 0; v < x.size(); ++v)
  {
    const Eigen::Vector3d dx = x[v] - mx;
    covariance += w[v] * (y[v] - my) * dx.transpose();
    varianceX += w[v] * dx.squaredNorm();
  }
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Vector3d sign(1.0, 1.0, 1.0);
  if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0.0)
  {
    sign(2) = -1.0; // no reflection: flip the direction of the smallest singular value
  }
  Similarity s;
  s.Rotation = svd.matrixU() * sign.asDiagonal() * svd.matrixV().transpose();
  if (withScale && varianceX > 0.0)
  {
    s.Scale = svd.singularValues().dot(sign) / varianceX;
  }
  s.Translation = my - s.Scale * s.Rotation * mx;
  return s;
}

double weightedRmsDistance(const ShapePoints& x,
  const ShapePoints& y,
  const std::vector<double>& w,
  const Similarity& T)
{
  double sum = 0.0;
  for (std::size_t v = 0; v < x.size(); ++v)
  {
    sum += w[v] * (T.apply(x[v]) - y[v]).squaredNorm();
  }
  return std::sqrt(sum);
}

namespace
{

// Normalises `weights` (the first n) to sum 1; the shapes of positive weight.
std::vector<std::size_t> normaliseWeights(std::vector<double>& weights, std::size_t n)
{
  double totalWeight = 0.0;
  for (double w : weights)
  {
    totalWeight += w;
  }
  std::vector<std::size_t> contributing;
  for (std::size_t i = 0; i < n; ++i)
  {
    weights[i] /= totalWeight;
    if (weights[i] > 0.0)
    {
      contributing.push_back(i);
    }
  }
  return contributing;
}

// A_v: the weighted mean of the contributing shapes' own vertexAreaWeights.
std::vector<double> meanVertexWeights(const std::vector<ShapePoints>& shapes,
  const std::vector<double>& weights,
  const std::vector<std::size_t>& contributing,
  const std::vector<std::array<int, 3>>& triangles)
{
  const std::size_t np = shapes[0].size();
  std::vector<double> A(np, 0.0);
  for (std::size_t i : contributing)
  {
    const std::vector<double> own = vertexAreaWeights(shapes[i], triangles);
    for (std::size_t v = 0; v < np; ++v)
    {
      A[v] += weights[i] * own[v];
    }
  }
  return A;
}

// What every step of the alignment reads.
struct AlignmentInputs
{
  const std::vector<ShapePoints>& shapes;
  const std::vector<double>& weights;           // normalised to sum 1
  const std::vector<std::size_t>& contributing; // the shapes of positive weight
  const std::vector<double>& A;                 // the vertex weights of every fit
  bool withScale;
  const ProcrustesOptions& options;
};

// T_i: every shape fitted onto `target`. Round r reports progress within
// [1 - 2^-r, 1 - 2^-(r+1)], so the fraction grows however many rounds run.
void alignAll(const AlignmentInputs& in,
  const ShapePoints& target,
  int round,
  std::vector<Similarity>& transforms)
{
  const std::size_t n = in.shapes.size();
  for (std::size_t i = 0; i < n; ++i)
  {
    transforms[i] = fitSimilarity(in.shapes[i], target, in.A, in.withScale);
    if (in.options.progress)
    {
      const double before = 1.0 - std::pow(0.5, round);
      in.options.progress(before + std::pow(0.5, round + 1) * (i + 1.0) / n);
    }
  }
}

// With scale, `x` scaled about its centroid to RMS radius 1; else as given.
ShapePoints normalised(const AlignmentInputs& in, const ShapePoints& x)
{
  const double radius = weightedRadius(x, in.A);
  return in.withScale && radius > 0.0
    ? transformed(x, scalingAbout(weightedCentroid(x, in.A), 1.0 / radius))
    : x;
}

// The Procrustes rounds: align onto the mean, average, until the mean moves
// less than the tolerance (relative to its radius) or the rounds run out.
ShapePoints iteratedMean(const AlignmentInputs& in, ProcrustesResult& result)
{
  ShapePoints mean = normalised(in, in.shapes[in.contributing[0]]);
  result.converged = false;
  while (result.iterations < in.options.maxIterations)
  {
    alignAll(in, mean, result.iterations, result.transforms);
    ShapePoints next = normalised(in, weightedMean(in.shapes, in.weights, result.transforms));
    ++result.iterations;
    const double radius = weightedRadius(next, in.A);
    const double change = weightedRmsDistance(mean, next, in.A);
    mean = std::move(next);
    if (!(radius > 0.0) || change <= in.options.tolerance * radius)
    {
      result.converged = true;
      break;
    }
  }
  return mean;
}

// The frame: the weighted mean size, then the rigid placement that fits the
// shapes as given best (a fit onto their unaligned weighted mean).
ShapePoints placedInFrame(const AlignmentInputs& in, ShapePoints mean)
{
  if (in.withScale)
  {
    double size = 0.0;
    for (std::size_t i : in.contributing)
    {
      size += in.weights[i] * weightedRadius(in.shapes[i], in.A);
    }
    const double radius = weightedRadius(mean, in.A);
    if (radius > 0.0)
    {
      mean = transformed(mean, scalingAbout(weightedCentroid(mean, in.A), size / radius));
    }
  }
  std::vector<Similarity> identity(in.shapes.size());
  const ShapePoints asGiven = weightedMean(in.shapes, in.weights, identity);
  return transformed(mean, fitSimilarity(mean, asGiven, in.A, false));
}

// The shapes aligned onto `mean` one last time and averaged.
ShapePoints alignedAverage(const AlignmentInputs& in,
  const ShapePoints& mean,
  ProcrustesResult& result)
{
  alignAll(in, mean, result.iterations, result.transforms);
  ShapePoints average = weightedMean(in.shapes, in.weights, result.transforms);
  if (in.withScale)
  {
    // Fitting each shape's scale onto the mean shrinks their average a
    // little; scale everything back to the chosen size.
    const double radius = weightedRadius(average, in.A);
    if (radius > 0.0)
    {
      const Similarity back =
        scalingAbout(weightedCentroid(average, in.A), weightedRadius(mean, in.A) / radius);
      for (Similarity& T : result.transforms)
      {
        T = back.after(T);
      }
      average = transformed(average, back);
    }
  }
  return average;
}

} // namespace

ProcrustesResult alignProcrustes(const std::vector<ShapePoints>& shapes,
  std::vector<double> weights,
  const std::vector<std::array<int, 3>>& triangles,
  const ProcrustesOptions& options)
{
  const std::size_t n = shapes.size();
  const std::vector<std::size_t> contributing = normaliseWeights(weights, n);

  ProcrustesResult result;
  result.vertexWeights = meanVertexWeights(shapes, weights, contributing, triangles);
  result.transforms.assign(n, Similarity());
  const AlignmentInputs in{ shapes,
    weights,
    contributing,
    result.vertexWeights,
    options.kind == AlignmentKind::Similarity,
    options };

  if (options.kind == AlignmentKind::None)
  {
    result.mean = weightedMean(shapes, weights, result.transforms);
  }
  else if (contributing.size() == 1)
  {
    // The mean is that shape as given; the others are aligned onto it.
    result.mean = shapes[contributing[0]];
    alignAll(in, result.mean, 0, result.transforms);
    result.transforms[contributing[0]] = Similarity();
  }
  else
  {
    const ShapePoints mean = placedInFrame(in, iteratedMean(in, result));
    result.mean = alignedAverage(in, mean, result);
  }

  result.rms.resize(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    result.rms[i] =
      weightedRmsDistance(shapes[i], result.mean, result.vertexWeights, result.transforms[i]);
  }
  return result;
}

} // namespace surfacemaps
