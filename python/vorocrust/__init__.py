"""VoroCrust for Python: conforming Voronoi meshing without clipping.

A thin layer over libvorocrust (C++): every figure comes from the library, and arrays are
NumPy arrays. The usual run::

    import vorocrust
    result = vorocrust.mesh("model.off", max_size=0.5, seed=7, progress=print)
    result.surface.vertices, result.surface.triangles, result.surface.regions
    result.seeds.positions, result.seeds.labels
    vorocrust.write_outputs(result, "out")          # the files `vorocrust mesh` writes

Models are files (OFF, OBJ, STL, PLY), a Surface, or (vertices, triangles) arrays. Failures
raise vorocrust.Error subclasses carrying the library's message; a progress callback that
returns False cancels a run with vorocrust.Cancelled, and nothing is written.
"""

import math
import os

from ._vorocrust import (  # noqa: F401  (the public interface)
    Balls,
    Cancelled,
    Cells,
    Error,
    InternalError,
    InvalidGeometryError,
    MeshResult,
    NotYetImplementedError,
    OutputError,
    Seeds,
    Surface,
    UnreadableInputError,
    DEFAULT_OPTIONS,
    UsageError,
    __version__,
    compute_cells,
    info,
    measure_surface_quality,
    merge_surfaces,
    read_mesh,
    read_seeds,
    validate,
    write_balls,
    write_openfoam,
    write_pflotran,
    write_seeds,
    write_surface,
    write_tough,
    write_vtu,
)
from . import _vorocrust

__all__ = [
    "Balls", "Cancelled", "Cells", "Error", "InternalError", "InvalidGeometryError", "MeshResult",
    "NotYetImplementedError", "OutputError", "Seeds", "Surface", "UnreadableInputError", "UsageError",
    "__version__", "DEFAULT_OPTIONS", "compute_cells", "info", "measure_surface_quality", "merge_surfaces", "mesh",
    "read_mesh", "read_seeds", "validate", "write_balls", "write_openfoam", "write_outputs", "write_pflotran",
    "write_tough",
    "write_files", "write_seeds", "write_surface", "write_vtu", "OUTPUT_FORMATS", "VOLUME_FORMATS",
    "INTERIOR_MODES", "STAGES",
]

#: What a run can stop after, in pipeline order.
STAGES = ("balls", "surface", "cells")
#: How the volume away from the surface is seeded (paper 2.5).
INTERIOR_MODES = ("random", "lattice", "cvt")
#: DEFAULT_OPTIONS: the library's default for each option of mesh() (from the extension).

#: What write_outputs() can write, with the files each one makes in the output folder.
OUTPUT_FORMATS = {
    "balls": ("balls.csv", "balls.vtk"),
    "seeds": ("seeds.csv",),
    "obj": ("surface.obj",),
    "ply": ("surface.ply",),
    "svg": ("quality.svg",),
    "report": ("report.json",),
    "vtu": ("mesh.vtu",),
    "openfoam": ("case",),
    "tough": ("MESH",),
    "pflotran": ("pflotran",),
}


