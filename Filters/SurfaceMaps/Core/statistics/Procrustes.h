// SurfaceMaps engine: generalized Procrustes alignment of shapes that share
// one connectivity (vertex v of every shape corresponds).
#pragma once

#include <Eigen/Core>

#include <array>
#include <functional>
#include <vector>

namespace surfacemaps
{

/// The points of one shape, vertex by vertex.
using ShapePoints = std::vector<Eigen::Vector3d>;

/// x -> Scale * Rotation * x + Translation (Rotation has det +1).
struct Similarity
{
  Eigen::Matrix3d Rotation = Eigen::Matrix3d::Identity();
  double Scale = 1.0;
  Eigen::Vector3d Translation = Eigen::Vector3d::Zero();

  Eigen::Vector3d apply(const Eigen::Vector3d& x) const
  {
    return this->Scale * (this->Rotation * x) + this->Translation;
  }
  /// This transformation applied after `first`.
  Similarity after(const Similarity& first) const;
};

/// A third of the area of the triangles around each vertex, normalised to sum
/// 1; uniform when the triangles have no finite positive area.
std::vector<double> vertexAreaWeights(const ShapePoints& points,
  const std::vector<std::array<int, 3>>& triangles);

/// The similarity minimising sum_v w_v |s R x_v + t - y_v|^2 with det R = +1
/// (Umeyama 1991, one 3x3 SVD); s = 1 unless `withScale`. `w` sums to 1.
Similarity fitSimilarity(const ShapePoints& x,
  const ShapePoints& y,
  const std::vector<double>& w,
  bool withScale);

/// sqrt(sum_v w_v |T(x_v) - y_v|^2).
double weightedRmsDistance(const ShapePoints& x,
  const ShapePoints& y,
  const std::vector<double>& w,
  const Similarity& T = {});

/// How shapes are aligned onto their mean.
enum class AlignmentKind
{
  None,      ///< as given
  Rigid,     ///< rotation and translation
  Similarity ///< rotation, translation and uniform scale
};

struct ProcrustesOptions
{
  AlignmentKind kind = AlignmentKind::Rigid;
  /// Converged when one round moves the mean by less than this area-weighted
  /// RMS distance, relative to the mean's RMS radius: tight, so that the
  /// result does not depend on the shape the iteration starts from.
  double tolerance = 1e-13;
  /// Rounds of "align every shape onto the mean, average" at most.
  int maxIterations = 200;
  /// Called after each shape's alignment with a fraction in [0, 1) that
  /// grows monotonically over the rounds (may throw to abort).
  std::function<void(double)> progress;
};

struct ProcrustesResult
{
  /// sum_i w_i T_i(x_i): the weighted mean of the aligned shapes.
  ShapePoints mean;
  /// T_i: shape i into the mean's frame (identity without alignment).
  std::vector<Similarity> transforms;
  /// sqrt(sum_v A_v |T_i(x_iv) - mean_v|^2) per shape.
  std::vector<double> rms;
  /// A_v: the vertex weights of every fit, the weighted mean of the shapes'
  /// own vertexAreaWeights (sum 1).
  std::vector<double> vertexWeights;
  int iterations = 0;
  bool converged = true;
};

/// Generalized Procrustes analysis (Gower 1975) with area weights: align
/// every shape onto the current mean (fitSimilarity with A_v), recompute the
/// weighted mean, repeat until it stops moving. Shapes of weight 0 are
/// aligned onto the mean but do not shape it; a single shape of positive
/// weight is the mean as given (identity transform).
///
/// The mean's frame (otherwise free) is fixed without reference to the
/// order of the shapes: its size (Similarity) is the weighted mean of the
/// shapes' RMS radii, and it is placed by the rigid motion that fits it best
/// to the shapes as given (sum_i w_i sum_v A_v |m_v - x_iv|^2 least), so
/// the mean lies where the inputs lie. The result is invariant under a
/// permutation of the shapes (with their weights) up to rounding and the
/// tolerance, as long as that placement is well defined (not when the
/// shapes' poses cancel out, e.g. a shape and its copy turned by half a
/// turn: then any rotation fits equally badly).
///
/// `weights` are >= 0 with a positive sum (normalised here); every shape has
/// the same number of points as `shapes[0]`.
ProcrustesResult alignProcrustes(const std::vector<ShapePoints>& shapes,
  std::vector<double> weights,
  const std::vector<std::array<int, 3>>& triangles,
  const ProcrustesOptions& options = {});

} // namespace surfacemaps
