#!/usr/bin/env python3
"""Meshing a model from Python with the `vorocrust` module.

    PYTHONPATH=build/python /usr/bin/python3 samples/python_example.py [MODEL] [OUTDIR]

(after `cmake --install`, no PYTHONPATH is needed). MODEL defaults to samples/cgal_joint.off,
OUTDIR to ./python_example_out. Ctrl-C cancels the run cleanly; so would a progress callback
returning False.
"""
import os
import sys
import time

import numpy as np

import vorocrust

here = os.path.dirname(os.path.abspath(__file__))
model = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "cgal_joint.off")
out = sys.argv[2] if len(sys.argv) > 2 else "python_example_out"

# The model: read, described and validated as `vorocrust info` does.
surface = vorocrust.read_mesh(model)
info = vorocrust.info(surface)
print("%s: %d vertices, %d triangles, genus %s" % (model, surface.num_vertices, surface.num_faces, info["genus"]))

# How far to go: "cells" is the whole mesh; with "surface" the cells below are built from the
# surface seeds alone, as `vorocrust cells seeds.csv` builds them.
STOP_AFTER = "cells"

# Progress: one line per stage ("refinement: patches, pass 3" counts as "refinement: patches").
start = time.monotonic()
last = [None]


def progress(phase, fraction):
    stage = phase.split(",")[0]
    if stage != last[0]:
        print("  %6.2f s  %s" % (time.monotonic() - start, stage))
        last[0] = stage
    return True  # False would cancel: mesh() then raises vorocrust.Cancelled


result = vorocrust.mesh(model, seed=7, stop_after=STOP_AFTER, progress=progress)

seeds, out_surface = result.seeds, result.surface
kinds = list(seeds.kinds)
print("seeds: %d surface, %d interior, %d outside; %d in the material; surface: %d triangles" % (
    kinds.count("surface"), kinds.count("interior"), kinds.count("outside"), (seeds.labels > 0).sum(),
    out_surface.num_faces))
q = result.surface_quality
print("surface quality: min angle %.1f deg, Q min %.3f, Hausdorff %.3f %% of the diagonal, topology %s" % (
    q["angles"]["min_degrees"], q["triangle_quality"]["min"], q["hausdorff"]["percent_of_bounding_box_diagonal"],
    "as the input's" if q["topology"]["matches"] else "differs"))

# The cells: from the run, or built from its seeds as `vorocrust cells seeds.csv` does.
cells = result.cells if result.cells is not None else vorocrust.compute_cells(seeds)
volume = sum(info["shell_volumes"])
print("cells: %d, %d faces, %d points; volume %.6g (the input encloses %.6g)" % (
    cells.num_cells, cells.num_faces, cells.num_points, cells.volumes.sum(), volume))
sizes = np.diff(cells.cell_face_offsets)
print("faces per cell: min %d, mean %.1f, max %d" % (sizes.min(), sizes.mean(), sizes.max()))

# Files: what `vorocrust mesh` writes, the volume mesh from these cells.
written = vorocrust.write_outputs(result, out, cells=cells)
print("wrote " + ", ".join(sorted(os.path.basename(p) for p in written)))
