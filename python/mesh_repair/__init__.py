"""Mesh_repair for Python: repair triangle meshes and fill holes, numpy arrays in and out.

Every operator takes a mesh as ``(vertices, faces)`` -- vertices a float64 array of shape
(n, 3), faces an integer array of shape (m, 3) or a list of polygons -- or as the path of an
OFF, OBJ, STL or PLY file, and returns new arrays and a report dict with the keys of the JSON
report of the matching ``mesh_repair`` command (doc/report_schema.md). The input arrays are
never modified. The input goes through the CLI's polygon-soup stage first (validation, CGAL's
soup repair and orientation, triangulation), whose changes the report counts.

Bad input raises ``ValueError`` with the CLI's one-line reason. The work runs without the
GIL; Ctrl-C stops it at the next progress point and raises ``KeyboardInterrupt`` (nothing is
returned, nothing was modified). ``progress=callback`` is called as ``callback(step, fraction)``
from the calling thread, at most every 50 ms and at each step boundary; an exception it raises
cancels the work and propagates.

Batch repair of many files, locally or on a Dask cluster: ``mesh_repair.batch.repair_many``.
See doc/python.md.
"""

import json as _json
import math as _math
import numbers as _numbers
import os as _os
from collections import namedtuple as _namedtuple

from . import _core

__all__ = [
    "Result",
    "read",
    "write",
    "check",
    "repair",
    "fill_holes",
    "stitch",
    "remove_slivers",
    "optimize",
    "suppress_feature",
    "smooth",
    "mesh_points",
    "bench_holes",
    "faces_in_sphere",
    "faces_in_box",
    "FILL_METHODS",
    "SMOOTHING_METHODS",
    "BENCH_METHODS",
    "HOLE_SHAPES",
]

#: ``(vertices, faces, report)``: what every operator that makes a mesh returns. ``faces`` is an
#: int64 array of shape (m, k) when every face has k vertices, else a list of polygons.
Result = _namedtuple("Result", "vertices faces report")

#: The hole-filling methods (doc/fill_holes.md).
FILL_METHODS = (
    "self_validated",
    "auto",
    "advancing_front",
    "shape_prediction",
    "curvature_variation",
    "liepa",
)

#: The smoothers of ``smooth`` (doc/mga_smooth.md): the micro-GA, the conjugate-gradient
#: baseline, CGAL's angle_and_area_smoothing + tangential_relaxation.
SMOOTHING_METHODS = ("mga", "cg", "cgal")

#: The methods of ``bench_holes`` (doc/bench_holes.md); ``"all"`` is every one but ``liepa``
#: (the alias of ``liepa_c1``).
BENCH_METHODS = (
    "advancing_front",
    "liepa",
    "liepa_c0",
    "liepa_c1",
    "liepa_c2",
    "shape_prediction",
    "curvature_variation",
    "self_validated",
    "auto",
)

#: The hole shapes of ``bench_holes``.
HOLE_SHAPES = ("disc", "jagged", "elongated", "ring")

_INT_MAX = 2**31 - 1
_SEED_MAX = 2**32 - 1


# ---- argument checks (the CLI's messages, with Python's parameter names) ----------------------


def _source(vertices, faces):
    """A path, or the (vertices, faces) pair the compiled module checks and copies."""
    if isinstance(vertices, (str, bytes, _os.PathLike)):
        if faces is not None:
            raise ValueError("give either a path or (vertices, faces), not both")
        path = _os.fsdecode(vertices)
        if not path:
            raise ValueError("the path is empty")
        return path
    if faces is None:
        raise ValueError("faces are missing: give (vertices, faces) or the path of a mesh file")
    return (vertices, faces)


def _number(name, value, low=-_math.inf, high=_math.inf, integer=False):
    kind = _numbers.Integral if integer else _numbers.Real
    if isinstance(value, bool) or not isinstance(value, kind):
        raise ValueError(f"{name} expects {'an integer' if integer else 'a number'}, got {value!r}")
    if not (low <= value <= high) or (not integer and _math.isnan(value)):
        raise ValueError(f"{name} must be in [{low}, {high}], got {value!r}")
    return int(value) if integer else float(value)


def _tolerance(options, tolerance, tolerance_rel):
    if tolerance is not None and tolerance_rel is not None:
        raise ValueError("give either tolerance or tolerance_rel, not both")
    if tolerance is not None:
        options["tolerance"] = _number("tolerance", tolerance, 0)
    if tolerance_rel is not None:
        options["tolerance_rel"] = _number("tolerance_rel", tolerance_rel, 0)
    return options


