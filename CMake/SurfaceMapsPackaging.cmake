# Debian packages of the main build: `cpack -G DEB` in the build directory
# (or .ci/package.sh, which also checks them) writes into <build>/packages:
#
#   surfacemaps          the module library and the `surfacemap` program
#   python3-surfacemaps  the Python package `surfacemaps` (for Debian's python3-vtk9)
#   surfacemaps-dev      headers and the CMake package (find_package(SurfaceMaps))
#
# They install into /usr on Debian 12 with `apt install ./<build>/packages/*.deb`
# and depend only on Debian's packages: the shared libraries' packages as
# dpkg-shlibdeps finds them (the module library links VTK 9.1, CHOLMOD,
# OpenMesh, libgomp; the Python module libpython3.11), the Python modules
# the package imports, and each other at the exact version. The ParaView
# plugin is not packaged: it is built against ParaView's own VTK in another
# build directory (.ci/build-paraview.sh).
#
# The install rules put every file in one of the three components below;
# .ci/package.sh fails when a file lands in none of them.

set(CPACK_GENERATOR "DEB")
set(CPACK_PACKAGE_NAME "surfacemaps")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_VENDOR "SurfaceMaps")
set(CPACK_PACKAGE_CONTACT "SurfaceMaps developers")
# No CPACK_PACKAGE_DESCRIPTION_SUMMARY: CPack would put it above every
# component's description; each component's first line is its summary.
set(CPACK_PACKAGE_DIRECTORY "${CMAKE_BINARY_DIR}/packages")
set(CPACK_PACKAGING_INSTALL_PREFIX "/usr")
# Release builds carry no debug information worth shipping; stripping
# halves the library.
set(CPACK_STRIP_FILES ON)

set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL runtime python development)
set(CPACK_DEBIAN_FILE_NAME "DEB-DEFAULT")
set(CPACK_DEBIAN_PACKAGE_SECTION "science")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# The Python module links the module library, which is in the surfacemaps
# package rather than installed: dpkg-shlibdeps finds it in the build tree
# (and, with no package owning it there, adds nothing for it; the component
# dependency below does).
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}")
# Component dependencies become Depends on the sibling package at the same version.
set(CPACK_DEBIAN_ENABLE_COMPONENT_DEPENDS ON)

set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME "surfacemaps")
set(CPACK_COMPONENT_RUNTIME_DESCRIPTION
  "Bijective maps between genus-0 surfaces via adaptive common triangulations
Computes continuous, bijective maps between closed genus-0 triangle meshes
through an adaptive common triangulation, with landmarks, transfer of
fields, labels and textures, and population averages and modes. This
package holds the VTK module library and the surfacemap program.")
# A shlibs file and the ldconfig trigger for the library in /usr/lib.
set(CPACK_DEBIAN_RUNTIME_PACKAGE_GENERATE_SHLIBS ON)
# `surfacemap --pictures` on a machine without a display starts Xvfb itself.
set(CPACK_DEBIAN_RUNTIME_PACKAGE_RECOMMENDS "xvfb")

set(CPACK_DEBIAN_PYTHON_PACKAGE_NAME "python3-surfacemaps")
set(CPACK_DEBIAN_PYTHON_PACKAGE_SECTION "python")
set(CPACK_COMPONENT_PYTHON_DEPENDS runtime)
set(CPACK_COMPONENT_PYTHON_DESCRIPTION
  "Python package of SurfaceMaps (import surfacemaps)
The module's VTK classes for Debian's python3-vtk9, and helpers that read
meshes with landmarks, map, evaluate, transfer data and compute population
statistics.")
# What the package imports besides the libraries dpkg-shlibdeps sees:
# vtkmodules and numpy always; matplotlib for the population pictures,
# mpi4py for population runs over MPI.
# The extension module is built for Debian 12's Python 3.11 (its ABI tag).
set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS "python3 (>= 3.11), python3 (<< 3.12), python3-vtk9, python3-numpy")
set(CPACK_DEBIAN_PYTHON_PACKAGE_RECOMMENDS "python3-matplotlib")
set(CPACK_DEBIAN_PYTHON_PACKAGE_SUGGESTS "python3-mpi4py")

set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_NAME "surfacemaps-dev")
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_SECTION "libdevel")
set(CPACK_COMPONENT_DEVELOPMENT_DEPENDS runtime)
set(CPACK_COMPONENT_DEVELOPMENT_DESCRIPTION
  "Development files of SurfaceMaps
Headers of the VTK module and its CMake package: find_package(SurfaceMaps)
and target_link_libraries(... SurfaceMaps::FiltersSurfaceMaps).")
# The CMake package finds VTK's (SurfaceMapsConfig.cmake).
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_DEPENDS "libvtk9-dev")

include(CPack)
