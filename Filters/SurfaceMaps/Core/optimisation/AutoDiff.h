// SurfaceMaps engine: forward-mode automatic differentiation with exact
// second derivatives for small, fixed numbers of variables.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <limits>
#include <type_traits>

namespace surfacemaps
{

/// A scalar carrying its value, its gradient and (when WithHessian) its
/// Hessian with respect to N variables. Energies are written once as
/// templates over the scalar type: instantiated with double they cost a plain
/// evaluation (line searches), with Dual<N> they give exact first and second
/// derivatives (Newton steps). Works inside Eigen fixed-size matrices.
template<int N, bool WithHessian = true>
struct Dual
{
  /// Number of variables and whether second derivatives are carried.
  static constexpr int Variables = N;
  static constexpr bool HasHessian = WithHessian;
  using Gradient = Eigen::Matrix<double, N, 1>;
  using Hessian = Eigen::Matrix<double, N, N>;
  struct NoHessian
  {
  };
  using HessianStorage = std::conditional_t<WithHessian, Hessian, NoHessian>;

  double val = 0.0;
  Gradient grad = Gradient::Zero();
  HessianStorage Hess = zeroHessian();

  Dual() = default;
  Dual(double value) // NOLINT: implicit, so constants mix with variables
    : val(value)
  {
  }
  Dual(int value) // NOLINT
    : val(value)
  {
  }

  /// Tag for a result whose gradient and Hessian are about to be assigned in
  /// full: skips zeroing N + N^2 entries that would be overwritten anyway.
  struct Uninitialised
  {
  };
  explicit Dual(Uninitialised)
    : grad()
    , Hess()
  {
  }

  /// The i-th variable, at `value`.
  static Dual variable(double value, int i)
  {
    Dual d(value);
    d.grad[i] = 1.0;
    return d;
  }

  static HessianStorage zeroHessian()
  {
    if constexpr (WithHessian)
    {
      return Hessian::Zero();
    }
    else
    {
      return NoHessian{};
    }
  }

  /// f(this) given f' and f'' at val: the chain rule.
  Dual chain(double f, double df, double ddf) const
  {
    Dual r{ Uninitialised{} };
    r.val = f;
    r.grad = df * this->grad;
    if constexpr (WithHessian)
    {
      // df H + (ddf g) g^T, one column at a time in a single pass.
      const Gradient w = ddf * this->grad;
      for (int j = 0; j < N; ++j)
      {
        r.Hess.col(j) = df * this->Hess.col(j) + w * this->grad[j];
      }
    }
    return r;
  }

  Dual& operator+=(const Dual& b)
  {
    this->val += b.val;
    this->grad += b.grad;
    if constexpr (WithHessian)
    {
      this->Hess += b.Hess;
    }
    return *this;
  }
  Dual& operator-=(const Dual& b)
  {
    this->val -= b.val;
    this->grad -= b.grad;
    if constexpr (WithHessian)
    {
      this->Hess -= b.Hess;
    }
    return *this;
  }
  Dual& operator*=(const Dual& b) { return *this = *this * b; }
  Dual& operator/=(const Dual& b) { return *this = *this / b; }
  Dual& operator+=(double b)
  {
    this->val += b;
    return *this;
  }
  Dual& operator-=(double b)
  {
    this->val -= b;
    return *this;
  }
  Dual& operator*=(double b)
  {
    this->val *= b;
    this->grad *= b;
    if constexpr (WithHessian)
    {
      this->Hess *= b;
    }
    return *this;
  }
  Dual& operator/=(double b) { return *this *= (1.0 / b); }

  Dual operator-() const
  {
    // Negation is exact, so this equals multiplying by -1 bit for bit.
    Dual r{ Uninitialised{} };
    r.val = -this->val;
    r.grad = -this->grad;
    if constexpr (WithHessian)
    {
      r.Hess = -this->Hess;
    }
    return r;
  }
  Dual operator+() const { return *this; }

  friend Dual operator+(Dual a, const Dual& b) { return a += b; }
  friend Dual operator-(Dual a, const Dual& b) { return a -= b; }
  friend Dual operator+(Dual a, double b) { return a += b; }
  friend Dual operator+(double a, Dual b) { return b += a; }
  friend Dual operator-(Dual a, double b) { return a -= b; }
  friend Dual operator-(double a, const Dual& b)
  {
    Dual r = -b;
    return r += a;
  }
  friend Dual operator*(Dual a, double b) { return a *= b; }
  friend Dual operator*(double a, Dual b) { return b *= a; }
  friend Dual operator/(Dual a, double b) { return a *= (1.0 / b); }
  friend Dual operator/(double a, const Dual& b) { return a * b.inverse(); }

