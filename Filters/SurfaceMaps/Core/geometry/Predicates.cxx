// The only file that includes CGAL: exact predicates with a filtered kernel
// (floating point where the sign is certain, exact arithmetic otherwise).
#include "geometry/Predicates.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>

namespace surfacemaps
{

int orient3dOrigin(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  // Semi-static filter first (Shewchuk's orient3d error bound A, which is
  // (7 + 56 eps) eps < 1e-15 times the permanent; with the fourth point at the
  // origin the coordinate differences are exact): most calls end here, far
  // cheaper than the kernel's interval arithmetic.
  const double bc = b.x() * c.y() - c.x() * b.y();
  const double ca = c.x() * a.y() - a.x() * c.y();
  const double ab = a.x() * b.y() - b.x() * a.y();
  const double det = a.z() * bc + b.z() * ca + c.z() * ab;
  const double permanent =
    (std::abs(b.x() * c.y()) + std::abs(c.x() * b.y())) * std::abs(a.z()) +
    (std::abs(c.x() * a.y()) + std::abs(a.x() * c.y())) * std::abs(b.z()) +
    (std::abs(a.x() * b.y()) + std::abs(b.x() * a.y())) * std::abs(c.z());
  const double bound = 1e-15 * permanent;
  if (det > bound)
  {
    return 1;
  }
  if (det < -bound)
  {
    return -1;
  }
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Point = Kernel::Point_3;
  const CGAL::Orientation o = CGAL::orientation(Point(0.0, 0.0, 0.0),
    Point(a.x(), a.y(), a.z()),
    Point(b.x(), b.y(), b.z()),
    Point(c.x(), c.y(), c.z()));
  return o == CGAL::POSITIVE ? 1 : (o == CGAL::NEGATIVE ? -1 : 0);
}

bool rayMeetsTriangle(const Eigen::Vector3d& a,
  const Eigen::Vector3d& b,
  const Eigen::Vector3d& c,
  const Eigen::Vector3d& q)
{
  return orient3dOrigin(a, b, q) >= 0 && orient3dOrigin(b, c, q) >= 0 &&
    orient3dOrigin(c, a, q) >= 0;
}

} // namespace surfacemaps
