#include "map/RotationSearch.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>

namespace surfacemaps
{

namespace
{

constexpr double Degree = M_PI / 180.0;

/// A few area-weighted sample points of a surface: where they are on it and
/// on its sphere.
struct ScoredSamples
{
  std::vector<Eigen::Vector3d> positions, spherePoints;
  std::vector<double> weights;
};

ScoredSamples scoredSamples(const PreparedInput& s, int count)
{
  ScoredSamples out;
  const ApproximationSampleSet& all = s.samples;
  const std::size_t n = all.positions.size();
  const std::size_t stride = std::max<std::size_t>(1, n / static_cast<std::size_t>(std::max(1, count)));
  double sum = 0.0;
  for (std::size_t k = 0; k < n; k += stride)
  {
    out.positions.push_back(all.positions[k]);
    out.spherePoints.push_back(all.spherePoints[k]);
    out.weights.push_back(all.weights[k]);
    sum += all.weights[k];
  }
  for (double& w : out.weights)
  {
    w /= sum;
  }
  return out;
}

/// The point of surface s at sphere point p (its lift through the
/// containing triangle).
Eigen::Vector3d surfacePoint(const PreparedInput& s, const Eigen::Vector3d& p)
{
  return s.lifts[s.locator->locate(p).triangle](p);
}

/// Weighted Procrustes misfit of point pairs under the best proper rigid
/// motion: sum w |Q (a - abar) - (b - bbar)|^2 / sum w.
class RigidMisfit
{
public:
  void add(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double w)
  {
    this->W += w;
    this->Sa += w * a;
    this->Sb += w * b;
    this->Saa += w * a.squaredNorm();
    this->Sbb += w * b.squaredNorm();
    this->Sba += w * b * a.transpose();
  }

  double value() const
  {
    const Eigen::Vector3d ca = this->Sa / this->W, cb = this->Sb / this->W;
    const Eigen::Matrix3d M = this->Sba - this->W * cb * ca.transpose();
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Eigen::Vector3d sigma = svd.singularValues();
    const double sign = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1.0 : 1.0;
    const double spread = this->Saa - this->W * ca.squaredNorm() + this->Sbb - this->W * cb.squaredNorm();
    return std::max(0.0, spread - 2.0 * (sigma[0] + sigma[1] + sign * sigma[2])) / this->W;
  }

private:
  double W = 0.0, Saa = 0.0, Sbb = 0.0;
  Eigen::Vector3d Sa = Eigen::Vector3d::Zero(), Sb = Eigen::Vector3d::Zero();
  Eigen::Matrix3d Sba = Eigen::Matrix3d::Zero();
};

class Scorer
{
public:
  Scorer(const PreparedInput& fixed, const PreparedInput& moving, int samples)
    : Fixed(fixed)
    , Moving(moving)
    , FixedSamples(scoredSamples(fixed, samples))
    , MovingSamples(scoredSamples(moving, samples))
  {
  }

  /// Both directions of the initial map under R, each weighing one half.
  double operator()(const Eigen::Matrix3d& R) const
  {
    RigidMisfit misfit;
    const ScoredSamples& a = this->FixedSamples;
    for (std::size_t k = 0; k < a.positions.size(); ++k)
    {
      const Eigen::Vector3d p = R.transpose() * a.spherePoints[k];
      misfit.add(a.positions[k], surfacePoint(this->Moving, p.normalized()), 0.5 * a.weights[k]);
    }
    const ScoredSamples& b = this->MovingSamples;
    for (std::size_t k = 0; k < b.positions.size(); ++k)
    {
      const Eigen::Vector3d p = R * b.spherePoints[k];
      misfit.add(surfacePoint(this->Fixed, p.normalized()), b.positions[k], 0.5 * b.weights[k]);
    }
    return misfit.value();
  }

private:
  const PreparedInput& Fixed;
  const PreparedInput& Moving;
  ScoredSamples FixedSamples, MovingSamples;
};

/// Rotations spread over SO(3): each Fibonacci-sphere direction d as the
/// image of the z axis, turned about z before.
std::vector<Eigen::Matrix3d> rotationGrid(int directions, int turns)
{
  std::vector<Eigen::Matrix3d> grid;
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < directions; ++i)
  {
    const double z = 1.0 - (2.0 * i + 1.0) / directions;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const Eigen::Vector3d d(r * std::cos(golden * i), r * std::sin(golden * i), z);
    const Eigen::Matrix3d toD =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), d).toRotationMatrix();
    for (int j = 0; j < turns; ++j)
    {
      grid.push_back(toD * Eigen::AngleAxisd(2.0 * M_PI * j / turns, Eigen::Vector3d::UnitZ()).toRotationMatrix());
    }
  }
  return grid;
}

