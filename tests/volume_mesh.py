"""The volume mesh as outside tools read it (VTK's reader, OpenFOAM's checkMesh), shared by the
Python tests."""
import os
import re
import shutil
import subprocess

import vtk  # python3-vtk9

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
