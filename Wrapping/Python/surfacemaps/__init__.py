"""SurfaceMaps: bijective maps between genus-0 surfaces via adaptive common triangulations.

The VTK classes of the module are available directly from this package::

    import surfacemaps
    reader = surfacemaps.vtkSurfaceMeshReader()
    reader.SetFileName("spot.obj")

Helpers:

``read_mesh(path, landmarks=None, sizing=None)``
    Read a mesh (and optional landmark and sizing files) into a vtkPolyData;
    landmarks given as points are snapped to the closest vertex (distances in
    the field data, a warning above 1 % of the bounding-box diagonal); raises
    ``surfacemaps.InputError`` with the reader's message on failure.
``validate(*meshes)``
    Validate one or more vtkPolyData as SurfaceMaps inputs; returns a list of
    dictionaries (one per mesh) with the statistics and the defects.
``embed_on_sphere(mesh, **settings)``
    Certified bijective sphere embedding (vtkSphereEmbeddingFilter); returns
    the mesh with the point array "SpherePosition"; raises InputError.
``evaluate_map(source, target, source_original=None, target_original=None)``
    The metrics of vtkSurfaceMapEvaluation as a dictionary.
``map_surfaces(meshes, landmarks=None, target_error=None, pairs=None, keep_landmarks=None, **settings)``
    Certified bijective map between meshes (vtkSurfaceMapFilter; with
    ``add_to=`` a map, the meshes are added to it); returns one
    output per mesh (the common triangulation lifted onto each), or with
    ``mapped=True`` also the first mesh mapped onto each, as a MapResult (a
    list that also holds the map, for transfer); raises InputError or
    MapError.
``transfer(mapping, source, target, arrays=None, source_data=None, as_numpy=False)``
    Point data (and texture coordinates) of input `source` of a map carried
    onto input `target`'s vertices (vtkSurfaceMapTransfer): a saved map
    (``surfacemap map``'s directory) or one in memory (what map_surfaces
    returns, or a vtkSurfaceMapFilter); `source_data` carries new arrays (a
    dict of numpy arrays, one row per source vertex, or a vtkPolyData of the
    source's connectivity) instead of those the source had; raises InputError.
``point_arrays(mesh)``
    The point arrays of a vtkPolyData as a dict of numpy arrays.
``average_surfaces(meshes, weights=None, align="rigid")``
    Weighted mean shape of meshes with identical connectivity (e.g. the
    outputs of map_surfaces) after generalized Procrustes alignment; it does
    not depend on the order of the meshes (vtkSurfaceAverage).
``align_surfaces(meshes, align="rigid")``
    Copies of meshes with identical connectivity moved onto the frame of
    their order-free mean (the alignment of average_surfaces), e.g. stage
    means before they become keyframes of an interpolated series.
``shape_statistics(meshes, modes=3, align="rigid")``
    Mean shape, principal modes of variation, variances, explained-variance
    fractions, scores and per-vertex spread of meshes with identical
    connectivity (vtkSurfaceShapeStatistics), as a ShapeStatistics.

Point arrays carried onto other points (map_surfaces, transfer,
average_surfaces) are continuous (interpolated; by default the floating-point
arrays) or categorical (labels: never a value the source does not have; by
default the integer arrays): through a map the value of the nearest corner of
the source triangle, in an average input 0's values. Each of these helpers
takes ``categorical=[names]`` and ``continuous=[names]`` to choose per array
(vtkSurfaceArrayTransferAlgorithm.SetArrayTransferMode).
``write_time_series(source, times, directory, name="surface")``
    The output of a temporal source (e.g. vtkSurfaceSequenceInterpolator) at
    each time as .vtp files plus a ParaView .pvd collection.
``write_collection(meshes, times, directory, name)``
    Given meshes, one per time, as .vtp files plus a ParaView .pvd collection.

Failures in pipelines: after every Update(), check the algorithm's
GetErrorCode() (or its GetLastErrorMessage()) before reading its outputs. When
an algorithm upstream fails, the module's algorithms downstream clear their
outputs and report InvalidInputError naming it; an executive other than the
module's (ParaView's) keeps VTK's behaviour, where a downstream algorithm does
not run and keeps the figures of its previous update. The helpers above check
for you and raise (InputError, MapError) instead of returning such outputs;
transfer also raises for a MapResult whose inputs were changed in place after
map_surfaces computed it.

The helpers are defined by concept in the modules ``mesh``, ``mapping``,
``transfer``, ``statistics``, ``files`` and ``errors``; import
them from the package itself, as above.

Submodules: ``surfacemaps.plots`` (distortion curves), ``surfacemaps.render``
(offscreen pictures), ``surfacemaps.population`` (``python3 -m
surfacemaps.population STAGES_DIR --output-dir OUT``: stage maps and means,
spread, one map across the stages, shape statistics over all specimens, the
interpolated series; under MPI when run with mpirun), ``surfacemaps.specimens``
(every specimen on T: its fit table and correspondences.npz, as ``surfacemap
map`` writes them).
"""

import vtkmodules.vtkCommonCore  # noqa: F401  (VTK's base classes must be loaded first)
import vtkmodules.vtkCommonDataModel  # noqa: F401
import vtkmodules.vtkCommonExecutionModel  # noqa: F401

from .SurfaceMapsFilters import *  # noqa: F401,F403

from .errors import InputError, MapError, SurfaceMapsWarning  # noqa: F401
from .mesh import point_arrays, read_mesh, validate  # noqa: F401
from .mapping import MapResult, embed_on_sphere, evaluate_map, map_surfaces, presets, settings_table  # noqa: F401
from .transfer import transfer  # noqa: F401  (the function: it replaces the module's name here)
from .statistics import ShapeStatistics, align_surfaces, average_surfaces, shape_statistics  # noqa: F401
from .files import map_file_stamp, write_collection, write_mesh, write_time_series  # noqa: F401

__version__ = "0.1.0"
