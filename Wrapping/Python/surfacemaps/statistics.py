"""Statistics over meshes of one connectivity (e.g. a map's outputs): the weighted mean shape
(vtkSurfaceAverage) and the principal modes of variation (vtkSurfaceShapeStatistics)."""

from .SurfaceMapsFilters import vtkSurfaceAverage, vtkSurfaceShapeStatistics
from .errors import InputError, _collect_errors, _update
from .mesh import _set_array_transfer_modes, _with_landmarks


_ALIGN_MODES = {"none": vtkSurfaceAverage.ALIGN_NONE, "rigid": vtkSurfaceAverage.ALIGN_RIGID,
                "similarity": vtkSurfaceAverage.ALIGN_SIMILARITY}


def average_surfaces(meshes, weights=None, align="rigid", categorical=None, continuous=None):
    """Weighted mean shape of meshes with identical connectivity (vtkSurfaceAverage).

    - `meshes`: vtkPolyData or file names, all with the same points count and
      cells, e.g. the outputs of map_surfaces (one common triangulation lifted
      onto each surface).
    - `weights`: None (all 1) or one weight >= 0 per mesh; normalised to sum 1.
    - `align`: "none", "rigid" (rotation and translation of each mesh onto the
      mean, area-weighted least squares, iterated with the mean: generalized
      Procrustes) or "similarity" (also a uniform scale).
    - `categorical`, `continuous`: names of point arrays taken from the first
      mesh (labels) or averaged, instead of by type (integer arrays
      categorical, floating-point ones continuous).

    The mean does not depend on the order of the meshes (with their weights):
    it lies where the meshes lie (placed by the rigid motion that fits it best
    to them as given), with the mean size of theirs under "similarity".
    Categorical arrays are the first mesh's.

    Returns a vtkPolyData with the first mesh's cells, the averaged points
    and point arrays, and field data "AlignmentRMS" (per mesh, the
    area-weighted RMS distance of the aligned mesh to the mean),
    "AlignmentTransform" (per mesh, the 3x4 matrix into the mean's frame),
    "AverageWeight" (and "AlignmentScale"). Raises InputError when the
    connectivity differs or a weight is invalid.
    """
    meshes = list(meshes)
    if not meshes:
        raise InputError("no meshes to average")
    if align not in _ALIGN_MODES:
        raise ValueError(f"align is one of {sorted(_ALIGN_MODES)}, not {align!r}")
    if weights is not None:
        weights = [float(w) for w in weights]
        if len(weights) != len(meshes):
            raise InputError(f"{len(meshes)} meshes but {len(weights)} weights")
    a = vtkSurfaceAverage()
    _set_array_transfer_modes(a, categorical, continuous)
    errors = _collect_errors(a)
    a.SetAlignMode(_ALIGN_MODES[align])
    for k, mesh in enumerate(meshes):
        a.AddInputData(_with_landmarks(mesh, None))
        if weights is not None:
            a.SetInputWeight(k, weights[k])
    _update(a, errors)
    if errors or a.GetOutput().GetNumberOfPoints() == 0:
        raise InputError("; ".join(errors) or "the average was aborted")
    result = a.GetOutput().NewInstance()
    result.ShallowCopy(a.GetOutput())
    return result


def align_surfaces(meshes, align="rigid"):
    """Copies of meshes with identical connectivity, each moved onto the frame of their order-free
    mean by average_surfaces' alignment ("rigid", "similarity" or "none": copies as given).

    The keyframes vtkSurfaceSequenceInterpolator blends with the same alignment setting: stage
    means aligned this way do not roll or change size between stages. Point arrays are copied
    unchanged (vectors are not turned). Returns a list of vtkPolyData; raises as average_surfaces.
    """
    import numpy as np
    from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
    from vtkmodules.vtkCommonCore import vtkPoints

    meshes = list(meshes)
    transforms = None
    if align != "none":
        mean = average_surfaces(meshes, align=align)
        transforms = vtk_to_numpy(mean.GetFieldData().GetArray("AlignmentTransform")).reshape(-1, 3, 4)
    result = []
    for k, mesh in enumerate(meshes):
        copy = mesh.NewInstance()
        copy.DeepCopy(mesh)
        if transforms is not None:
            moved = vtk_to_numpy(mesh.GetPoints().GetData()) @ transforms[k][:, :3].T + transforms[k][:, 3]
            points = vtkPoints()
            points.SetData(numpy_to_vtk(np.ascontiguousarray(moved, dtype=np.float64), deep=True))
            copy.SetPoints(points)
        result.append(copy)
    return result


