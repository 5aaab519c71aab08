"""The volume mesh as outside tools read it (VTK's reader, OpenFOAM's checkMesh), shared by the
Python tests."""
import os
import re
import shutil
import subprocess

import numpy
import vtk  # VTK's Python modules, from python3-paraview
from vtk.util.numpy_support import vtk_to_numpy

from vtk_volume import vtk_boundary_volume  # noqa: F401  (one import for the tests)

CHECKMESH = shutil.which("checkMesh") or "/usr/bin/checkMesh"


def read_vtu(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def cell_array(grid, name):
    return vtk_to_numpy(grid.GetCellData().GetArray(name)).tolist()


def vtk_cell_volumes(grid):
    f = vtk.vtkCellSizeFilter()
    f.SetInputData(grid)
    f.ComputeVolumeOn()
    f.Update()
    return cell_array(f.GetOutput(), "Volume")


def all_polyhedron_faces(grid):
    """The polygons of every polyhedron cell of a VTK grid: a list per cell of tuples of point ids,
    from the grid's face stream read at once (asking VTK cell by cell takes most of a test's time
    on a mesh of 10^5 cells)."""
    stream = vtk_to_numpy(grid.GetFaces()).tolist()
    cells = []
    for at in vtk_to_numpy(grid.GetFaceLocations()).tolist():
        faces, i = [], at + 1
        for _ in range(stream[at]):
            n = stream[i]
            faces.append(tuple(stream[i + 1:i + 1 + n]))
            i += n + 1
        cells.append(faces)
    return cells


def check_mesh(case):
    env = dict(os.environ, WM_PROJECT_DIR="/usr/share/openfoam")
    r = subprocess.run([CHECKMESH, "-case", case], capture_output=True, text=True, timeout=600, env=env)
    m = re.search(r"Mesh non-orthogonality Max: (\S+) average: (\S+)", r.stdout)
    return r, (float(m.group(1)), float(m.group(2))) if m else None


def read_obj_triangles(path):
    """The triangles of an OBJ file, each as three (x, y, z) tuples."""
    vertices, triangles = [], []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if parts and parts[0] == "v":
                vertices.append(tuple(float(x) for x in parts[1:4]))
            elif parts and parts[0] == "f":
                triangles.append(tuple(vertices[int(p.split("/")[0]) - 1] for p in parts[1:4]))
    return triangles


def obj_enclosed_volume(path):
    """The volume a closed OBJ triangle surface encloses, by the divergence theorem."""
    volume = 0.0
    for a, b, c in read_obj_triangles(path):
        volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                   + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6
    return abs(volume)


def read_seed_positions(path):
    """The seeds of a seeds.csv, as (x, y, z) tuples in file order."""
    with open(path) as f:
        return [tuple(float(x) for x in line.split(",")[:3]) for line in f.readlines()[1:]]


def vtk_link_angles(grid, seeds):
    """For every face VTK's reader gives two cells of `grid`, the angle in degrees between the
    face's normal (Newell's, from the points as read) and the link between the two cells' seeds
    (the grid's `seed` cell array, indexing `seeds`). Returns the largest angle and the number of
    such faces."""
    seed_of = cell_array(grid, "seed")
    first_cell = {}
    shared_faces, cells, others = [], [], []
    for cell, faces in enumerate(all_polyhedron_faces(grid)):
        for face in faces:
            key = tuple(sorted(face))
            other = first_cell.pop(key, None)
            if other is None:
                first_cell[key] = cell
                continue
            shared_faces.append(face)
            cells.append(cell)
            others.append(other)
    if not shared_faces:
        return 0.0, 0
    points = vtk_to_numpy(grid.GetPoints().GetData()).astype(float)
    sizes = numpy.fromiter((len(f) for f in shared_faces), dtype=numpy.int64, count=len(shared_faces))
    corner = numpy.fromiter((p for f in shared_faces for p in f), dtype=numpy.int64, count=int(sizes.sum()))
    face_of = numpy.repeat(numpy.arange(len(shared_faces)), sizes)
    # Each corner's successor around its face: the next corner, or the face's first for its last.
    starts = numpy.cumsum(sizes) - sizes
    following = numpy.arange(len(corner)) + 1
    following[starts + sizes - 1] = starts
    a, b = points[corner], points[corner[following]]
    terms = numpy.stack([(a[:, 1] - b[:, 1]) * (a[:, 2] + b[:, 2]),
                         (a[:, 2] - b[:, 2]) * (a[:, 0] + b[:, 0]),
                         (a[:, 0] - b[:, 0]) * (a[:, 1] + b[:, 1])], axis=1)
    normal = numpy.stack([numpy.bincount(face_of, terms[:, k], len(shared_faces)) for k in range(3)], axis=1)
    seed_points = numpy.asarray(seeds, dtype=float)
    seed_of = numpy.asarray(seed_of)
    link = seed_points[seed_of[cells]] - seed_points[seed_of[others]]
    measured = (numpy.linalg.norm(normal, axis=1) > 0) & (numpy.linalg.norm(link, axis=1) > 0)
    normal, link = normal[measured], link[measured]
    # The face's orientation in either cell is its own business: the angle to the line.
    angles = numpy.degrees(numpy.arctan2(numpy.linalg.norm(numpy.cross(normal, link), axis=1),
                                         numpy.abs(numpy.einsum("ij,ij->i", normal, link))))
    return (float(angles.max()) if len(angles) else 0.0), len(shared_faces)
