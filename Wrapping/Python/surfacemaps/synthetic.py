"""Synthetic heart-tube-like surfaces: closed genus-0 tubes that bend and loop over time.

A stand-in for a developmental time series of organ surfaces (e.g. mouse
heart tubes in stage groups), made to exercise averaging and interpolation
with SurfaceMaps. Developmental time ``t`` runs from 0 to 1: at ``t = 0`` the
tube is straight; with ``t`` it lengthens, its middle widens, and it bends in
one plane (turning up to 225 degrees) while rising out of that plane, so that
at ``t = 1`` it forms an open helical loop.

Each surface is swept along the tube's centre curve (a rotation-minimising
frame carries the cross-section), with rounded end caps. Every mesh is
closed, 2-manifold, genus 0, outward oriented and free of degenerate
triangles. Specimens of one stage differ by

- smooth shape noise (centre-curve bends, radius bulges around and along the
  tube, overall size), seeded,
- pose (a small random rotation and translation),
- developmental time (a small spread around the stage's time),
- triangulation: the number of vertices around and along the tube, a random
  angular offset of every ring, and random vertex jitter within the surface
  (in the sweep's parameters, so points stay on the smooth surface).

Landmarks (point array "Landmarks", int, -1 elsewhere): id 0 is the tip of
the cap at the tube's start (inflow), id 1 the tip at its end (outflow),
id 2 the point halfway along the tube on its outer curvature. The same id
marks corresponding points on every specimen, which maps between elongated
tubes need to keep the ends apart.

Field data: "DevelopmentalTime" (the specimen's own t), "Stage" and
"Specimen" (indices, when made by :func:`time_series` / :func:`stage_specimens`;
"Specimen" also by :func:`specimens`).

Example::

    from surfacemaps import synthetic
    for t, meshes in synthetic.time_series(stages=4, specimens_per_stage=3, seed=1):
        print(t, [m.GetNumberOfPoints() for m in meshes])

Needs numpy.
"""

import math

import numpy as np

LANDMARK_NAMES = ("inflow tip", "outflow tip", "outer curvature")


# ------------------------------------------------------------ the shape over time

def tube_length(t):
    """Arc length of the centre curve at developmental time t (3 at t = 0, 4.5 at t = 1)."""
    return 3.0 + 1.5 * t


def turning_angle(t):
    """Total in-plane turning of the centre curve, radians (0 at t = 0, 225 degrees at t = 1)."""
    return 1.25 * math.pi * t


def lift_angle(t):
    """Constant angle of the centre curve out of the bending plane, radians (helical rise)."""
    return 0.35 * t


def radius(t, s):
    """Tube radius at arc-length fraction s in [0, 1]: 0.22 at the ends, widest in the middle."""
    s = np.asarray(s, float)
    return 0.22 + (0.10 + 0.08 * t) * np.sin(math.pi * s) ** 2


def centre_curve(t, samples=801):
    """The centre curve at time t, sampled at `samples` equally spaced arc-length fractions.

    Returns ``(s, points, tangents, normals, binormals)`` (arrays of shape (n,)
    and (n, 3)). The curvature is largest in the middle (profile
    1 - cos(2 pi s) / 2); normals and binormals form a rotation-minimising
    frame starting with the normal +x, the side the tube bends towards, so
    the outer curvature lies in direction -normal. Centred on the origin.
    """
    s = np.linspace(0.0, 1.0, samples)
    theta = turning_angle(t) * (s - np.sin(2.0 * math.pi * s) / (4.0 * math.pi))
    phi = lift_angle(t)
    tangents = np.stack([math.cos(phi) * np.sin(theta), np.full_like(s, math.sin(phi)),
                         math.cos(phi) * np.cos(theta)], axis=1)
    step = tube_length(t) / (samples - 1)
    points = np.zeros((samples, 3))
    points[1:] = np.cumsum(0.5 * (tangents[1:] + tangents[:-1]) * step, axis=0)
    points -= points.mean(axis=0)
    normals = np.zeros_like(points)
    normal = np.array([1.0, 0.0, 0.0])
    for i, tangent in enumerate(tangents):
        normal = normal - normal.dot(tangent) * tangent  # parallel transport by projection
        normal /= np.linalg.norm(normal)
        normals[i] = normal
    binormals = np.cross(tangents, normals)
    return s, points, tangents, normals, binormals