def _method(name, value):
    if value not in FILL_METHODS:
        raise ValueError(f"{name} expects one of {', '.join(FILL_METHODS)}, got {value!r}")
    return value


def _sheet_ratio(sheet_border_ratio, fill_sheet_borders):
    if fill_sheet_borders:
        return _math.inf
    ratio = _number("sheet_border_ratio", sheet_border_ratio)
    if not ratio > 0:
        raise ValueError("sheet_border_ratio must be positive")
    return ratio


def _points_source(points):
    """A path, or the (n, 3) points the compiled module checks and copies."""
    if isinstance(points, (str, bytes, _os.PathLike)):
        path = _os.fsdecode(points)
        if not path:
            raise ValueError("the path is empty")
        return path
    return points


def _list(name, value, check):
    """One value or a non-empty sequence of them, each passed through ``check``."""
    values = [value]
    if not isinstance(value, (_numbers.Number, str, bytes)):
        try:
            values = list(value)
        except TypeError:
            pass
    if not values:
        raise ValueError(f"{name} needs at least one value")
    return [check(v) for v in values]


def _bench_methods(methods):
    names = methods.split(",") if isinstance(methods, str) else _list("methods", methods, str)
    names = [n for n in names if n]
    for name in names:
        if name != "all" and name not in BENCH_METHODS:
            raise ValueError(f"unknown method {name!r}; methods are {', '.join(BENCH_METHODS)} "
                             "or all")
    if not names:
        raise ValueError("methods needs at least one method")
    return names


def _radius(value):
    radius = _number("radius", value)
    if not 0 < radius < 0.5:
        raise ValueError(f"radius must be in (0, 0.5), got {value!r}")
    return radius


def _progress(progress):
    if progress is not None and not callable(progress):
        raise ValueError("progress must be a callable (step, fraction) or None")
    return progress


def _result(raw):
    vertices, faces, report = raw
    return Result(vertices, faces, _json.loads(report))


# ---- operators ---------------------------------------------------------------------------------


def read(path, *, repair_soup=True):
    """Reads a mesh file (OFF, OBJ, STL, PLY) as the CLI does: validated, soup repaired and
    oriented (unless ``repair_soup=False``), polygons triangulated. Returns a ``Result``; the
    report holds ``input``, ``vertices``, ``faces`` and ``soup_repair``."""
    return _result(_core.read(_source(path, None), bool(repair_soup)))


def write(path, vertices, faces, *, binary=False):
    """Writes the mesh to ``path`` (format by extension; ``binary`` for STL/PLY) through a
    temporary file renamed into place. The arrays must form a valid polygon mesh (they are not
    repaired: use ``repair``). Returns ``{"output", "vertices", "faces", "binary"}``."""
    return _json.loads(_core.write(_os.fspath(path), vertices, faces, bool(binary)))


def check(vertices, faces=None, *, tolerance=None, tolerance_rel=None, self_intersections=True,
          progress=None):
    """Every defect of the mesh (``mesh_repair check --json``): border cycles, non-manifold
    elements, duplicated, degenerate and sliver faces, gaps, T-junctions, overlaps,
    self-intersections, components, closedness; the soup stage's findings merged in.
    ``tolerance`` (model units) or ``tolerance_rel`` (fraction of the bounding-box diagonal)
    is the gap / T-junction distance. Returns the report dict."""
    options = _tolerance({"self_intersections": bool(self_intersections)}, tolerance,
                         tolerance_rel)
    return _result(_core.check(_source(vertices, faces), options, _progress(progress))).report


