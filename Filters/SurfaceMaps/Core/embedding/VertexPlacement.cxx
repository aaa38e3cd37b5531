// SurfaceMaps engine: vertex placement for the sphere embedding: the
// candidates in a one-ring's kernel, the star's energy, and a vertex's local
// Newton with its exact validity check.
#include "embedding/VertexPlacement.h"

#include "geometry/Predicates.h"
#include "optimisation/HessianProjection.h"
#include "optimisation/LineSearch.h"
#include "optimisation/SpherePoints.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace surfacemaps
{

namespace
{
// True if p joined to its ring gives positively oriented triangles and
// spherical edges shorter than the energy's limit, so the energy is finite.
bool validInRing(const Eigen::Vector3d& p,
  const std::vector<int>& ring,
  const std::vector<Eigen::Vector3d>& pos,
  double minEdgeCos)
{
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i)
  {
    if (orient3dOrigin(p, pos[ring[i]], pos[ring[(i + 1) % n]]) <= 0 ||
      !(p.dot(pos[ring[i]]) > minEdgeCos))
    {
      return false;
    }
  }
  return true;
}

// The energy of the triangles around c.removed if it were at p.
double starEnergy(const Collapse& c,
  const EmbeddingEnergy& energy,
  const std::vector<Eigen::Vector3d>& pos,
  const Eigen::Vector3d& p)
{
  const std::size_t n = c.ring.size();
  double e = 0.0;
  for (std::size_t i = 0; i < n && std::isfinite(e); ++i)
  {
    const std::array<int, 3> t{ c.removed, c.ring[i], c.ring[(i + 1) % n] };
    e += energy.triangleEnergy<double>(t, { p, pos[t[1]], pos[t[2]] });
  }
  return e;
}

// The candidates for c.removed's position: the one with the lowest star
// energy among those that qualify goes to `out`.
class KernelCandidates
{
public:
  KernelCandidates(const Collapse& c,
    const EmbeddingEnergy& energy,
    const std::vector<Eigen::Vector3d>& pos,
    Eigen::Vector3d& out)
    : C(c)
    , Energy(energy)
    , Pos(pos)
    , Out(out)
  {
  }

  // Whether `candidate` (normalised onto the sphere) qualifies with a finite
  // energy.
  bool consider(const Eigen::Vector3d& candidate)
  {
    if (!(candidate.norm() > 1e-12))
    {
      return false;
    }
    const Eigen::Vector3d p = candidate.normalized();
    if (!validInRing(p, this->C.ring, this->Pos, this->Energy.minEdgeCos))
    {
      return false;
    }
    const double e = starEnergy(this->C, this->Energy, this->Pos, p);
    if (e < this->Best)
    {
      this->Best = e;
      this->Out = p;
    }
    return std::isfinite(e);
  }

  bool found() const { return std::isfinite(this->Best); }

private:
  const Collapse& C;
  const EmbeddingEnergy& Energy;
  const std::vector<Eigen::Vector3d>& Pos;
  Eigen::Vector3d& Out;
  double Best = std::numeric_limits<double>::infinity();
};

// Points close to c.kept inside the angle its two ring edges make.
void considerNearKept(const Collapse& c,
  const std::vector<Eigen::Vector3d>& pos,
  KernelCandidates& candidates)
{
  const std::size_t n = c.ring.size();
  std::size_t iu = 0;
  while (iu < n && c.ring[iu] != c.kept)
  {
    ++iu;
  }
  if (iu == n)
  {
    return;
  }
  const Eigen::Vector3d& u = pos[c.kept];
  const Eigen::Vector3d& prev = pos[c.ring[(iu + n - 1) % n]];
  const Eigen::Vector3d& next = pos[c.ring[(iu + 1) % n]];
  // Tangent directions t with det[t, prev, u] > 0 and det[t, u, next] > 0.
  Eigen::Vector3d n1 = prev.cross(u), n2 = u.cross(next);
  n1 -= n1.dot(u) * u;
  n2 -= n2.dot(u) * u;
  Eigen::Vector3d t = n1.normalized() + n2.normalized();
  if (!(t.norm() > 1e-12))
  {
    return;
  }
  t.normalize();
  double shortest = 2.0;
  for (int w : c.ring)
  {
    if (w != c.kept)
    {
      shortest = std::min(shortest, (pos[w] - u).norm());
    }
  }
  // A few distances from u; further halving only while nothing qualifies.
  int tried = 0;
  for (double eps = 0.4 * shortest; eps > 1e-14; eps *= 0.5, ++tried)
  {
    const bool ok = candidates.consider(u + eps * t);
    if (tried >= 3 && (ok || candidates.found()))
    {
      break;
    }
  }
}

using D = Dual<2>;

// The star's energy with its gradient and Hessian in the tangent variables
// of c.removed at p (basis B).
D starEnergyWithDerivatives(const Collapse& c,
  const EmbeddingEnergy& energy,
  const std::vector<Eigen::Vector3d>& pos,
  const Eigen::Vector3d& p,
  const Eigen::Matrix<double, 3, 2>& B)
{
  const std::size_t n = c.ring.size();
  Eigen::Matrix<D, 3, 1> pv;
  for (int k = 0; k < 3; ++k)
  {
    pv[k] = D(p[k]);
    pv[k].grad = B.row(k).transpose();
    pv[k].Hess = -p[k] * Eigen::Matrix2d::Identity();
  }
  D e = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    const std::array<int, 3> t{ c.removed, c.ring[i], c.ring[(i + 1) % n] };
    e +=
      energy.triangleEnergy<D>(t, { pv, pos[t[1]].cast<D>().eval(), pos[t[2]].cast<D>().eval() });
  }
  return e;
}
} // namespace