  friend Dual operator*(const Dual& a, const Dual& b)
  {
    Dual r{ Uninitialised{} };
    r.val = a.val * b.val;
    r.grad = a.val * b.grad + b.val * a.grad;
    if constexpr (WithHessian)
    {
      // a b'' + b a'' + a' b'^T + b' a'^T in a single pass.
      for (int j = 0; j < N; ++j)
      {
        r.Hess.col(j) =
          a.val * b.Hess.col(j) + b.val * a.Hess.col(j) + a.grad * b.grad[j] + b.grad * a.grad[j];
      }
    }
    return r;
  }
  friend Dual operator/(const Dual& a, const Dual& b)
  {
    // q = a / b: dq = (da - q db) / b, d2q = (d2a - q d2b - dq db' - db dq') / b.
    const double inv = 1.0 / b.val;
    Dual r{ Uninitialised{} };
    r.val = a.val * inv;
    r.grad.noalias() = inv * (a.grad - r.val * b.grad);
    if constexpr (WithHessian)
    {
      for (int j = 0; j < N; ++j)
      {
        r.Hess.col(j) = inv * (a.Hess.col(j) - r.val * b.Hess.col(j)) -
          inv * (r.grad * b.grad[j] + b.grad * r.grad[j]);
      }
    }
    return r;
  }

  Dual inverse() const
  {
    const double inv = 1.0 / this->val;
    return this->chain(inv, -inv * inv, 2.0 * inv * inv * inv);
  }

  friend bool operator<(const Dual& a, const Dual& b) { return a.val < b.val; }
  friend bool operator<=(const Dual& a, const Dual& b) { return a.val <= b.val; }
  friend bool operator>(const Dual& a, const Dual& b) { return a.val > b.val; }
  friend bool operator>=(const Dual& a, const Dual& b) { return a.val >= b.val; }
  friend bool operator==(const Dual& a, const Dual& b) { return a.val == b.val; }
  friend bool operator!=(const Dual& a, const Dual& b) { return a.val != b.val; }
  friend bool operator<(const Dual& a, double b) { return a.val < b; }
  friend bool operator<=(const Dual& a, double b) { return a.val <= b; }
  friend bool operator>(const Dual& a, double b) { return a.val > b; }
  friend bool operator>=(const Dual& a, double b) { return a.val >= b; }
  friend bool operator<(double a, const Dual& b) { return a < b.val; }
  friend bool operator<=(double a, const Dual& b) { return a <= b.val; }
  friend bool operator>(double a, const Dual& b) { return a > b.val; }
  friend bool operator>=(double a, const Dual& b) { return a >= b.val; }