def mesh(model, *, lipschitz=DEFAULT_OPTIONS["lipschitz"], smooth=DEFAULT_OPTIONS["smooth"], sharp_angle=None,
         max_size=None, sizing=None, smoothing_iterations=None,
         smoothing_tolerance=DEFAULT_OPTIONS["smoothing_tolerance"], min_triangle_angle=None,
         interior=DEFAULT_OPTIONS["interior"], cvt_iterations=DEFAULT_OPTIONS["cvt_iterations"],
         max_aspect_ratio=DEFAULT_OPTIONS["max_aspect_ratio"], stop_after=DEFAULT_OPTIONS["stop_after"], seed=DEFAULT_OPTIONS["seed"], threads=DEFAULT_OPTIONS["threads"],
         self_intersections=DEFAULT_OPTIONS["self_intersections"], box=None, progress=None):
    """Meshes a model: `vorocrust mesh` without the files. Returns a MeshResult.

    model: a file path, a list of paths (merged into one model, one group per file), a
        Surface, or a (vertices, triangles) pair of arrays (n x 3 numbers, m x 3 indices).
    lipschitz: L in (0, 1), how fast ball radii may vary (CLI --lipschitz).
    smooth: the model approximates a smooth surface (a scan, a coarse tessellation of a curved
        shape): it is smoothed as one patch and its features are found on the result, so the
        folds of its tessellation are not creases (--smooth).
    sharp_angle: normal deviation in degrees (0, 90) above which an edge is a sharp crease
        (--sharp-angle); None: DEFAULT_OPTIONS["sharp_angle"], or ["smooth_sharp_angle"] when smooth.
    max_size: largest ball radius and cell size, None for no bound (--max-size).
    sizing: a sizing file of lines "x y z size", interpolated (--sizing).
    smoothing_iterations: rounds of adaptive Loop subdivision inside smooth patches; None: none,
        or DEFAULT_OPTIONS["smooth_smoothing_iterations"] when smooth.
    smoothing_tolerance: how far smoothing should move the surface at most, as a fraction of the
        input's bounding-box diagonal (a target, not a bound): the faces around a vertex that
        Loop's rules would move farther are first split at their edge midpoints, at most twice; 0
        for Loop's rules alone (--smoothing-tolerance).
    min_triangle_angle: surface triangles away from features with an angle below this many
        degrees (0 to 30) are split by shrinking the balls that cover their circumcentres
        (--min-triangle-angle); None: DEFAULT_OPTIONS["min_triangle_angle"] (0, none), or
        ["smooth_min_triangle_angle"] (30) when smooth.
    interior: how the volume is seeded: "random", "lattice" or "cvt" (paper 2.5).
    cvt_iterations: Lloyd iterations of interior="cvt".
    max_aspect_ratio: cells whose aspect ratio (enclosing sphere over inscribed ball) exceeds this
        get a seed at their centroid, for at most 2 rounds; 0 for none, else at least 3
        (--max-aspect-ratio).
    stop_after: "balls", "surface" or "cells" (the whole mesh).
    seed: random seed; equal model, options and seed give equal results.
    threads: worker threads, 0 for all cores; results do not depend on it.
    self_intersections: faces that cut through each other: "resolve" cuts them along their
        intersection curves, which become creases, each new piece of space joining a region of
        the input; "refuse" raises InvalidGeometryError naming them; "keep" meshes them as they
        are (--self-intersections).
    box: (xmin, ymin, zmin, xmax, ymax, zmax), the domain around open sheets (--box): its sides
        join the surface and what no material fills inside it becomes the material "domain".
        None: a model with open edges gets its bounding box grown by a tenth of its diagonal on
        every side, a closed model no box.
    progress: a callable progress(phase, fraction) with phase a str and fraction in [0, 1] or
        None when unknown, called at each new phase and at most every 50 ms within one. Return
        False (any false value but None) to cancel the run: it raises Cancelled and has
        written nothing. An exception the callback raises stops the run and propagates.

    The input is validated first, its orientation fixed; a finding of severity "error" raises
    InvalidGeometryError with its message. The run releases the GIL (other Python threads go
    on) and answers Ctrl-C. Raises UsageError for options out of range, UnreadableInputError /
    InvalidGeometryError for bad models (naming file and line), NotYetImplementedError for a
    stage this version of the library does not have.
    """
    return _vorocrust._mesh(
        model, lipschitz=float(lipschitz), smooth=bool(smooth),
        sharp_angle=None if sharp_angle is None else float(sharp_angle),
        max_size=None if max_size is None or math.isinf(max_size) else float(max_size), sizing=sizing,
        smoothing_iterations=None if smoothing_iterations is None else int(smoothing_iterations),
        smoothing_tolerance=float(smoothing_tolerance),
        min_triangle_angle=None if min_triangle_angle is None else float(min_triangle_angle),
        interior=interior,
        cvt_iterations=int(cvt_iterations), max_aspect_ratio=float(max_aspect_ratio), stop_after=stop_after, seed=int(seed), threads=int(threads),
        self_intersections=self_intersections,
        box=None if box is None else tuple(float(x) for x in box), progress=progress)