class ShapeStatistics:
    """The result of shape_statistics (numpy arrays; k modes, N meshes, V vertices).

    - ``mean``: vtkPolyData of the mean shape with the point arrays
      "StandardDeviation" and "Mode_1" ... "Mode_k";
    - ``variances`` (k), ``explained_fractions`` (k), ``total_variance``;
    - ``scores`` (N x k): mesh i ~ mean + sum_m scores[i, m] * modes[m];
    - ``modes`` (k x V x 3): unit area-weighted norm;
    - ``standard_deviation`` (V), ``alignment_rms`` (N).
    ``shape(mode, coefficient)`` is the mean moved `coefficient` standard
    deviations along `mode` (1-based), a vtkPolyData.
    """

    def __init__(self, algorithm):
        from vtkmodules.util.numpy_support import vtk_to_numpy
        import numpy as np

        self._algorithm = algorithm
        self.mean = algorithm.GetOutput().NewInstance()
        self.mean.ShallowCopy(algorithm.GetOutput())
        fields, points = self.mean.GetFieldData(), self.mean.GetPointData()
        self.variances = vtk_to_numpy(fields.GetArray("Variance")).copy()
        k = len(self.variances)
        self.explained_fractions = vtk_to_numpy(fields.GetArray("ExplainedVarianceFraction")).copy()
        self.total_variance = fields.GetArray("TotalVariance").GetValue(0)
        self.scores = vtk_to_numpy(fields.GetArray("Scores")).reshape(-1, k).copy()
        self.modes = np.array([vtk_to_numpy(points.GetArray(f"Mode_{m + 1}")) for m in range(k)])
        self.standard_deviation = vtk_to_numpy(points.GetArray("StandardDeviation")).copy()
        self.alignment_rms = vtk_to_numpy(fields.GetArray("AlignmentRMS")).copy()

    def shape(self, mode, coefficient):
        """The mean + coefficient * sqrt(variance) * mode (mode 1-based) as vtkPolyData."""
        a = self._algorithm
        if not 1 <= mode <= len(self.variances):
            raise ValueError(f"mode is 1 to {len(self.variances)}, not {mode}")
        a.SetMode(mode)
        a.SetCoefficient(coefficient)
        _update(a)
        result = a.GetOutput().NewInstance()
        result.ShallowCopy(a.GetOutput())
        return result


def shape_statistics(meshes, modes=3, align="rigid"):
    """Mean shape and principal modes of variation of meshes with identical connectivity.

    - `meshes`: two or more vtkPolyData or file names with the same points
      count and cells, e.g. the outputs of map_surfaces.
    - `modes`: modes computed (at most N - 1 come out).
    - `align`: "none", "rigid" (size stays part of the variation) or
      "similarity" (shape alone): generalized Procrustes alignment first, as
      average_surfaces does it (the same order-free mean).

    Variances, scores and mode norms use the area-weighted inner product
    (vertex areas, normalised to sum 1), with 1/N: sqrt(variance) is an RMS
    displacement over the surface in length units. Returns a ShapeStatistics;
    raises InputError (connectivity, fewer than 2 meshes).
    """
    meshes = list(meshes)
    if align not in _ALIGN_MODES:
        raise ValueError(f"align is one of {sorted(_ALIGN_MODES)}, not {align!r}")
    if len(meshes) < 2:
        raise InputError(f"shape statistics need at least 2 meshes, not {len(meshes)}")
    a = vtkSurfaceShapeStatistics()
    errors = _collect_errors(a)
    a.SetAlignMode(_ALIGN_MODES[align])
    a.SetNumberOfModes(int(modes))
    for mesh in meshes:
        a.AddInputData(_with_landmarks(mesh, None))
    _update(a, errors)
    if errors or a.GetOutput().GetNumberOfPoints() == 0:
        raise InputError("; ".join(errors) or "the statistics were aborted")
    return ShapeStatistics(a)