bool placeInKernel(const Collapse& c,
  const EmbeddingEnergy& energy,
  const std::vector<Eigen::Vector3d>& pos,
  Eigen::Vector3d& out)
{
  const std::vector<Eigen::Vector3d>& x = *energy.input;
  KernelCandidates candidates(c, energy, pos, out);
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
  for (int w : c.ring)
  {
    centroid += pos[w];
    weighted += pos[w] / std::max(1e-300, (x[w] - x[c.removed]).norm());
  }
  candidates.consider(centroid);
  candidates.consider(weighted);
  considerNearKept(c, pos, candidates);
  return candidates.found();
}

void relaxVertex(const Collapse& c,
  const EmbeddingEnergy& energy,
  std::vector<Eigen::Vector3d>& pos,
  int iterations)
{
  const int v = c.removed;
  for (int it = 0; it < iterations; ++it)
  {
    const Eigen::Vector3d p = pos[v];
    const Eigen::Matrix<double, 3, 2> B = SpherePoints::tangentBasis(p);
    const D e = starEnergyWithDerivatives(c, energy, pos, p, B);
    if (!std::isfinite(e.val))
    {
      return;
    }
    Eigen::Matrix2d H = e.Hess;
    projectToPositiveDefinite<2>(H, 1e-12 * std::max(1.0, H.cwiseAbs().maxCoeff()));
    Eigen::Vector2d d = -H.ldlt().solve(e.grad);
    double slope = d.dot(e.grad);
    if (!(slope < 0.0))
    {
      d = -e.grad;
      slope = -e.grad.squaredNorm();
    }
    // Converged: the decrease a Newton step expects is negligible.
    if (!(-slope > 1e-10 * std::abs(e.val)))
    {
      return;
    }
    // The energy tests orientation in floating point, in the order of the
    // star's triangles; where the ring leaves a kernel only a few rounding
    // errors wide, it can call a position valid that the exact predicates
    // (the certificate's) call inverted. Such a trial is rejected here: once
    // accepted, no later step can repair it (the energy of some other corner
    // order is infinite from then on).
    LineSearchResult ls = armijoBacktracking(
      [&](double s)
      {
        const Eigen::Vector3d q = SpherePoints::retraction(p, B, s * d[0], s * d[1]);
        return validInRing(q, c.ring, pos, energy.minEdgeCos)
          ? starEnergy(c, energy, pos, q)
          : std::numeric_limits<double>::infinity();
      },
      e.val,
      slope,
      std::min(1.0, 0.5 / std::max(1e-12, d.norm())));
    if (!ls.success)
    {
      return;
    }
    pos[v] = SpherePoints::retraction(p, B, ls.step * d[0], ls.step * d[1]);
  }
}

} // namespace surfacemaps
