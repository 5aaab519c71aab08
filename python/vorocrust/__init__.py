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

import inspect
import os
import textwrap

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
    OPTIONS,
    PLANE_FORMATS,
    PLANE_OPTIONS,
    PlaneMesh,
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
    write_exodus,
    read_exodus,
    write_seeds,
    write_surface,
    write_tough,
    write_tets,
    write_vtu,
)
from . import _vorocrust

__all__ = [
    "Balls", "Cancelled", "Cells", "Error", "InternalError", "InvalidGeometryError", "MeshResult",
    "NotYetImplementedError", "OutputError", "Seeds", "Surface", "UnreadableInputError", "UsageError",
    "__version__", "DEFAULT_OPTIONS", "OPTIONS", "compute_cells", "info", "measure_surface_quality", "merge_surfaces", "mesh",
    "read_exodus", "read_mesh", "read_seeds", "validate", "write_balls", "write_openfoam", "write_exodus", "write_outputs", "write_pflotran",
    "write_tough",
    "write_files", "write_seeds", "write_surface", "write_tets", "write_vtu", "OUTPUT_FORMATS", "VOLUME_FORMATS",
    "INTERIOR_MODES", "STAGES", "mesh2d", "PlaneMesh", "PLANE_OPTIONS", "PLANE_FORMATS",
]

#: OPTIONS: every option of mesh(), from the library's one table of options: a dict each with its
#: name, kind, label, help, the paper's section, unit, default (None: unset, see default_text),
#: range (min, max, min_open, max_open, also) or choices, and how each front end spells it.
_OPTION = {o["name"]: o for o in OPTIONS}
#: The library's default of each option; None where the default is unset (it follows `smooth`,
#: or means "none", as OPTIONS[...]["default_text"] says).
DEFAULT_OPTIONS = {o["name"]: o["default"] for o in OPTIONS if "python" in o["front_ends"]}
#: What a run can stop after, in pipeline order.
STAGES = tuple(_OPTION["stop_after"]["choices"])
#: How the volume away from the surface is seeded (paper 2.5).
INTERIOR_MODES = tuple(_OPTION["interior"]["choices"])

#: What write_outputs() can write, with the files each one makes in the output folder.
OUTPUT_FORMATS = {name: files for name, files, _, _, _ in _vorocrust._OUTPUT_TABLE}
OUTPUT_FORMATS["report"] = ("report.json",)


def _option_doc(o):
    text = "%s: %s" % (o["name"], o["help"])
    if o["section"]:
        text += " (paper %s)" % o["section"]
    text += ". %s%s." % (o["default_text"][0].upper() + o["default_text"][1:],
                         "" if o["kind"] == "flag" else "; range: " + o["range_text"])
    return textwrap.fill(text, 96, initial_indent="    ", subsequent_indent="        ")


def mesh(model, *, output_dir=None, progress=None, **options):
    return _vorocrust._mesh(model, options, output_dir, progress)


mesh.__signature__ = inspect.Signature(
    [inspect.Parameter("model", inspect.Parameter.POSITIONAL_OR_KEYWORD)]
    + [inspect.Parameter(o["name"], inspect.Parameter.KEYWORD_ONLY, default=o["default"])
       for o in OPTIONS if "python" in o["front_ends"]]
    + [inspect.Parameter(name, inspect.Parameter.KEYWORD_ONLY, default=None) for name in ("output_dir", "progress")])
mesh.__doc__ = """Meshes a model as `vorocrust mesh` does. Returns a MeshResult.

model: a file path, a list of paths (merged into one model, one group per file), a Surface, or
    a (vertices, triangles) pair of arrays (n x 3 numbers, m x 3 indices).
output_dir: a folder to write the outputs into (made when missing), as `vorocrust mesh -o`
    does: the formats of `formats` the run reached, and report.json. None: nothing is written.
progress: a callable progress(phase, fraction) with phase a str and fraction in [0, 1] or None
    when unknown, called at each new phase and at most every 50 ms within one. Return False
    (any false value but None) to cancel the run: it raises Cancelled and writes nothing (an
    output folder keeps what it held, and gets report.json saying so). An exception the
    callback raises stops the run and propagates.

The options (OPTIONS holds them as data; None leaves an option at its default):
""" + "\n".join(_option_doc(o) for o in OPTIONS if "python" in o["front_ends"]) + """

The input is validated first, its orientation fixed; a finding of severity "error" raises
InvalidGeometryError with its message. The run releases the GIL (other Python threads go on)
and answers Ctrl-C. Raises UsageError for an unknown option or a value out of range (naming the
option), UnreadableInputError / InvalidGeometryError for bad models (naming file and line).
"""


#: The formats written from the cells (the volume mesh), by name in OUTPUT_FORMATS.
VOLUME_FORMATS = tuple(name for name, _, _, volume, _ in _vorocrust._OUTPUT_TABLE if volume)

# The part of a run each format is written from.
_FORMAT_PARTS = {"balls": "balls", "seeds": "seeds", "obj": "surface", "ply": "surface", "svg": "run",
                 "html": "run", "report": "run", "vtu": "cells", "openfoam": "cells", "tough": "cells", "pflotran": "cells",
                 "exodus": "cells", "tets": "cells"}


