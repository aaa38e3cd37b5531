# Installs the build into PREFIX, then configures, builds and runs the consumer
# project (Testing/Consumer: find_package(SurfaceMaps) and one program) against
# that prefix alone, and checks that the program mapped the bundled meshes.
# With -DBUILD_TREE=ON nothing is installed: the consumer finds the package
# in the build tree (SurfaceMaps_DIR=BUILD_DIR/CMAKE_DESTINATION).
if (BUILD_TREE)
  set(package_dir "${BUILD_DIR}/${CMAKE_DESTINATION}")
  set(find_package_hint "-DSurfaceMaps_DIR=${package_dir}")
  file(REMOVE_RECURSE "${CONSUMER_BUILD}")
else ()
  set(package_dir "${PREFIX}/${CMAKE_DESTINATION}")
  set(find_package_hint "-DCMAKE_PREFIX_PATH=${PREFIX}")
  file(REMOVE_RECURSE "${PREFIX}" "${CONSUMER_BUILD}")
  execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}"
    RESULT_VARIABLE rc OUTPUT_QUIET)
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "cmake --install failed: ${rc}")
  endif ()
endif ()
foreach (file IN ITEMS SurfaceMapsConfig.cmake SurfaceMapsConfigVersion.cmake SurfaceMaps-targets.cmake)
  if (NOT EXISTS "${package_dir}/${file}")
    message(FATAL_ERROR "missing: ${package_dir}/${file}")
  endif ()
endforeach ()

execute_process(
  COMMAND "${CMAKE_COMMAND}" -S "${CONSUMER_SOURCE}" -B "${CONSUMER_BUILD}" -G "${GENERATOR}"
    -DCMAKE_BUILD_TYPE=Release
    "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}"
    "${find_package_hint}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring the consumer project failed (${rc}):\n${out}${err}")
endif ()
# The package must come from where this test put it (the install tree or
# the build tree), not from elsewhere.
file(STRINGS "${CONSUMER_BUILD}/CMakeCache.txt" found REGEX "^SurfaceMaps_DIR:")
string(REGEX REPLACE "^[^=]*=" "" found "${found}")
if (NOT found STREQUAL package_dir)
  message(FATAL_ERROR "SurfaceMaps found in '${found}', not in ${package_dir}")
endif ()

execute_process(COMMAND "${CMAKE_COMMAND}" --build "${CONSUMER_BUILD}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "building the consumer project failed (${rc}):\n${out}${err}")
endif ()

execute_process(COMMAND "${CONSUMER_BUILD}/surfacemaps_consumer" "${DATA}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0 OR NOT out MATCHES "certified map, common triangulation of [1-9][0-9]* vertices")
  message(FATAL_ERROR "the consumer program failed (${rc}):\n${out}${err}")
endif ()
message(STATUS "${out}")