  friend Dual sqrt(const Dual& a)
  {
    const double s = std::sqrt(a.val);
    return a.chain(s, 0.5 / s, -0.25 / (s * a.val));
  }
  friend Dual log(const Dual& a)
  {
    const double inv = 1.0 / a.val;
    // log of a non-positive number is NaN (or -inf): the element is invalid.
    return a.chain(std::log(a.val), inv, -inv * inv);
  }
  friend Dual exp(const Dual& a)
  {
    const double e = std::exp(a.val);
    return a.chain(e, e, e);
  }
  friend Dual pow(const Dual& a, double e)
  {
    const double p = std::pow(a.val, e);
    return a.chain(p, e * std::pow(a.val, e - 1.0), e * (e - 1.0) * std::pow(a.val, e - 2.0));
  }
  friend Dual pow(const Dual& a, const Dual& e) { return exp(e * log(a)); }
  friend Dual abs(const Dual& a) { return a.val < 0.0 ? -a : a; }
  friend Dual acos(const Dual& a)
  {
    const double s = 1.0 - a.val * a.val;
    const double d = -1.0 / std::sqrt(s);
    return a.chain(std::acos(a.val), d, -a.val / (s * std::sqrt(s)));
  }
  friend Dual atan2(const Dual& y, const Dual& x)
  {
    // Partial derivatives of atan2(y, x), then the two-argument chain rule.
    const double r2 = x.val * x.val + y.val * y.val;
    const double fy = x.val / r2, fx = -y.val / r2;
    const double r4 = r2 * r2;
    const double fyy = -2.0 * x.val * y.val / r4, fxx = 2.0 * x.val * y.val / r4;
    const double fxy = (y.val * y.val - x.val * x.val) / r4;
    Dual r{ Uninitialised{} };
    r.val = std::atan2(y.val, x.val);
    r.grad.noalias() = fy * y.grad + fx * x.grad;
    if constexpr (WithHessian)
    {
      r.Hess.noalias() = fy * y.Hess + fx * x.Hess + (fyy * y.grad) * y.grad.transpose() +
        (fxx * x.grad) * x.grad.transpose() + (fxy * x.grad) * y.grad.transpose() +
        (fxy * y.grad) * x.grad.transpose();
    }
    return r;
  }
  friend Dual min(const Dual& a, const Dual& b) { return a.val <= b.val ? a : b; }
  friend Dual max(const Dual& a, const Dual& b) { return a.val >= b.val ? a : b; }
  friend bool isfinite(const Dual& a) { return std::isfinite(a.val); }
  friend bool isnan(const Dual& a) { return std::isnan(a.val); }
};

/// Derivatives of g(x) = f(u(x)) from f's derivatives with respect to M
/// intermediate quantities u (f evaluated with u as its variables) and the
/// derivatives of each u_k with respect to the N variables x. Lets an element
/// compute a few intermediate quantities with few variables each and combine
/// them cheaply, instead of carrying all N derivatives through every operation.
template<std::size_t M, int N, bool H>
Dual<N, H> compose(const Dual<static_cast<int>(M), H>& f, const std::array<Dual<N, H>, M>& u)
{
  Dual<N, H> r;
  r.val = f.val;
  for (std::size_t k = 0; k < M; ++k)
  {
    r.grad.noalias() += f.grad[k] * u[k].grad;
  }
  if constexpr (H)
  {
    for (std::size_t k = 0; k < M; ++k)
    {
      r.Hess.noalias() += f.grad[k] * u[k].Hess;
      Eigen::Matrix<double, N, 1> w = Eigen::Matrix<double, N, 1>::Zero();
      for (std::size_t l = 0; l < M; ++l)
      {
        w.noalias() += f.Hess(k, l) * u[l].grad;
      }
      r.Hess.noalias() += u[k].grad * w.transpose();
    }
  }
  return r;
}

/// embed() written into r, whose derivatives must be zero (as a
/// default-constructed one's are): no temporary of N + N^2 doubles.
template<int N, int K, bool H>
void embedInto(const Dual<K, H>& d, int offset, Dual<N, H>& r)
{
  static_assert(K <= N, "embed into at least as many variables");
  r.val = d.val;
  r.grad.template segment<K>(offset) = d.grad;
  if constexpr (H)
  {
    r.Hess.template block<K, K>(offset, offset) = d.Hess;
  }
}

/// A scalar that depends on K variables, seen as depending on N >= K
/// variables of which its own are offset .. offset + K - 1.
template<int N, int K, bool H>
Dual<N, H> embed(const Dual<K, H>& d, int offset)
{
  Dual<N, H> r;
  embedInto(d, offset, r);
  return r;
}

/// The variables offset .. offset + K - 1 of d as a K-variable scalar; exact
/// when d depends on no other variables.
template<int K, int N, bool H>
Dual<K, H> restrict(const Dual<N, H>& d, int offset)
{
  static_assert(K <= N, "restrict to at most as many variables");
  Dual<K, H> r{ typename Dual<K, H>::Uninitialised{} };
  r.val = d.val;
  r.grad = d.grad.template segment<K>(offset);
  if constexpr (H)
  {
    r.Hess = d.Hess.template block<K, K>(offset, offset);
  }
  return r;
}

/// True for Dual scalars, false for double.
template<typename T>
struct IsDual : std::false_type
{
};
template<int N, bool H>
struct IsDual<Dual<N, H>> : std::true_type
{
};

/// Number of variables a scalar type carries derivatives for (0 for double).
template<typename T>
inline constexpr int variablesOf = 0;
template<int N, bool H>
inline constexpr int variablesOf<Dual<N, H>> = N;

/// The value of a scalar that may or may not carry derivatives.
inline double valueOf(double x)
{
  return x;
}
template<int N, bool H>
double valueOf(const Dual<N, H>& x)
{
  return x.val;
}

// Plain doubles spelled the same way, so templated energies can call
// sqrt/log/... unqualified for both scalar types.
using std::abs;
using std::acos;
using std::atan2;
using std::exp;
using std::isfinite;
using std::log;
using std::max;
using std::min;
using std::pow;
using std::sqrt;

} // namespace surfacemaps

namespace Eigen
{

template<int N, bool H>
struct NumTraits<surfacemaps::Dual<N, H>> : NumTraits<double>
{
  using Real = surfacemaps::Dual<N, H>;
  using NonInteger = surfacemaps::Dual<N, H>;
  using Nested = surfacemaps::Dual<N, H>;
  using Literal = double;
  enum
  {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 1 + N + (H ? N * N : 0),
    AddCost = ReadCost,
    MulCost = 3 * ReadCost,
  };
};

template<int N, bool H>
struct ScalarBinaryOpTraits<surfacemaps::Dual<N, H>, double>
{
  using ReturnType = surfacemaps::Dual<N, H>;
};
template<int N, bool H>
struct ScalarBinaryOpTraits<double, surfacemaps::Dual<N, H>>
{
  using ReturnType = surfacemaps::Dual<N, H>;
};

} // namespace Eigen