# ------------------------------------------------------------ one surface

def _interpolate(s_grid, values, s):
    """Linear interpolation of rows of `values` (n, 3) at fractions s."""
    return np.stack([np.interp(s, s_grid, values[:, k]) for k in range(values.shape[1])], axis=-1)


def _ring_angles(count, rng, jitter, through_pi=False):
    """`count` increasing angles around a ring: random offset, jitter as a fraction of the spacing."""
    spacing = 2.0 * math.pi / count
    if through_pi:
        offset = math.pi - spacing * (count // 2)  # vertex count // 2 sits exactly at angle pi
    else:
        offset = rng.uniform(0.0, spacing)
    angles = offset + spacing * np.arange(count) + jitter * spacing * rng.uniform(-0.5, 0.5, count)
    if through_pi:
        angles[count // 2] = math.pi
    return angles


def _zip_rings(first, first_angles, second, second_angles):
    """Triangles between two closed rings of vertex ids (angles increasing), outward for the sweep."""
    m, n = len(first), len(second)
    if m == 1 or n == 1:  # a pole: a fan
        if m == 1:
            return [(first[0], second[(j + 1) % n], second[j]) for j in range(n)]
        return [(first[i], first[(i + 1) % m], second[0]) for i in range(m)]
    a = np.append(first_angles, first_angles[0] + 2.0 * math.pi)
    # Start the second ring at the vertex closest in angle to the first ring's start.
    start = int(np.argmin(np.abs(np.angle(np.exp(1j * (second_angles - first_angles[0]))))))
    order = [(start + k) % n for k in range(n + 1)]
    b = second_angles[order].copy()
    b += 2.0 * math.pi * np.round((first_angles[0] - b[0]) / (2.0 * math.pi))
    b[1:] += 2.0 * math.pi * np.cumsum(np.diff(b) < 0)  # unwrap: strictly increasing
    triangles, i, j = [], 0, 0
    while i < m or j < n:
        if j == n or (i < m and a[i + 1] < b[j + 1]):
            triangles.append((first[i], first[(i + 1) % m], second[order[j]]))
            i += 1
        else:
            triangles.append((first[i % m], second[order[j + 1]], second[order[j]]))
            j += 1
    return triangles


def tube_mesh(t, around=24, seed=None, shape_noise=0.0, jitter=0.0, pose_noise=0.0):
    """One closed tube surface at developmental time t, as vtkPolyData.

    - `around`: vertices around the tube's body (>= 6); rings along it are
      spaced to match, end caps get fewer vertices per ring towards the tip.
    - `seed`: seed (or numpy Generator) of the noise and the ring offsets;
      None with no noise and no jitter gives the ideal tube.
    - `shape_noise`: amplitude of the smooth shape noise (0.04 is a visible
      but plausible specimen-to-specimen variation; keep it below 0.1).
    - `jitter`: vertex jitter within the surface as a fraction of the vertex
      spacing (0 to 0.5).
    - `pose_noise`: random rotation (radians, about a random axis) and
      translation (that times the tube's length) of the whole specimen.

    Point array "Landmarks" (ids 0, 1, 2: see the module doc), field array
    "DevelopmentalTime".
    """
    if around < 6:
        raise ValueError(f"around is at least 6, not {around}")
    if not 0.0 <= jitter <= 0.5:
        raise ValueError(f"jitter is a fraction of the vertex spacing in [0, 0.5], not {jitter}")
    rng = seed if isinstance(seed, np.random.Generator) else np.random.default_rng(seed)
    length = tube_length(t)
    grid, centre, tangents, normals, binormals = centre_curve(t)

    # Smooth shape noise: bends of the centre curve, radius bulges, size.
    bend = shape_noise * length * rng.normal(size=(3, 2)) / np.arange(1, 4)[:, None] * 0.5
    bulge_along = shape_noise * rng.normal(size=2)
    bulge_around = shape_noise * rng.normal(size=2)
    bulge_phase = rng.uniform(0.0, 2.0 * math.pi, 2)
    size = math.exp(0.5 * shape_noise * rng.normal())

    def frame(s):
        n = _interpolate(grid, normals, s)
        b = _interpolate(grid, binormals, s)
        return n, b

    def centre_at(s):
        n, b = frame(s)
        waves = np.stack([np.sin((k + 1) * math.pi * s) for k in range(3)], axis=-1)
        offset = (waves @ bend[:, 0])[:, None] * n + (waves @ bend[:, 1])[:, None] * b
        return _interpolate(grid, centre, s) + offset

    def radius_at(s, a):
        along = 1.0 + bulge_along[0] * np.cos(math.pi * s) + bulge_along[1] * np.cos(2.0 * math.pi * s)
        around_ = 1.0 + 0.5 * (bulge_around[0] * np.cos(a - bulge_phase[0])
                               + bulge_around[1] * np.cos(2.0 * a - bulge_phase[1]))
        return radius(t, s) * np.maximum(along * around_, 0.5)

    def body(s, a):
        n, b = frame(s)
        direction = np.cos(a)[:, None] * n + np.sin(a)[:, None] * b
        return centre_at(s) + radius_at(s, a)[:, None] * direction

    def cap(end, beta, a):
        s = np.full_like(a, float(end))
        n, b = frame(s)
        direction = np.cos(a)[:, None] * n + np.sin(a)[:, None] * b
        axis = _interpolate(grid, tangents, s) * (1.0 if end else -1.0)
        tip = radius(t, float(end)) * np.cos(beta)[:, None] * axis
        return centre_at(s) + tip + (radius_at(s, a) * np.sin(beta))[:, None] * direction

    # Rings along the tube: spacing along ~ spacing around at the mean radius.
    mean_radius = float(np.mean(radius(t, grid)))
    body_rings = max(5, int(round(length / (2.0 * math.pi * mean_radius / around))))
    body_rings += 1 - body_rings % 2  # odd: a ring at s = 0.5 carries the outer-curvature landmark
    cap_rings = max(2, int(round(around / 4)))
    beta_step = 0.5 * math.pi / cap_rings
    s_step = 1.0 / (body_rings - 1)

    points, rings = [], []  # rings: (vertex ids, angles) from the start tip to the end tip
    landmarks = {}

    def add(xyz, angles):
        first = sum(len(p) for p in points)
        points.append(xyz)
        rings.append((np.arange(first, first + len(xyz)), np.asarray(angles, float)))
        return first

    landmarks[0] = add(cap(0, np.zeros(1), np.zeros(1)), [0.0])
    for k in range(1, cap_rings):
        count = max(3, int(round(around * math.sin(k * beta_step))))
        a = _ring_angles(count, rng, jitter)
        beta = k * beta_step + jitter * beta_step * rng.uniform(-0.5, 0.5, count)
        add(cap(0, beta, a), a)
    middle = body_rings // 2
    for j in range(body_rings):
        a = _ring_angles(around, rng, jitter, through_pi=(j == middle))
        s = np.full(around, j * s_step)
        if 0 < j < body_rings - 1:
            s += jitter * s_step * rng.uniform(-0.5, 0.5, around)
        if j == middle:
            s[around // 2] = 0.5
        first = add(body(s, a), a)
        if j == middle:
            landmarks[2] = first + around // 2
    for k in range(cap_rings - 1, 0, -1):
        count = max(3, int(round(around * math.sin(k * beta_step))))
        a = _ring_angles(count, rng, jitter)
        beta = k * beta_step + jitter * beta_step * rng.uniform(-0.5, 0.5, count)
        add(cap(1, beta, a), a)
    landmarks[1] = add(cap(1, np.zeros(1), np.zeros(1)), [0.0])

    triangles = []
    for (ids0, angles0), (ids1, angles1) in zip(rings[:-1], rings[1:]):
        triangles += _zip_rings(ids0, angles0, ids1, angles1)
    xyz = np.concatenate(points) * size

    if pose_noise > 0.0:
        axis = rng.normal(size=3)
        axis /= np.linalg.norm(axis)
        angle = pose_noise * rng.normal()
        k = np.array([[0.0, -axis[2], axis[1]], [axis[2], 0.0, -axis[0]], [-axis[1], axis[0], 0.0]])
        rotation = np.eye(3) + math.sin(angle) * k + (1.0 - math.cos(angle)) * k @ k
        xyz = xyz @ rotation.T + pose_noise * length * rng.normal(size=3)

    ids = np.full(len(xyz), -1, dtype=np.int32)
    for landmark, vertex in landmarks.items():
        ids[vertex] = landmark
    return polydata(xyz, np.asarray(triangles, dtype=np.int64), landmarks=ids, time=t)


def polydata(points, triangles, landmarks=None, time=None):
    """vtkPolyData from numpy points (n, 3) and triangles (m, 3) (+ "Landmarks", "DevelopmentalTime")."""
    from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    points = np.ascontiguousarray(points, dtype=np.float64)
    triangles = np.asarray(triangles).reshape(-1, 3)
    vtk_points = vtkPoints()
    vtk_points.SetDataTypeToDouble()
    vtk_points.SetData(numpy_to_vtk(points, deep=True))
    cells = vtkCellArray()
    offsets = np.arange(0, 3 * len(triangles) + 1, 3, dtype=np.int64)
    cells.SetData(numpy_to_vtkIdTypeArray(offsets, deep=True),
                  numpy_to_vtkIdTypeArray(np.ascontiguousarray(triangles.ravel(), dtype=np.int64), deep=True))
    mesh = vtkPolyData()
    mesh.SetPoints(vtk_points)
    mesh.SetPolys(cells)
    if landmarks is not None:
        array = numpy_to_vtk(np.ascontiguousarray(landmarks, dtype=np.int32), deep=True)
        array.SetName("Landmarks")
        mesh.GetPointData().AddArray(array)
    if time is not None:
        field = vtkDoubleArray()
        field.SetName("DevelopmentalTime")
        field.InsertNextValue(float(time))
        mesh.GetFieldData().AddArray(field)
    return mesh


# ------------------------------------------------------------ specimens and series

def _tag(mesh, name, value):
    from vtkmodules.vtkCommonCore import vtkIntArray
    array = vtkIntArray()
    array.SetName(name)
    array.InsertNextValue(int(value))
    mesh.GetFieldData().AddArray(array)


def specimens(t, count, seed=0, resolution=24, shape_noise=0.04, jitter=0.3, pose_noise=0.05, time_spread=0.02,
              resolution_spread=0.25):
    """`count` noisy specimens around developmental time t, each with its own triangulation.

    Specimen i draws its noise from ``numpy.random.SeedSequence(seed).spawn``
    so the list is the same for the same seed. Its vertices around the tube
    are ``resolution`` times a factor drawn from [1 - resolution_spread,
    1 + resolution_spread]; its own time is t plus a normal spread of
    `time_spread`, clipped to [0, 1]. Other settings: see :func:`tube_mesh`.
    """
    meshes = []
    for i, child in enumerate(np.random.SeedSequence(seed).spawn(count)):
        rng = np.random.default_rng(child)
        around = max(6, int(round(resolution * rng.uniform(1.0 - resolution_spread, 1.0 + resolution_spread))))
        own_time = float(np.clip(t + time_spread * rng.normal(), 0.0, 1.0))
        mesh = tube_mesh(own_time, around=around, seed=rng, shape_noise=shape_noise, jitter=jitter,
                         pose_noise=pose_noise)
        _tag(mesh, "Specimen", i)
        meshes.append(mesh)
    return meshes


def stage_times(stages):
    """Evenly spaced stage times in [0, 1] (0.5 for a single stage)."""
    return [0.5] if stages == 1 else [k / (stages - 1) for k in range(stages)]


def stage_specimens(k, stages, specimens_per_stage=5, seed=0, resolution=24, **settings):
    """``(t_k, [specimen meshes])`` of stage k alone, exactly as in :func:`time_series`."""
    t = stage_times(stages)[k]
    meshes = specimens(t, specimens_per_stage, seed=[seed, k], resolution=resolution, **settings)
    for mesh in meshes:
        _tag(mesh, "Stage", k)
    return t, meshes


def time_series(stages=10, specimens_per_stage=5, seed=0, resolution=24, **settings):
    """``[(t_k, [specimen meshes])]`` for `stages` evenly spaced times; settings as :func:`specimens`.

    Stage k's specimens are seeded with ``[seed, k]``.
    """
    return [stage_specimens(k, stages, specimens_per_stage, seed, resolution, **settings) for k in range(stages)]