#: The formats written from the cells (the volume mesh), by name in OUTPUT_FORMATS.
VOLUME_FORMATS = ("vtu", "openfoam", "tough", "pflotran")

# The part of a run each format is written from.
_FORMAT_PARTS = {"balls": "balls", "seeds": "seeds", "obj": "surface", "ply": "surface", "svg": "run",
                 "report": "run", "vtu": "cells", "openfoam": "cells", "tough": "cells", "pflotran": "cells"}


def write_files(folder, formats, *, run=None, balls=None, seeds=None, surface=None, cells=None):
    """Writes the given parts into `folder` (created when missing) under the names
    `vorocrust mesh` uses: the building block of write_outputs(), for parts that come from
    elsewhere (seeds read back from a seeds.csv, cells from compute_cells()).

    formats: names from OUTPUT_FORMATS, each needing its part: "balls" balls, "seeds" seeds,
        "obj" and "ply" surface, "svg" and "report" run (a MeshResult), "vtu", "openfoam",
        "tough" and "pflotran" cells. A format whose part is missing raises UsageError before anything is written.

    Every file is written atomically. Returns the paths written, in the order of `formats`.
    """
    parts = {"run": run, "balls": balls, "seeds": seeds, "surface": surface, "cells": cells}
    formats = list(formats)
    for name in formats:
        if name not in OUTPUT_FORMATS:
            raise UsageError("unknown output format %r: expected one of %s" % (name, ", ".join(OUTPUT_FORMATS)))
        if parts[_FORMAT_PARTS[name]] is None:
            stage = " (the run stopped after %s)" % run.stop_after if run is not None else ""
            raise UsageError("nothing to write as %r: no %s%s" % (name, _FORMAT_PARTS[name], stage))
    os.makedirs(folder, exist_ok=True)
    writers = {
        "balls": lambda: (write_balls(balls, _at(folder, "balls.csv")), write_balls(balls, _at(folder, "balls.vtk"))),
        "seeds": lambda: write_seeds(seeds, _at(folder, "seeds.csv")),
        "obj": lambda: write_surface(surface, _at(folder, "surface.obj")),
        "ply": lambda: write_surface(surface, _at(folder, "surface.ply")),
        "svg": lambda: run.write_quality_svg(_at(folder, "quality.svg")),
        "report": lambda: run.write_report(_at(folder, "report.json")),
        "vtu": lambda: write_vtu(cells, _at(folder, "mesh.vtu")),
        "openfoam": lambda: write_openfoam(cells, _at(folder, "case")),
        "tough": lambda: write_tough(cells, _at(folder, "MESH")),
        "pflotran": lambda: write_pflotran(cells, _at(folder, "pflotran")),
    }
    written = []
    for name in formats:
        writers[name]()
        written += [_at(folder, f) for f in OUTPUT_FORMATS[name]]
    return written


def write_outputs(result, folder, formats=None, cells=None):
    """Writes a run's results into `folder` (created when missing), as `vorocrust mesh` does.

    formats: names from OUTPUT_FORMATS ("balls", "seeds", "obj", "ply", "svg", "report",
        "vtu", "openfoam", "tough", "pflotran"); None for every one the run has the parts for. Asking for a part the
        run did not make (cells after stop_after="surface") raises UsageError and writes
        nothing.
    cells: the Cells to write the volume formats from, instead of result.cells: e.g.
        compute_cells(result.seeds) for a run that stopped after the surface.

    Every file is written atomically (a temporary file renamed into place). Returns the paths
    written, in the order of `formats`.
    """
    parts = {"run": result, "balls": result.balls, "seeds": result.seeds, "surface": result.surface,
             "cells": result.cells if cells is None else cells}
    if formats is None:
        formats = [name for name in OUTPUT_FORMATS if parts[_FORMAT_PARTS[name]] is not None]
    return write_files(folder, formats, **parts)


def _at(folder, name):
    return os.path.join(os.fspath(folder), name)

