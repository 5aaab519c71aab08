#!/usr/bin/env python3
"""The library's layers point one way: no file under libvorocrust/src includes a file of a later
stage of the pipeline.

The stages in order (a folder may include its own files and those of every folder before it):
core and options (the vocabulary: meshes, errors, the option table), geometry (predicates, trees,
spheres), io (read, validate, write the inputs, balls and seeds), regions, arrangement (cutting
self-intersections), info, features (2.2), refinement (2.3), seeds (2.4), interior (2.5), cells,
clipping (the clipped methods, which cut the cells to the input), quality, export, report, mesher
(the pipeline and the job). A public header (vorocrust/*.hpp) counts as the stage that implements
it; one that declares data types only counts as core.

Usage: check_layers.py LIBVOROCRUST_DIR. Prints every include that points the wrong way and
exits 1 when there is one.
"""
import os
import re
import sys

ORDER = ["core", "options", "geometry", "io", "regions", "arrangement", "info", "features", "refinement",
         "seeds", "interior", "cells", "clipping", "quality", "export", "report", "mesher"]
RANK = {stage: rank for rank, stage in enumerate(ORDER)}
RANK["options"] = RANK["core"]  # the option table is vocabulary, as the core types are

# Public headers that declare a stage's functions, by the stage implementing them; every other
# public header holds data types (and their small inline helpers) and counts as core.
PUBLIC = {
    "read_mesh.hpp": "io", "validate.hpp": "io", "write_mesh.hpp": "io", "merge_surfaces.hpp": "io",
    "surface_from_arrays.hpp": "io", "regions.hpp": "regions", "resolve_self_intersections.hpp": "arrangement",
    "quality.hpp": "quality", "cell_quality.hpp": "quality", "method_figures.hpp": "quality",
    "face_orthogonality.hpp": "quality", "face_skewness.hpp": "quality", "write_vtu.hpp": "export",
    "write_openfoam.hpp": "export", "write_tough.hpp": "export", "write_pflotran.hpp": "export",
    "write_volume_mesh.hpp": "export", "quality_svg.hpp": "report", "report.hpp": "report",
    "report_html.hpp": "report",
    "mesh_result.hpp": "mesher", "mesher.hpp": "mesher", "job.hpp": "mesher", "compare.hpp": "mesher", "vorocrust.hpp": "mesher",
}

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def stage_of_include(path):
    parts = path.split("/")
    if parts[0] == "vorocrust":
        return PUBLIC.get(parts[1], "core")
    return parts[0] if parts[0] in RANK else None


def main():
    root = sys.argv[1]
    src = os.path.join(root, "src")
    wrong = []
    folders = set()
    for folder, _, files in os.walk(src):
        if folder == src:
            continue
        stage = os.path.relpath(folder, src).split(os.sep)[0]
        folders.add(stage)
        for name in files:
            if not name.endswith((".cpp", ".hpp")):
                continue
            path = os.path.join(folder, name)
            with open(path) as f:
                for included in INCLUDE.findall(f.read()):
                    target = stage_of_include(included)
                    if target is not None and RANK[target] > RANK[stage]:
                        wrong.append(f"{os.path.relpath(path, root)}: includes {included} ({target} comes after {stage})")
    unknown = sorted(folders - set(RANK))
    for line in wrong:
        print(line)
    if unknown:
        print("folders of no known stage: " + ", ".join(unknown))
    print(f"{len(wrong)} includes point to a later stage" if wrong else "every include points to its own stage or an earlier one")
    return 1 if wrong or unknown else 0


if __name__ == "__main__":
    sys.exit(main())
