#include "optimisation/AutoDiff.h"

#include "FiniteDifferences.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <gtest/gtest.h>

#include <cmath>

using namespace surfacemaps;
using namespace surfacemaps::testing;

namespace
{
constexpr int N = 3;
using D = Dual<N>;

// Checks value, gradient and Hessian of f at x against plain evaluation and
// central finite differences; f is a generic lambda over the scalar type.
template<typename F>
void check(const char* what, F f, const Eigen::Vector3d& x, double tolerance = 2e-6)
{
  std::array<D, N> vars;
  for (int i = 0; i < N; ++i)
  {
    vars[i] = D::variable(x[i], i);
  }
  const D r = f(vars);
  const std::array<double, N> plain{ x[0], x[1], x[2] };
  const double value = f(plain);
  EXPECT_DOUBLE_EQ(r.val, value) << what;

  auto scalar = [&](const Eigen::VectorXd& y) {
    return f(std::array<double, N>{ y[0], y[1], y[2] });
  };
  const Eigen::VectorXd g = finiteDifferenceGradient(scalar, x);
  const Eigen::MatrixXd H = finiteDifferenceHessian(scalar, x);
  EXPECT_LT(relativeError(r.grad, g), tolerance) << what << "\n"
                                                 << r.grad.transpose() << "\n"
                                                 << g.transpose();
  EXPECT_LT(relativeError(r.Hess, H), 100 * tolerance) << what << "\n" << r.Hess << "\n\n" << H;
  EXPECT_LT((r.Hess - r.Hess.transpose()).cwiseAbs().maxCoeff(), 1e-12) << what;

  // The gradient-only scalar agrees with the full one.
  std::array<Dual<N, false>, N> gvars;
  for (int i = 0; i < N; ++i)
  {
    gvars[i] = Dual<N, false>::variable(x[i], i);
  }
  const Dual<N, false> rg = f(gvars);
  EXPECT_DOUBLE_EQ(rg.val, r.val) << what;
  EXPECT_LT((rg.grad - r.grad).cwiseAbs().maxCoeff(), 1e-14) << what;
}
const Eigen::Vector3d X(0.7, -0.4, 1.3);
} // namespace

TEST(AutoDiff, Arithmetic)
{
  check(
    "a+b", [](const auto& v) { return v[0] + v[1] + 2.0 + v[2] * 3.0; }, X);
  check(
    "a-b", [](const auto& v) { return v[0] - v[1] - 2.0 - (1.0 - v[2]); }, X);
  check(
    "a*b", [](const auto& v) { return v[0] * v[1] * v[2] * v[0]; }, X);
  check(
    "a/b", [](const auto& v) { return v[0] / v[1] + 1.0 / v[2] + v[2] / 3.0; }, X);
  check(
    "neg", [](const auto& v) { return -(v[0] * v[2]) + +v[1]; }, X);
  check(
    "compound",
    [](const auto& v)
    {
      auto a = v[0];
      a += v[1];
      a *= v[2];
      a -= 0.5 * v[0];
      a /= v[2] + 3.0;
      return a;
    },
    X);
}

TEST(AutoDiff, Functions)
{
  check(
    "sqrt", [](const auto& v) { return sqrt(v[0] * v[0] + v[1] * v[1] + v[2]); }, X);
  check(
    "log", [](const auto& v) { return log(v[0] * v[2] + 2.0); }, X);
  check(
    "exp", [](const auto& v) { return exp(v[0] * v[1] - v[2]); }, X);
  check(
    "pow double", [](const auto& v) { return pow(v[2] + v[0], 2.5); }, X);
  check(
    "pow scalar", [](const auto& v) { return pow(v[2], v[0] + 1.0); }, X);
  check(
    "atan2", [](const auto& v) { return atan2(v[1] * v[2], v[0] - v[2]); }, X);
  check(
    "acos", [](const auto& v) { return acos(0.3 * v[0] * v[1]); }, X);
  check(
    "abs negative", [](const auto& v) { return abs(v[1] * v[2]); }, X);
  check(
    "abs positive", [](const auto& v) { return abs(v[0] * v[2]); }, X);
  check(
    "min", [](const auto& v) { return min(v[0] * v[0], v[1] * v[2] + 2.0); }, X);
  check(
    "max", [](const auto& v) { return max(v[0] * v[0], v[1] * v[2] + 2.0); }, X);
}