def mesh2d(domain, *, output_dir=None, formats=None, thickness=1.0, **options):
    return _vorocrust._mesh2d(domain, options, output_dir, formats, float(thickness))


mesh2d.__signature__ = inspect.Signature(
    [inspect.Parameter("domain", inspect.Parameter.POSITIONAL_OR_KEYWORD)]
    + [inspect.Parameter(o["name"], inspect.Parameter.KEYWORD_ONLY, default=o["default"])
       for o in OPTIONS if o["name"] in PLANE_OPTIONS]
    + [inspect.Parameter("output_dir", inspect.Parameter.KEYWORD_ONLY, default=None),
       inspect.Parameter("formats", inspect.Parameter.KEYWORD_ONLY, default=None),
       inspect.Parameter("thickness", inspect.Parameter.KEYWORD_ONLY, default=1.0)])
mesh2d.__doc__ = """Meshes a 2D domain as `vorocrust mesh2d` does (paper 2.6). Returns a PlaneMesh.

domain: a .poly file (Triangle's: vertices, segments, holes, regional attributes), an .obj file
    of polylines (l elements), or a dict of arrays: "points" (n x 2), "segments" (m x 2 indices
    from 0), and optionally "holes" (k x 2) and "regions" ([(x, y, label), ...]). Open segments
    inside a region are breaklines: cell edges follow them, both sides keep the region.
output_dir: a folder to write into (made when missing), with report.json. None: nothing written.
formats: what to write there, of PLANE_FORMATS (None: all): vtu (mesh.vtu, polygons), svg
    (mesh.svg), openfoam (case/, one cell thick), tough (MESH), pflotran, exodus, seeds.
thickness: the thickness of the one-cell slab the OpenFOAM, TOUGH, PFLOTRAN and Exodus files hold.

The options, those of mesh() that a 2D run takes (None leaves one at its default):
""" + "\n".join(_option_doc(o) for o in OPTIONS if o["name"] in PLANE_OPTIONS) + """

Raises UsageError naming an unknown option or a value out of range, UnreadableInputError and
InvalidGeometryError naming the file, line or place (open boundaries, crossing or repeated
segments that cannot be split, features closer than the circles can resolve).
"""


def write_files(folder, formats, *, run=None, balls=None, seeds=None, surface=None, cells=None):
    """Writes the given parts into `folder` (created when missing) under the names
    `vorocrust mesh` uses: the building block of write_outputs(), for parts that come from
    elsewhere (seeds read back from a seeds.csv, cells from compute_cells()).

    formats: names from OUTPUT_FORMATS, each needing its part: "balls" balls, "seeds" seeds,
        "obj" and "ply" surface, "svg", "html" and "report" run (a MeshResult), "vtu", "openfoam",
        "tough", "pflotran", "exodus" and "tets" (for clipped cells) cells. A format whose part is missing raises UsageError before anything is written.

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
        "balls": lambda: _write_balls(folder, balls, run),
        "seeds": lambda: write_seeds(seeds, _at(folder, "seeds.csv")),
        "obj": lambda: write_surface(surface, _at(folder, "surface.obj")),
        "ply": lambda: write_surface(surface, _at(folder, "surface.ply")),
        "svg": lambda: run.write_quality_svg(_at(folder, "quality.svg")),
        "html": lambda: run.write_report_html(_at(folder, "report.html")),
        "report": lambda: run.write_report(_at(folder, "report.json")),
        "vtu": lambda: write_vtu(cells, _at(folder, "mesh.vtu")),
        "openfoam": lambda: write_openfoam(cells, _at(folder, "case")),
        "tough": lambda: write_tough(cells, _at(folder, "MESH")),
        "pflotran": lambda: write_pflotran(cells, _at(folder, "pflotran")),
        "exodus": lambda: write_exodus(cells, _at(folder, "mesh.exo")),
        "tets": lambda: write_tets(cells, _at(folder, "tets.vtu")),
    }
    written = []
    for name in formats:
        writers[name]()
        written += [_at(folder, f) for f in OUTPUT_FORMATS[name] if os.path.exists(_at(folder, f))]
    return written


def _write_balls(folder, balls, run):
    write_balls(balls, _at(folder, "balls.csv"))
    write_balls(balls, _at(folder, "balls.vtk"))
    # The surface the balls cover, when smoothing changed it, as `vorocrust mesh` writes it.
    smoothed = _at(folder, "smoothed_surface.ply")
    if run is not None and run.report()["features"]["smoothing_iterations"] > 0:
        write_surface(run.smoothed_input, smoothed)
    elif os.path.exists(smoothed):
        os.remove(smoothed)


def write_outputs(result, folder, formats=None, cells=None):
    """Writes a run's results into `folder` (created when missing), as `vorocrust mesh` does.

    formats: names from OUTPUT_FORMATS ("balls", "seeds", "obj", "ply", "svg", "html", "report",
        "vtu", "openfoam", "tough", "pflotran", "exodus", "tets"); None for every one the run has the parts for
        ("tets" is written for a clipped run only). Asking for a part the
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
    # The dual tetrahedra belong to a clipped mesh: as `vorocrust mesh`, a VoroCrust run writes none.
    if result.report()["options"].get("method") != "clipped":
        formats = [name for name in formats if name != "tets"]
    return write_files(folder, formats, **parts)


def _at(folder, name):
    return os.path.join(os.fspath(folder), name)

