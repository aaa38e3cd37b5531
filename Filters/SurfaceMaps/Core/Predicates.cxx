// The only file that includes CGAL: exact predicates with a filtered kernel
// (floating point where the sign is certain, exact arithmetic otherwise).
#include "Predicates.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace surfacemaps
{

int orient3dOrigin(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
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