def repair(vertices, faces=None, *, tolerance=None, tolerance_rel=None, fill="self_validated",
           continuity=1, max_hole_size=None, max_hole_edges=None, sheet_border_ratio=0.9,
           fill_sheet_borders=False, largest_component=False, ring_holes=True,
           self_intersections=True, remove_self_intersections=True,
           merge_intersecting_solids=False, remove_hole_fragments=True,
           bridge_through_holes=True, orient_closed_parts=True, threads=0, seed=0,
           progress=None):
    """The automatic repair pipeline (``mesh_repair repair``): soup repair and orientation,
    stitching of gaps and overlaps, T-junctions, degenerate faces, hole filling, verification.
    Options as the CLI's (``mesh_repair repair --help``): ``fill`` one of ``FILL_METHODS``,
    ``continuity`` 0-2 (Liepa fairing), ``max_hole_size`` (fraction of the bounding-box
    diagonal) and ``max_hole_edges`` leave larger holes open, ``threads`` 0 = all cores,
    ``remove_self_intersections`` replaces the faces that intersect others of their component
    by checked patches (``self_intersections=False`` neither counts nor removes them),
    ``merge_intersecting_solids`` replaces closed parts that intersect one another by their
    union (CGAL corefinement; the faces inside are removed), ``remove_hole_fragments`` removes
    the small open fragments of scans found in holes before filling (counted; ``False`` keeps
    them), ``bridge_through_holes`` gives the through-holes of a part whose wall is missing a
    tube between their two ends (counted; ``False`` leaves both ends to the hole filling),
    ``orient_closed_parts`` turns every closed part that faces inward outward, with the parts
    inside it (cavities stay cavities; counted; ``False`` keeps their orientation).
    Returns a ``Result``; the report holds ``soup_repair``, ``defects_before``,
    ``defects_after`` and ``repair``."""
    options = _tolerance({}, tolerance, tolerance_rel)
    options.update(
        fill=_method("fill", fill),
        continuity=_number("continuity", continuity, 0, 2, integer=True),
        sheet_border_ratio=_sheet_ratio(sheet_border_ratio, fill_sheet_borders),
        largest_component=bool(largest_component),
        ring_holes=bool(ring_holes),
        self_intersections=bool(self_intersections),
        remove_self_intersections=bool(remove_self_intersections),
        merge_intersecting_solids=bool(merge_intersecting_solids),
        remove_hole_fragments=bool(remove_hole_fragments),
        bridge_through_holes=bool(bridge_through_holes),
        orient_closed_parts=bool(orient_closed_parts),
        threads=_number("threads", threads, 0, 1024, integer=True),
        seed=_number("seed", seed, 0, 2**32 - 1, integer=True),
    )
    if max_hole_size is not None:
        options["max_hole_size"] = _number("max_hole_size", max_hole_size, 0)
    if max_hole_edges is not None:
        options["max_hole_edges"] = _number("max_hole_edges", max_hole_edges, 3, integer=True)
    return _result(_core.repair(_source(vertices, faces), options, _progress(progress)))


def fill_holes(vertices, faces=None, *, method="self_validated", continuity=1,
               max_hole_edges=None, max_hole_size=None, sheet_border_ratio=0.9,
               fill_sheet_borders=False, ring_holes=True, threads=0, seed=0, progress=None):
    """Fills the holes with one method (``mesh_repair fill``); every patch is checked with exact
    predicates and rolled back if it fails. ``method`` one of ``FILL_METHODS``; ``continuity``
    0-2 for liepa; holes with more than ``max_hole_edges`` border edges or wider than
    ``max_hole_size`` x the bounding-box diagonal stay open. Returns a ``Result``; the report
    holds ``method``, ``output_closed`` and ``result`` (one entry per hole)."""
    options = {
        "method": _method("method", method),
        "continuity": _number("continuity", continuity, 0, 2, integer=True),
        "sheet_border_ratio": _sheet_ratio(sheet_border_ratio, fill_sheet_borders),
        "ring_holes": bool(ring_holes),
        "threads": _number("threads", threads, 0, 1024, integer=True),
        "seed": _number("seed", seed, 0, 2**32 - 1, integer=True),
    }
    if max_hole_edges is not None:
        options["max_hole_edges"] = _number("max_hole_edges", max_hole_edges, 3, integer=True)
    if max_hole_size is not None:
        size = _number("max_hole_size", max_hole_size)
        if not size > 0:
            raise ValueError("max_hole_size must be positive")
        options["max_hole_size"] = size
    return _result(_core.fill_holes(_source(vertices, faces), options, _progress(progress)))


def stitch(vertices, faces=None, *, tolerance=None, tolerance_rel=None, curves=True,
           check_self_intersections=True, progress=None):
    """Closes gaps, small overlaps and T-junctions within a tolerance (``mesh_repair stitch``;
    default tolerance: half the shortest border edge at each node). ``curves=False`` puts
    T-junction nodes on the chord instead of the cubic boundary curve. Stitching that would make
    faces intersect is left undone (the vertices of those faces are frozen, counted in the
    report's ``stitch.frozen_vertices``); ``check_self_intersections=False`` skips that check
    (``--allow-self-intersections``). Returns a ``Result``; the report holds the border cycles
    before and after and ``stitch``."""
    options = _tolerance({"curves": bool(curves),
                          "check_self_intersections": bool(check_self_intersections)},
                         tolerance, tolerance_rel)
    return _result(_core.stitch(_source(vertices, faces), options, _progress(progress)))


