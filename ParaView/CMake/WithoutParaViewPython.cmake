# Debian's paraview-dev exports the targets of ParaView's Python extension
# modules (VTK::vtk*Python, ParaView::*Python) and of its command-line tools
# (ParaView::pvpython, pvbatch, pvserver, ...), but their files come with
# python3-paraview, which conflicts with python3-vtk9 (both ship vtkmodules)
# and is never installed here. The exported targets files stop the
# configuration when a referenced file is missing, unless every target of
# their export set is already defined: then they return at once. The plugin
# uses neither Python nor those tools, so the targets of the three export
# sets are declared here,
# before find_package(ParaView), as empty imported targets.
#
# Input: SURFACEMAPS_PARAVIEW_DIR, the directory of paraview-config.cmake.
foreach (_surfacemaps_targets_file IN ITEMS
    "${SURFACEMAPS_PARAVIEW_DIR}/vtk/VTKPython-targets.cmake"
    "${SURFACEMAPS_PARAVIEW_DIR}/ParaViewPython-targets.cmake"
    "${SURFACEMAPS_PARAVIEW_DIR}/ParaViewTools-targets.cmake")
  if (NOT EXISTS "${_surfacemaps_targets_file}")
    continue ()
  endif ()
  file(STRINGS "${_surfacemaps_targets_file}" _surfacemaps_line
    REGEX "^foreach\\(_cmake_expected_target IN ITEMS ")
  string(REGEX REPLACE "^foreach\\(_cmake_expected_target IN ITEMS ([^)]*)\\)$" "\\1"
    _surfacemaps_targets "${_surfacemaps_line}")
  separate_arguments(_surfacemaps_targets)
  foreach (_surfacemaps_target IN LISTS _surfacemaps_targets)
    if (NOT TARGET "${_surfacemaps_target}")
      add_library("${_surfacemaps_target}" INTERFACE IMPORTED)
    endif ()
  endforeach ()
endforeach ()
unset(_surfacemaps_targets_file)
unset(_surfacemaps_line)
unset(_surfacemaps_targets)
unset(_surfacemaps_target)
