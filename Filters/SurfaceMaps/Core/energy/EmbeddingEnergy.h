// SurfaceMaps engine: the distortion energy of a sphere embedding.
#pragma once

#include "optimisation/AutoDiff.h"
#include "energy/SymmetricDirichlet.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace surfacemaps
{

/// Per triangle (a, b, c) of a mesh embedded on the sphere: the symmetric
/// Dirichlet distortion (DESIGN.md section 6) from the 3D triangle of the
/// same vertices to the chord triangle on the sphere, both meshes scaled to
/// unit total area, plus barriers that keep the embedding valid:
/// -barrierWeight log det[a, b, c] (orientation) and -barrierWeight log(a.b -
/// cos 140 deg) per edge (spherical edges shorter than 140 degrees). Works for
/// every level of a decimation hierarchy, whose triangles join input vertices.
/// Both total areas are parameters, held fixed within a Newton step.
struct EmbeddingEnergy
{
  std::vector<std::array<int, 3>> triangles;
  /// The input's vertex positions.
  const std::vector<Eigen::Vector3d>* input = nullptr;
  /// Total area of `triangles` in 3D and on the sphere (chords).
  double inputArea = 1.0;
  double chordArea = 4.0 * M_PI;
  /// Weight of the distortion term (0: barrier only).
  double distortionWeight = 1.0;
  double barrierWeight = 1e-4;
  /// Cosine of the largest allowed spherical edge length (140 degrees).
  double minEdgeCos = std::cos(140.0 * M_PI / 180.0);

  int numberOfElements() const { return static_cast<int>(this->triangles.size()); }
  std::array<int, 3> points(int e) const { return this->triangles[e]; }

  template<typename T>
  T operator()(int e, const std::array<Eigen::Matrix<T, 3, 1>, 3>& p) const
  {
    return this->triangleEnergy(this->triangles[e], p);
  }

  /// The energy of triangle t (input vertex indices) at sphere points p.
  /// On the unit sphere it depends on p only through det[a, b, c] and the
  /// Gram entries of the edges e1 = b - a, e2 = c - a (the points' dot
  /// products follow: a.b = 1 - |e1|^2 / 2, ...). Those four are computed with
  /// p's derivatives; the rest with derivatives in those four only, composed
  /// at the end: half the cost of carrying all derivatives. (The Gram entries
  /// come from the edge vectors, not from 2 - 2 a.b, which cancels to 0 for
  /// tiny triangles.)
  template<typename T>
  T triangleEnergy(const std::array<int, 3>& t,
    const std::array<Eigen::Matrix<T, 3, 1>, 3>& p) const
  {
    const Eigen::Matrix<T, 3, 1> e1 = p[1] - p[0];
    const Eigen::Matrix<T, 3, 1> e2 = p[2] - p[0];
    const std::array<T, 4> u = { p[0].dot(p[1].cross(p[2])), e1.dot(e1), e2.dot(e2), e1.dot(e2) };
    constexpr int variables = variablesOf<T>;
    if constexpr (variables > 4)
    {
      using D4 = Dual<4, T::HasHessian>;
      std::array<D4, 4> vars;
      for (int k = 0; k < 4; ++k)
      {
        vars[k] = D4::variable(u[k].val, k);
      }
      const D4 f = this->fromInvariants(t, vars);
      if (!std::isfinite(f.val))
      {
        return T(std::numeric_limits<double>::infinity());
      }
      return compose(f, u);
    }
    else
    {
      return this->fromInvariants(t, u);
    }
  }

  /// The energy from u = (det[a, b, c], e1.e1, e2.e2, e1.e2).
  template<typename T>
  T fromInvariants(const std::array<int, 3>& t, const std::array<T, 4>& u) const
  {
    const double inf = std::numeric_limits<double>::infinity();
    if (!(u[0] > 0.0))
    {
      return T(inf);
    }
    T energy = -this->barrierWeight * log(u[0]);
    // Squared lengths of the edges ab, ca and bc; a.b = 1 - |b - a|^2 / 2.
    const std::array<T, 3> squaredLengths = { u[1], u[2], u[1] + u[2] - 2.0 * u[3] };
    for (const T& l2 : squaredLengths)
    {
      const T slack = (1.0 - 0.5 * l2) - this->minEdgeCos;
      if (!(slack > 0.0))
      {
        return T(inf);
      }
      // Each edge is seen by two triangles: half the weight each.
      energy -= 0.5 * this->barrierWeight * log(slack);
    }
    if (this->distortionWeight > 0.0)
    {
      const auto& x = *this->input;
      std::array<double, 3> P = gramEntries(x[t[0]], x[t[1]], x[t[2]]);
      for (double& v : P)
      {
        v /= this->inputArea;
      }
      const double scale = 1.0 / this->chordArea;
      const std::array<T, 3> Q = { scale * u[1], scale * u[2], scale * u[3] };
      energy += this->distortionWeight * symmetricDirichlet(P, Q);
    }
    return energy;
  }
};

} // namespace surfacemaps
