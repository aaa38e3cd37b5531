# Debian's paraview-dev does not ship the wrapping hierarchy files of
# ParaView's bundled VTK (lib/<arch>/vtk/hierarchy/ParaView/*.txt), which the
# client-server wrapping of the plugin's modules reads to know the classes
# their headers name (superclasses, typedefs). Debian's VTK 9.1 ships its own
# (libvtk9-dev, installed by .ci/install-deps.sh): ParaView 5.11's VTK is a
# later 9.x, but the classes the module's public headers name
# (vtkPolyDataAlgorithm, vtkTableAlgorithm, vtkAlgorithmOutput, ...) have the
# same hierarchy in both. So every imported VTK module whose hierarchy file is
# missing points at VTK 9.1's file of the same name, or has none (a module
# without one is skipped by the wrapping).
#
# Call after find_package(ParaView), in the directory that called it.
set(SURFACEMAPS_VTK_HIERARCHY_DIR "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/vtk/hierarchy/VTK"
  CACHE PATH "Wrapping hierarchy files standing in for ParaView's missing ones")
get_property(_surfacemaps_imported DIRECTORY PROPERTY IMPORTED_TARGETS)
foreach (_surfacemaps_target IN LISTS _surfacemaps_imported)
  get_property(_surfacemaps_hierarchy_set TARGET "${_surfacemaps_target}"
    PROPERTY INTERFACE_vtk_module_hierarchy SET)
  if (NOT _surfacemaps_hierarchy_set)
    continue ()
  endif ()
  get_property(_surfacemaps_hierarchy TARGET "${_surfacemaps_target}"
    PROPERTY INTERFACE_vtk_module_hierarchy)
  if (EXISTS "${_surfacemaps_hierarchy}")
    continue ()
  endif ()
  get_filename_component(_surfacemaps_name "${_surfacemaps_hierarchy}" NAME)
  if (EXISTS "${SURFACEMAPS_VTK_HIERARCHY_DIR}/${_surfacemaps_name}")
    set_property(TARGET "${_surfacemaps_target}" PROPERTY INTERFACE_vtk_module_hierarchy
      "${SURFACEMAPS_VTK_HIERARCHY_DIR}/${_surfacemaps_name}")
  else ()
    set_property(TARGET "${_surfacemaps_target}" PROPERTY INTERFACE_vtk_module_hierarchy)
  endif ()
endforeach ()
unset(_surfacemaps_imported)
unset(_surfacemaps_target)
unset(_surfacemaps_hierarchy_set)
unset(_surfacemaps_hierarchy)
unset(_surfacemaps_name)
