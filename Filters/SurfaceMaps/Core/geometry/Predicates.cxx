// The only file that includes CGAL: the exact arithmetic behind the
// floating-point filter of Predicates.h.
#include "geometry/Predicates.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>

namespace surfacemaps
{

int orient3dOriginExact(const Eigen::Vector3d& a,
  const Eigen::Vector3d& b,
  const Eigen::Vector3d& c)
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Point = Kernel::Point_3;
  const CGAL::Orientation o = CGAL::orientation(Point(0.0, 0.0, 0.0),
    Point(a.x(), a.y(), a.z()),
    Point(b.x(), b.y(), b.z()),
    Point(c.x(), c.y(), c.z()));
  return o == CGAL::POSITIVE ? 1 : (o == CGAL::NEGATIVE ? -1 : 0);
}

} // namespace surfacemaps
