# Installs the build into PREFIX, then imports the installed Python package and
# runs the installed program, with nothing from the build tree on any path.
file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}"
  RESULT_VARIABLE rc OUTPUT_QUIET)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed: ${rc}")
endif ()

execute_process(
  COMMAND "${CMAKE_COMMAND}" -E env "PYTHONPATH=${PREFIX}/${PYTHON_DESTINATION}"
    "${PYTHON}" -c "import surfacemaps, sys; m = surfacemaps.read_mesh(sys.argv[1]); print(surfacemaps.__file__); assert m.GetNumberOfPoints() == 642"
    "${DATA}/ellipsoid.obj"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "import from the install tree failed: ${out}${err}")
endif ()
string(FIND "${out}" "${PREFIX}" at)
if (at EQUAL -1)
  message(FATAL_ERROR "surfacemaps was not imported from the install tree: ${out}")
endif ()

execute_process(COMMAND "${PREFIX}/bin/surfacemap" check "${DATA}/ellipsoid.obj"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0 OR NOT out MATCHES "valid")
  message(FATAL_ERROR "installed surfacemap check failed (${rc}): ${out}${err}")
endif ()
message(STATUS "install tree OK: ${PREFIX}")
