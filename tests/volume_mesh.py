"""The volume mesh as outside tools read it (VTK's reader, OpenFOAM's checkMesh), shared by the
Python tests."""
import math
import os
import re
import shutil
import subprocess

import vtk  # VTK's Python modules, from python3-paraview

from vtk_volume import vtk_boundary_volume  # noqa: F401  (one import for the tests)

CHECKMESH = shutil.which("checkMesh") or "/usr/bin/checkMesh"


def read_vtu(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def cell_array(grid, name):
    a = grid.GetCellData().GetArray(name)
    return [a.GetValue(i) for i in range(a.GetNumberOfTuples())]


def vtk_cell_volumes(grid):
    f = vtk.vtkCellSizeFilter()
    f.SetInputData(grid)
    f.ComputeVolumeOn()
    f.Update()
    return cell_array(f.GetOutput(), "Volume")


def polyhedron_faces(grid, cell):
    """The polygons of a polyhedron cell of a VTK grid, as tuples of point ids."""
    ids = vtk.vtkIdList()
    grid.GetFaceStream(cell, ids)
    stream = [ids.GetId(i) for i in range(ids.GetNumberOfIds())]
    faces, i = [], 1
    for _ in range(stream[0]):
        n = stream[i]
        faces.append(tuple(stream[i + 1:i + 1 + n]))
        i += n + 1
    return faces


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
    points = grid.GetPoints()
    seed_of = cell_array(grid, "seed")
    first_cell = {}
    largest, shared = 0.0, 0
    for cell in range(grid.GetNumberOfCells()):
        for face in polyhedron_faces(grid, cell):
            key = tuple(sorted(face))
            other = first_cell.pop(key, None)
            if other is None:
                first_cell[key] = cell
                continue
            shared += 1
            coords = [points.GetPoint(p) for p in face]
            normal = [0.0, 0.0, 0.0]
            for k, a in enumerate(coords):
                b = coords[(k + 1) % len(coords)]
                normal[0] += (a[1] - b[1]) * (a[2] + b[2])
                normal[1] += (a[2] - b[2]) * (a[0] + b[0])
                normal[2] += (a[0] - b[0]) * (a[1] + b[1])
            s, t = seeds[seed_of[other]], seeds[seed_of[cell]]
            link = [t[i] - s[i] for i in range(3)]
            n_len = math.sqrt(sum(x * x for x in normal))
            l_len = math.sqrt(sum(x * x for x in link))
            if n_len == 0 or l_len == 0:
                continue
            cross = (normal[1] * link[2] - normal[2] * link[1], normal[2] * link[0] - normal[0] * link[2],
                     normal[0] * link[1] - normal[1] * link[0])
            # The face's orientation in either cell is its own business: the angle to the line.
            angle = math.degrees(math.atan2(math.sqrt(sum(x * x for x in cross)), abs(sum(normal[i] * link[i] for i in range(3)))))
            largest = max(largest, angle)
    return largest, shared