double angleBetween(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b)
{
  const double c = std::clamp(0.5 * ((a.transpose() * b).trace() - 1.0), -1.0, 1.0);
  return std::acos(c) / Degree;
}

struct Candidate
{
  Eigen::Matrix3d rotation;
  double misfit;
};

/// Coordinate descent over small turns about the three axes, the step
/// halved whenever none of the six improves.
Candidate refine(const Scorer& score, Candidate c, double step, double finest)
{
  while (step >= finest)
  {
    bool improved = false;
    for (int axis = 0; axis < 3; ++axis)
    {
      for (const double sign : { 1.0, -1.0 })
      {
        const Eigen::Matrix3d R =
          Eigen::AngleAxisd(sign * step * Degree, Eigen::Vector3d::Unit(axis)).toRotationMatrix() *
          c.rotation;
        const double misfit = score(R);
        if (misfit < c.misfit)
        {
          c = { R, misfit };
          improved = true;
        }
      }
    }
    if (!improved)
    {
      step *= 0.5;
    }
  }
  return c;
}

/// The best candidates at least `angle` degrees from every better one.
std::vector<Candidate> distinctBest(std::vector<Candidate> all, int count, double angle)
{
  std::sort(all.begin(), all.end(),
    [](const Candidate& a, const Candidate& b) { return a.misfit < b.misfit; });
  std::vector<Candidate> chosen;
  for (const Candidate& c : all)
  {
    if (static_cast<int>(chosen.size()) >= count)
    {
      break;
    }
    if (std::all_of(chosen.begin(), chosen.end(),
          [&](const Candidate& o) { return angleBetween(o.rotation, c.rotation) >= angle; }))
    {
      chosen.push_back(c);
    }
  }
  return chosen;
}

std::string number(double value, int digits)
{
  std::ostringstream text;
  text << std::setprecision(digits) << value;
  return text.str();
}

} // namespace

RotationSearchResult searchRotation(const PreparedInput& fixed,
  const PreparedInput& moving,
  const RotationSearchOptions& options)
{
  const Scorer score(fixed, moving, options.samples);
  std::vector<Candidate> grid;
  for (const Eigen::Matrix3d& R : rotationGrid(options.directions, options.turns))
  {
    grid.push_back({ R, score(R) });
  }
  // Half the grid's spacing: the refinement can reach any rotation of its cell.
  const double spacing = std::max(360.0 / options.turns,
    std::sqrt(4.0 * M_PI / options.directions) / Degree);
  std::vector<Candidate> refined;
  for (const Candidate& c : distinctBest(grid, options.candidates, options.distinctAngle))
  {
    refined.push_back(refine(score, c, 0.5 * spacing, options.finestStep));
  }
  const std::vector<Candidate> best =
    distinctBest(refined, 2, options.distinctAngle);
  RotationSearchResult result;
  result.rotation = best[0].rotation;
  result.misfit = best[0].misfit;
  result.runnerUpMisfit = std::numeric_limits<double>::infinity();
  if (best.size() > 1)
  {
    result.runnerUpMisfit = best[1].misfit;
    result.runnerUpAngle = angleBetween(best[0].rotation, best[1].rotation);
  }
  return result;
}

void alignWithoutLandmarks(std::vector<PreparedInput>& surfaces,
  const Logger& log,
  double closeCall,
  const RotationSearchOptions& options)
{
  for (std::size_t i = 1; i < surfaces.size(); ++i)
  {
    const RotationSearchResult found = searchRotation(surfaces[0], surfaces[i], options);
    const std::string name = "input " + std::to_string(surfaces[i].label);
    const std::string first = "input " + std::to_string(surfaces[0].label);
    if (!rotateEmbedding(surfaces[i], found.rotation))
    {
      log(Logger::Warning,
        name + ": the embedding turned onto " + first +
          "'s without landmarks does not certify; using it unturned");
      continue;
    }
    log(Logger::Info,
      name + ": embedding turned onto " + first + "'s without landmarks (rigid misfit " +
        number(found.misfit, 3) + ", the next distinct rotation " +
        number(found.runnerUpMisfit, 3) + ")");
    if (found.runnerUpMisfit <= (1.0 + closeCall) * found.misfit)
    {
      log(Logger::Warning,
        name + ": without landmarks its correspondence with " + first +
          " is uncertain: two rotations " + number(found.runnerUpAngle, 3) +
          " degrees apart fit within " + number(100.0 * closeCall, 3) +
          " % of each other; give a landmark or two");
    }
  }
}

} // namespace surfacemaps
