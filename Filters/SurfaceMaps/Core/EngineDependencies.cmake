# The engine's external packages, whose imported targets SurfaceMapsCore's
# interface names: included by Core/CMakeLists.txt and by a build that imports
# another build tree's engine (the ParaView plugin's, see
# ParaView/CMakeLists.txt).
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(OpenMesh REQUIRED)
find_package(OpenMP REQUIRED COMPONENTS CXX)
find_package(CGAL REQUIRED)
# Header-only: container::small_vector (map/CommonTriangulation.h).
find_package(Boost REQUIRED)
