#include "geometry/Predicates.h"
#include "mesh/Primitives.h"
#include "geometry/SphericalTriangulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace surfacemaps;

namespace
{
} // namespace

TEST(Predicates, ExactSignsOnDegenerateInput)
{
  const Eigen::Vector3d a(1, 2, 3), b(4, 5, 6);
  Eigen::Vector3d c = a + b; // exactly coplanar with the origin
  EXPECT_EQ(orient3dOrigin(a, b, c), 0);
  c.z() = std::nextafter(c.z(), 100.0); // det = (a x b).z * ulp = -3 ulp < 0
  EXPECT_EQ(orient3dOrigin(a, b, c), -1);
  c.z() = std::nextafter(9.0, 0.0);
  EXPECT_EQ(orient3dOrigin(a, b, c), 1);

  // Nearly parallel long vectors where the naive determinant cancels badly:
  // det[a, a + e1 * eps, a + e2 * eps] = eps^2 * a.(e1 x e2) > 0.
  const Eigen::Vector3d p(0.5773502691896258, 0.5773502691896258, 0.5773502691896257);
  const double eps = std::ldexp(1.0, -40);
  const Eigen::Vector3d q = p + Eigen::Vector3d(eps, 0, 0);
  const Eigen::Vector3d r = p + Eigen::Vector3d(0, eps, 0);
  EXPECT_EQ(orient3dOrigin(p, q, r), 1);
  EXPECT_EQ(orient3dOrigin(p, r, q), -1);
}

TEST(Predicates, AgreesWithTheDeterminantWhenClearlyNonZero)
{
  std::mt19937 rng(1);
  std::normal_distribution<double> n;
  for (int i = 0; i < 1000; ++i)
  {
    const Eigen::Vector3d a(n(rng), n(rng), n(rng)), b(n(rng), n(rng), n(rng)),
      c(n(rng), n(rng), n(rng));
    const double det = a.dot(b.cross(c));
    if (std::abs(det) > 1e-6)
    {
      EXPECT_EQ(orient3dOrigin(a, b, c), det > 0 ? 1 : -1);
    }
  }
}

TEST(SphericalTriangulation, AreasAndDegree)
{
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(),
                        z = Eigen::Vector3d::UnitZ();
  EXPECT_NEAR(signedSphericalArea(x, y, z), M_PI / 2, 1e-15); // an octant
  EXPECT_NEAR(signedSphericalArea(x, z, y), -M_PI / 2, 1e-15);
  const PolygonMesh ico = makeIcosphere(3);
  EXPECT_NEAR(sphericalDegree(ico.points, ico.triangles()), 1.0, 1e-12);
}

TEST(SphericalTriangulation, CertifiesBijectiveEmbeddings)
{
  const PolygonMesh ico = makeIcosphere(2);
  const BijectivityCertificate ok = certifyBijective(ico.points, ico.triangles());
  EXPECT_TRUE(ok.bijective) << ok.reason;
  EXPECT_EQ(ok.nonPositiveTriangles, 0);
}

TEST(SphericalTriangulation, RejectsFoldsAndMultipleCovers)
{
  const PolygonMesh ico = makeIcosphere(2);
  std::vector<Eigen::Vector3d> folded = ico.points;
  folded[0] = -folded[0];
  const BijectivityCertificate fold = certifyBijective(folded, ico.triangles());
  EXPECT_FALSE(fold.bijective);
  EXPECT_GT(fold.nonPositiveTriangles, 0);
  EXPECT_NE(fold.reason.find("not positively oriented"), std::string::npos);

  // Every triangle listed twice: all positive, but the sphere is covered twice.
  std::vector<std::array<int, 3>> twice = ico.triangles();
  const auto once = twice;
  twice.insert(twice.end(), once.begin(), once.end());
  const BijectivityCertificate cover = certifyBijective(ico.points, twice);
  EXPECT_FALSE(cover.bijective);
  EXPECT_EQ(cover.nonPositiveTriangles, 0);
  EXPECT_NEAR(cover.degree, 2.0, 1e-12);
  EXPECT_NE(cover.reason.find("covers the sphere"), std::string::npos);

  // A triangle exactly degenerate (two equal points) is not positive.
  std::vector<Eigen::Vector3d> collapsed = ico.points;
  const auto t0 = ico.triangles()[0];
  collapsed[t0[1]] = collapsed[t0[0]];
  EXPECT_FALSE(certifyBijective(collapsed, ico.triangles()).bijective);
}