def remove_slivers(vertices, faces=None, *, shape_factor=0.7, feature_angle=135.0,
                   edge_length=None, progress=None):
    """Removes sliver triangles (shape factor below ``shape_factor``) by node merging and edge
    swapping, keeping edges whose faces meet at less than ``feature_angle`` degrees
    (``mesh_repair slivers``). Returns a ``Result``; the report holds ``slivers``."""
    options = {
        "shape_factor": _number("shape_factor", shape_factor, 0, 1),
        "feature_angle": _number("feature_angle", feature_angle, 0, 180),
        "edge_length": -1.0 if edge_length is None else _number("edge_length", edge_length, 0),
    }
    return _result(_core.remove_slivers(_source(vertices, faces), options, _progress(progress)))


def optimize(vertices, faces=None, *, mode="reduction", target_ratio=None, target_faces=None,
             max_deviation=None, feature_angle=135.0, min_angle=15.0, seed=0, progress=None):
    """GA mesh reduction or quality improvement keeping features (``mesh_repair optimize``).
    ``mode`` "reduction" (to ``target_faces``, or ``target_ratio`` x the faces, default 0.5, or
    while the normal deviation stays below ``max_deviation``) or "quality". Returns a
    ``Result``; the report holds ``optimization``, ``quality_before`` and ``quality_after``."""
    if mode not in ("reduction", "quality"):
        raise ValueError(f"mode must be reduction or quality, got {mode!r}")
    if target_ratio is not None and target_faces is not None:
        raise ValueError("give target_ratio or target_faces, not both")
    options = {
        "mode": mode,
        "feature_angle": _number("feature_angle", feature_angle, 0, 180),
        "min_angle": _number("min_angle", min_angle, 0, 60),
        "seed": _number("seed", seed, 0, 2**32 - 1, integer=True),
    }
    if target_ratio is not None:
        options["target_ratio"] = _number("target_ratio", target_ratio, 0, 1)
    if target_faces is not None:
        options["target_faces"] = _number("target_faces", target_faces, 0, integer=True)
    if max_deviation is not None:
        options["max_deviation"] = _number("max_deviation", max_deviation, 0)
    return _result(_core.optimize(_source(vertices, faces), options, _progress(progress)))


def suppress_feature(vertices, faces=None, *, faces_to_remove, method="shape_prediction", seed=0,
                     progress=None):
    """Feature suppression by hole repair (``mesh_repair suppress``, thesis 6.1): removes the
    faces ``faces_to_remove`` (indices into the faces, e.g. from ``faces_in_sphere``) and fills
    every hole this opens with ``method`` (shape prediction by default). Returns a ``Result``;
    the report holds ``removed_faces`` and one entry per opened hole."""
    import numpy as np

    indices = np.asarray(faces_to_remove)
    if indices.dtype.kind not in "iu" or indices.ndim != 1:
        raise ValueError("faces_to_remove must be a 1-D sequence of face indices")
    options = {
        "faces": [int(i) for i in indices],
        "method": _method("method", method),
        "seed": _number("seed", seed, 0, 2**32 - 1, integer=True),
    }
    return _result(_core.suppress_feature(_source(vertices, faces), options, _progress(progress)))


def smooth(vertices, faces=None, *, method="mga", quads=False, iterations=None, seed=0, threads=1,
           generations=3, feature_angle=120.0, tangent_scale=0.45, slide_feature_nodes=False,
           progress=None):
    """Node smoothing (``mesh_repair smooth``): ``method`` "mga" (micro-GA on a G1 surface
    rebuilt from the mesh, Chen et al.), "cg" (the paper's conjugate-gradient baseline) or
    "cgal" (CGAL's angle_and_area_smoothing then tangential_relaxation, triangles only).
    ``quads=True`` converts to quads first (the faces are then a list of polygons when
    triangles remain). ``iterations``: sweeps (default 3, 1 for cgal); ``generations``: micro-GA
    generations (CG iterations) per node and sweep; edges sharper than ``feature_angle``
    degrees hold their nodes fixed (``slide_feature_nodes=True``: they slide along the line);
    ``tangent_scale`` in [0, 1] scales the G1 surface's tangents (0 = the input triangles).
    Returns a ``Result``; the report holds ``quality_before``, ``quality_after`` (worst and mean
    alpha, beta for quads), ``max_distance_to_input`` and the smoothing counts."""
    if method not in SMOOTHING_METHODS:
        raise ValueError(f"method must be mga, cg or cgal, got {method!r}")
    if quads and method == "cgal":
        raise ValueError("CGAL's smoothing works on triangles only; drop quads")
    options = {
        "method": method,
        "quads": bool(quads),
        "seed": _number("seed", seed, 0, _SEED_MAX, integer=True),
        "threads": _number("threads", threads, 1, 1024, integer=True),
        "generations": _number("generations", generations, 1, _INT_MAX, integer=True),
        "feature_angle": _number("feature_angle", feature_angle, 0, 180),
        "tangent_scale": _number("tangent_scale", tangent_scale, 0, 1),
        "slide_feature_nodes": bool(slide_feature_nodes),
    }
    if iterations is not None:
        options["iterations"] = _number("iterations", iterations, 0, _INT_MAX, integer=True)
    return _result(_core.smooth(_source(vertices, faces), options, _progress(progress)))