TEST(AutoDiff, Comparisons)
{
  const D a = D::variable(1.0, 0), b = D::variable(2.0, 1);
  EXPECT_TRUE(a < b);
  EXPECT_TRUE(a <= b);
  EXPECT_FALSE(a > b);
  EXPECT_TRUE(b >= a);
  EXPECT_TRUE(a != b);
  EXPECT_TRUE(a == 1.0 * a);
  EXPECT_TRUE(a < 1.5 && 1.5 < b && b > 1.5 && a <= 1.0 && 2.0 >= b && b >= 2.0);
}

TEST(AutoDiff, CompositesInsideEigen)
{
  // Frobenius norm of a 2x2 matrix and of its inverse (symmetric-Dirichlet-like).
  check(
    "2x2 inverse",
    [](const auto& v)
    {
      using T = std::decay_t<decltype(v[0])>;
      Eigen::Matrix<T, 2, 2> J;
      J << v[0] + 2.0, v[1], v[2], v[0] * v[1] + 1.5;
      const Eigen::Matrix<T, 2, 2> Jinv = J.inverse();
      return J.squaredNorm() + Jinv.squaredNorm();
    },
    X);
  check(
    "cross dot",
    [](const auto& v)
    {
      using T = std::decay_t<decltype(v[0])>;
      const Eigen::Matrix<T, 3, 1> a(v[0], v[1], v[2]);
      const Eigen::Matrix<T, 3, 1> b(v[1], T(2.0), v[0] * v[2]);
      return a.cross(b).dot(Eigen::Matrix<T, 3, 1>(v[2], v[0], T(1.0))) + a.dot(b);
    },
    X);
  check(
    "normalisation",
    [](const auto& v)
    {
      using T = std::decay_t<decltype(v[0])>;
      const Eigen::Matrix<T, 3, 1> a(v[0], v[1], v[2]);
      const Eigen::Matrix<T, 3, 1> n = a / a.norm();
      return n[0] * 2.0 + n[1] * n[2];
    },
    X);
  check(
    "determinant",
    [](const auto& v)
    {
      using T = std::decay_t<decltype(v[0])>;
      Eigen::Matrix<T, 3, 3> M;
      M << v[0], v[1], T(1.0), v[2], T(0.5), v[0], v[1] * v[2], T(2.0), v[0];
      return M.determinant();
    },
    X);
}

TEST(AutoDiff, InvalidValuesPropagate)
{
  const D a = D::variable(-1.0, 0);
  EXPECT_FALSE(isfinite(log(a)));
  EXPECT_FALSE(isfinite(sqrt(a)));
  EXPECT_TRUE(isfinite(log(-a)));
}

TEST(AutoDiff, TwentyFourVariables)
{
  using D24 = Dual<24>;
  D24 sum = 0.0;
  for (int i = 0; i < 24; ++i)
  {
    const D24 x = D24::variable(0.1 * (i + 1), i);
    sum += x * x;
  }
  EXPECT_NEAR(sum.val, 0.01 * 24 * 25 * 49 / 6.0, 1e-12);
  EXPECT_DOUBLE_EQ(sum.grad[23], 2 * 2.4);
  EXPECT_TRUE(sum.Hess.isApprox(2.0 * Eigen::Matrix<double, 24, 24>::Identity()));
}

