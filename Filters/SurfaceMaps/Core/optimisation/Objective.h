// SurfaceMaps engine: energies made of per-element terms over sphere points.
#pragma once

#include "optimisation/AutoDiff.h"
#include "optimisation/HessianProjection.h"
#include "optimisation/SpherePoints.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace surfacemaps
{

/// One kind of element energy (e.g. the barrier of one embedding), evaluated
/// over all its elements at once. Each element depends on a fixed number of
/// sphere points; its variables are their tangent coordinates (2 per point,
/// locked points included: the assembly drops them). Implementations evaluate
/// elements in parallel into per-element slots, so results do not depend on
/// the number of threads. Use ElementTerm rather than deriving directly.
class ObjectiveTerm
{
public:
  virtual ~ObjectiveTerm() = default;
  virtual std::string name() const = 0;
  virtual int numberOfElements() const = 0;
  virtual int pointsPerElement() const = 0;
  /// The sphere points of element e (pointsPerElement() of them).
  virtual void elementPoints(int e, int* points) const = 0;
  /// values[e] for every element (+inf for an invalid element).
  virtual void evaluateValues(const SpherePoints& points, double* values) const = 0;
  /// Values, gradients (n per element) and, if hessians is not null, Hessians
  /// (n*n per element, column-major) projected to eigenvalues >= projectionEps
  /// (a negative projectionEps leaves them as they are, e.g. for derivative
  /// checks); n = 2 * pointsPerElement(). Elements [first, last) only, on the
  /// calling thread, into their own slots of arrays over all elements: callers
  /// split the elements between threads (see evaluateDerivatives).
  virtual void evaluateDerivatives(const SpherePoints& points,
    double projectionEps,
    int first,
    int last,
    double* values,
    double* gradients,
    double* hessians) const = 0;

  /// The same for all elements, on all threads.
  void evaluateDerivatives(const SpherePoints& points,
    double projectionEps,
    double* values,
    double* gradients,
    double* hessians) const;

  /// Elements per unit of work when the elements are split between threads
  /// (a derivative costs microseconds, so a chunk amortises taking it).
  static constexpr int DerivativeChunk = 64;
  /// Below this many elements, derivatives stay on one thread (waking
  /// threads takes microseconds).
  static constexpr int ParallelDerivativeThreshold = 200;
};

/// An ObjectiveTerm from an energy functor over NV sphere points:
///
///   struct MyEnergy {
///     int numberOfElements() const;
///     std::array<int, NV> points(int e) const;
///     template <typename T> T operator()(int e, const std::array<Eigen::Matrix<T, 3, 1>, NV>& p)
///     const;
///   };
///
/// The functor is written once; it is instantiated with double for values and
/// with Dual<2 NV> for derivatives. Return +inf for an invalid element.
template<int NV, typename Energy>
class ElementTerm : public ObjectiveTerm
{
public:
  static constexpr int N = 2 * NV;
  // Below this element count a parallel loop costs more than it saves
  // (waking threads takes microseconds; a value takes tens of nanoseconds).
  static constexpr int ParallelValueThreshold = 2000;

  ElementTerm(std::string name, Energy energy)
    : Name(std::move(name))
    , Functor(std::move(energy))
  {
  }

  std::string name() const override { return this->Name; }
  int numberOfElements() const override { return this->Functor.numberOfElements(); }
  int pointsPerElement() const override { return NV; }
  void elementPoints(int e, int* points) const override
  {
    const std::array<int, NV> p = this->Functor.points(e);
    std::copy(p.begin(), p.end(), points);
  }
  Energy& energy() { return this->Functor; }
  const Energy& energy() const { return this->Functor; }
  /// Element e's points seeded with T's variables (2 per point, in order).
  template<typename T>
  std::array<Eigen::Matrix<T, 3, 1>, NV> seededPoints(const SpherePoints& points, int e) const
  {
    const std::array<int, NV> idx = this->Functor.points(e);
    std::array<Eigen::Matrix<T, 3, 1>, NV> p;
    for (int k = 0; k < NV; ++k)
    {
      points.seedInto<T>(idx[k], 2 * k, p[k]);
    }
    return p;
  }

  void evaluateValues(const SpherePoints& points, double* values) const override
  {
    const int ne = this->numberOfElements();
#pragma omp parallel for schedule(static) if (ne > ParallelValueThreshold)
    for (int e = 0; e < ne; ++e)
    {
      const std::array<int, NV> idx = this->Functor.points(e);
      std::array<Eigen::Vector3d, NV> p;
      for (int k = 0; k < NV; ++k)
      {
        p[k] = points.position(idx[k]);
      }
      values[e] = this->Functor(e, p);
    }
  }

  using ObjectiveTerm::evaluateDerivatives;
  void evaluateDerivatives(const SpherePoints& points,
    double projectionEps,
    int first,
    int last,
    double* values,
    double* gradients,
    double* hessians) const override
  {
    if (hessians)
    {
      this->evaluate<true>(points, projectionEps, first, last, values, gradients, hessians);
    }
    else
    {
      this->evaluate<false>(points, projectionEps, first, last, values, gradients, hessians);
    }
  }

private:
  template<bool WithHessian>
  void evaluate(const SpherePoints& points,
    double projectionEps,
    int first,
    int last,
    double* values,
    double* gradients,
    double* hessians) const
  {
    using T = Dual<N, WithHessian>;
    for (int e = first; e < last; ++e)
    {
      const T energy = this->Functor(e, this->template seededPoints<T>(points, e));
      values[e] = energy.val;
      Eigen::Map<Eigen::Matrix<double, N, 1>>(gradients + static_cast<std::size_t>(e) * N) =
        energy.grad;
      if constexpr (WithHessian)
      {
        Eigen::Matrix<double, N, N> H = energy.Hess;
        if (std::isfinite(energy.val) && projectionEps >= 0.0)
        {
          projectToPositiveDefinite<N>(H, projectionEps);
        }
        Eigen::Map<Eigen::Matrix<double, N, N>>(hessians + static_cast<std::size_t>(e) * N * N) = H;
      }
    }
  }

  std::string Name;
  Energy Functor;
};

/// An ElementTerm whose projected Hessian is a Gauss-Newton one, positive
/// semi-definite by construction (no eigendecomposition per element):
/// derived classes compute each element's value, gradient and that Hessian
/// (without the projection's + eps I) in gaussNewton(). Values, gradients
/// alone, the exact Hessian (projectionEps < 0) and elements for which
/// useGaussNewton() is false are ElementTerm's.
template<int NV, typename Energy>
class GaussNewtonTerm : public ElementTerm<NV, Energy>
{
public:
  using ElementTerm<NV, Energy>::ElementTerm;
  static constexpr int N = 2 * NV;

  using ObjectiveTerm::evaluateDerivatives;
  void evaluateDerivatives(const SpherePoints& points,
    double projectionEps,
    int first,
    int last,
    double* values,
    double* gradients,
    double* hessians) const override
  {
    if (!hessians || projectionEps < 0.0 || !this->useGaussNewton())
    {
      ElementTerm<NV, Energy>::evaluateDerivatives(
        points, projectionEps, first, last, values, gradients, hessians);
      return;
    }
    for (int e = first; e < last; ++e)
    {
      Eigen::Map<Eigen::Matrix<double, N, 1>> gradient(gradients + static_cast<std::size_t>(e) * N);
      Eigen::Map<Eigen::Matrix<double, N, N>> H(hessians + static_cast<std::size_t>(e) * N * N);
      values[e] = this->gaussNewton(points, e, gradient, H);
      H.diagonal().array() += projectionEps;
    }
  }

protected:
  virtual bool useGaussNewton() const { return true; }
  /// Element e's value; its gradient and Gauss-Newton Hessian into the maps.
  virtual double gaussNewton(const SpherePoints& points,
    int e,
    Eigen::Map<Eigen::Matrix<double, N, 1>>& gradient,
    Eigen::Map<Eigen::Matrix<double, N, N>>& H) const = 0;
};

/// Value, gradient and projected Hessian of a weighted sum of terms.
class Objective
{
public:
  /// Adds a term with a weight (>= 0) to a group (the caller's label, e.g.
  /// which energy term it belongs to). Invalidates the sparsity structure.
  void addTerm(std::shared_ptr<ObjectiveTerm> term, double weight = 1.0, int group = 0);
  int group(std::size_t term) const { return this->Terms[term].Group; }
  void setWeight(std::size_t term, double weight) { this->Terms[term].Weight = weight; }
  std::size_t numberOfTerms() const { return this->Terms.size(); }
  ObjectiveTerm& term(std::size_t i) { return *this->Terms[i].Term; }
  void clear();

  /// Call after the elements' points changed (mesh edits) or points were
  /// locked or unlocked: the Hessian pattern is rebuilt on next use.
  void structureChanged() { this->PatternValid = false; }

  /// Total energy (+inf if any element is invalid). Deterministic.
  double value(const SpherePoints& points) const;
  /// Energy per term, unweighted, in the order added.
  std::vector<double> termValues(const SpherePoints& points) const;

  /// Energy and gradient over points.numberOfVariables() variables.
  double gradient(const SpherePoints& points, Eigen::VectorXd& gradient);
  /// Energy, gradient and projected Hessian (upper triangle, column-major
  /// compressed; projectionEps < 0: not projected). `patternChanged` tells whether the sparsity
  /// pattern differs from the previous call (so a solver must re-analyse it); clear() and
  /// structureChanged() keep the previous pattern for that comparison. `newPattern`, if given,
  /// is called with a changed pattern (zero values) before the Hessian is complete, on one thread
  /// while the others evaluate element derivatives: a solver's symbolic analysis fits there
  /// (parallel regions it opens run on that one thread).
  double hessian(const SpherePoints& points,
    double projectionEps,
    Eigen::VectorXd& gradient,
    Eigen::SparseMatrix<double>& hessian,
    bool* patternChanged = nullptr,
    const std::function<void(const Eigen::SparseMatrix<double>&)>& newPattern = {});

private:
  struct Entry
  {
    std::shared_ptr<ObjectiveTerm> Term;
    double Weight = 1.0;
    int Group = 0;
    // Per-element evaluation buffers, reused between calls.
    std::vector<double> Values, Gradients, Hessians;
    // For each element, n*n indices into the Hessian's value array (-1: lower
    // triangle or locked variable).
    std::vector<int> Scatter;
  };
  /// The upper-triangle 2x2 blocks of the Hessian (diagonal included), by
  /// block column: column c's block rows, ascending (the diagonal last), are
  /// rows[start[c] .. start[c + 1]).
  struct BlockColumns
  {
    std::vector<int> start;
    std::vector<int> rows;
  };
  BlockColumns blockColumns(const SpherePoints& points) const;
  /// Lays out Pattern from the blocks (remembering whether it changed).
  void layOutPattern(int nvars, const BlockColumns& blocks);
  /// Each element's Hessian entries' positions in Pattern's value array.
  void buildScatter(const SpherePoints& points, const BlockColumns& blocks);
  double assembleGradient(const SpherePoints& points, Eigen::VectorXd& gradient);
  /// Every term's element derivatives on all threads; `alongside`, if given,
  /// runs first on one of them.
  void evaluateDerivatives(const SpherePoints& points,
    double projectionEps,
    bool withHessian,
    const std::function<void()>& alongside = {});

  std::vector<Entry> Terms;
  bool PatternValid = false;
  // The last rebuild produced the same pattern as before it.
  bool PatternUnchanged = false;
  int PatternVariables = -1;
  Eigen::SparseMatrix<double> Pattern;
};

} // namespace surfacemaps
