"""Volumes of a VTK unstructured grid as VTK itself measures them, shared by the Python tests."""
import vtk  # VTK's Python modules, from python3-paraview


def vtk_boundary_volume(grid):
    """The volume VTK finds inside the grid's outer surface (its faces used by one cell only).

    VTK's per-polyhedron volumes (vtkCellSizeFilter) mis-measure some cells with many nearly
    degenerate faces, by some 1e-5 of the total on VoroCrust meshes; the outer surface does not."""
    surface = vtk.vtkDataSetSurfaceFilter()
    surface.SetInputData(grid)
    triangles = vtk.vtkTriangleFilter()
    triangles.SetInputConnection(surface.GetOutputPort())
    mass = vtk.vtkMassProperties()
    mass.SetInputConnection(triangles.GetOutputPort())
    mass.Update()
    return mass.GetVolume()