TEST(AutoDiff, ComposeEmbedRestrictMatchDirectDifferentiation)
{
  // g(x) = f(u1(x0, x1), u2(x2, x3)) with f(u1, u2) = u1^2 u2 + sin-free terms.
  constexpr int NX = 4;
  using DX = Dual<NX>;
  using D2 = Dual<2>;
  const double x[NX] = { 0.3, -1.2, 0.8, 0.45 };
  auto u1 = [](const auto& a, const auto& b) { return a * b + a * a; };
  auto u2 = [](const auto& a, const auto& b) { return sqrt(a * a + b * b + 1.0); };
  auto f = [](const auto& p, const auto& q) { return p * p * q + log(q) / p; };

  // Directly in 4 variables.
  std::array<DX, NX> v;
  for (int i = 0; i < NX; ++i)
  {
    v[i] = DX::variable(x[i], i);
  }
  const DX direct = f(u1(v[0], v[1]), u2(v[2], v[3]));

  // In pieces: each u in 2 variables, embedded, then composed.
  const D2 a = restrict<2>(v[0], 0), b = restrict<2>(v[1], 0);
  const D2 c = restrict<2>(v[2], 2), d = restrict<2>(v[3], 2);
  const std::array<DX, 2> u = { embed<NX>(u1(a, b), 0), embed<NX>(u2(c, d), 2) };
  const D2 fu = f(D2::variable(u[0].val, 0), D2::variable(u[1].val, 1));
  const DX composed = compose(fu, u);

  EXPECT_DOUBLE_EQ(composed.val, direct.val);
  EXPECT_LT((composed.grad - direct.grad).cwiseAbs().maxCoeff(), 1e-13);
  EXPECT_LT((composed.Hess - direct.Hess).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(AutoDiff, EmbedIntoEqualsEmbed)
{
  // A 2-variable scalar with non-zero value, gradient and Hessian, placed at
  // variables 3 and 4 of 6: in place, exactly as embed() places it, and no
  // other entry touched.
  using D2 = Dual<2>;
  using D6 = Dual<6>;
  const D2 a = D2::variable(0.7, 0), b = D2::variable(-1.3, 1);
  const D2 s = a * a * b + sqrt(a * a + b * b);
  D6 inPlace;
  embedInto(s, 3, inPlace);
  const D6 copied = embed<6>(s, 3);
  EXPECT_EQ(inPlace.val, copied.val);
  EXPECT_EQ(inPlace.grad, copied.grad);
  EXPECT_EQ(inPlace.Hess, copied.Hess);
  EXPECT_NE(inPlace.Hess(4, 3), 0.0);
  EXPECT_EQ((inPlace.Hess.block<3, 6>(0, 0).cwiseAbs().maxCoeff()), 0.0);
}

TEST(AutoDiff, SinglePassHessiansAreThoseOfTheMatrixExpressions)
{
  // Product, quotient and chain rule fill their Hessian column by column;
  // each entry must be the expression's, to the last bit (the maps of the
  // normal build depend on it).
  using D = Dual<5>;
  std::array<D, 5> v;
  for (int i = 0; i < 5; ++i)
  {
    v[i] = D::variable(0.3 + 0.37 * i, i);
  }
  const D a = v[0] * v[1] + v[2] * v[2] - v[4];
  const D b = v[3] * v[4] + sqrt(v[0] + 2.0);
  const D p = a * b, q = a / b, e = exp(a);
  const Eigen::Matrix<double, 5, 5> productHess =
    a.val * b.Hess + b.val * a.Hess + a.grad * b.grad.transpose() + b.grad * a.grad.transpose();
  const Eigen::Matrix<double, 5, 5> quotientHess = (1.0 / b.val) * (a.Hess - q.val * b.Hess) -
    (1.0 / b.val) * (q.grad * b.grad.transpose() + b.grad * q.grad.transpose());
  const Eigen::Matrix<double, 5, 5> chainHess =
    e.val * a.Hess + (e.val * a.grad) * a.grad.transpose();
#ifdef __FMA__
  // With fused multiply-adds the compiler may contract the two forms
  // differently: equal to rounding.
  const double tolerance = 1e-14;
#else
  const double tolerance = 0.0;
#endif
  EXPECT_LE((p.Hess - productHess).cwiseAbs().maxCoeff(), tolerance * productHess.norm());
  EXPECT_LE((q.Hess - quotientHess).cwiseAbs().maxCoeff(), tolerance * quotientHess.norm());
  EXPECT_LE((e.Hess - chainHess).cwiseAbs().maxCoeff(), tolerance * chainHess.norm());
  EXPECT_NE(p.Hess(2, 4), 0.0); // the cross terms a' b'^T + b' a'^T are exercised
}

TEST(AutoDiff, ArithmeticDoesNotDependOnTheTargetInstructionSet)
{
#if defined(SURFACEMAPS_PORTABLE_ARITHMETIC)
  // SURFACEMAPS_PORTABLE_ARITHMETIC (CMakeLists.txt) must reach the code:
  // with FMA or AVX enabled, a -march=native build computes other maps than
  // a portable one.
#if defined(__FMA__) || defined(__AVX__)
  FAIL() << "SURFACEMAPS_PORTABLE_ARITHMETIC is on but this code is compiled with FMA or AVX";
#endif
  // No contraction either: a * b + c rounds the product first. Here the
  // product is 1 - 2^-60, which rounds to 1, so the sum is 0; fused, it
  // would be -2^-60.
  volatile double a = 1.0 + std::ldexp(1.0, -30), b = 1.0 - std::ldexp(1.0, -30), c = -1.0;
  const double sum = a * b + c;
  EXPECT_EQ(sum, 0.0);
#else
  GTEST_SKIP() << "built with SURFACEMAPS_PORTABLE_ARITHMETIC=OFF or not for x86-64";
#endif
}