def mesh_points(points, *, quads=False, smooth=True, iterations=3, seed=0, threads=0,
                feature_angle=120.0, progress=None):
    """Meshes a point cloud (``mesh_repair mesh-points``): CGAL's advancing-front surface
    reconstruction, quality edge flips, optional conversion to quads (``quads``), then
    ``iterations`` micro-GA sweeps on the G1 surface through the points (``smooth=False``: none).
    ``points``: a float array of shape (n, 3), n >= 3, or the path of a point file (XYZ or
    PWN, or the vertices of OFF, OBJ, STL, PLY). ``threads`` 0 = all cores. Returns a ``Result``; the report holds
    ``points``, ``edge_flips``, ``quads`` and the quality before and after the smoothing."""
    options = {
        "quads": bool(quads),
        "smooth": bool(smooth),
        "iterations": _number("iterations", iterations, 0, _INT_MAX, integer=True),
        "seed": _number("seed", seed, 0, _SEED_MAX, integer=True),
        "threads": _number("threads", threads, 0, 1024, integer=True),
        "feature_angle": _number("feature_angle", feature_angle, 0, 180),
    }
    return _result(_core.mesh_points(_points_source(points), options, _progress(progress)))


def bench_holes(vertices, faces=None, *, holes=1, radius=0.05, seeds=1, methods="liepa",
                shape="disc", progress=None):
    """The hole-filling benchmark (``mesh_repair bench holes``) on one closed mesh: for each
    ``radius`` (fraction of the bounding-box diagonal, in (0, 0.5); one or a list) and each of
    ``seeds`` (one or a list), punches ``holes`` holes of ``shape`` (one of ``HOLE_SHAPES``),
    fills them with each of ``methods`` (names of ``BENCH_METHODS``, a list or a comma-separated
    string, ``"all"``) and measures every fill against the removed faces. The mesh must be
    closed (``ValueError`` otherwise); it is not modified. Returns the report dict (no mesh):
    ``input``, ``methods``, ``results`` (one dict per hole x method x radius x seed, the keys of
    a line of the tool's ``results.jsonl``: E1/E2/Einf, Hausdorff, normal deviation, quality,
    closedness, time...) and ``shortfalls`` (radius and seed where fewer holes fit, and why)."""
    if shape not in HOLE_SHAPES:
        raise ValueError(f"shape expects disc, jagged, elongated or ring, got {shape!r}")
    options = {
        "holes": _number("holes", holes, 1, _INT_MAX, integer=True),
        "radius": _list("radius", radius, _radius),
        "seeds": _list("seeds", seeds,
                       lambda s: _number("seeds", s, 0, _SEED_MAX, integer=True)),
        "methods": _bench_methods(methods),
        "shape": shape,
    }
    return _result(_core.bench_holes(_source(vertices, faces), options,
                                     _progress(progress))).report


def _centroids(vertices, faces):
    import numpy as np

    return np.asarray(vertices, float)[np.asarray(faces)].mean(axis=1)


def faces_in_sphere(vertices, faces, centre, radius):
    """Indices of the triangles whose centroid lies in the ball (``suppress --sphere``)."""
    import numpy as np

    distance = np.linalg.norm(_centroids(vertices, faces) - np.asarray(centre, float), axis=1)
    return np.flatnonzero(distance <= radius)


def faces_in_box(vertices, faces, low, high):
    """Indices of the triangles whose centroid lies in the axis-aligned box (``--box``)."""
    import numpy as np

    c = _centroids(vertices, faces)
    return np.flatnonzero(np.all((c >= np.asarray(low, float)) & (c <= np.asarray(high, float)),
                                 axis=1))
