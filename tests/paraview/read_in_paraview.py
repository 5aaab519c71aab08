# Run by pvpython: opens a run's mesh.vtu, its OpenFOAM case (cell zones) and its mesh.exo (the
# Exodus II reader) in ParaView and prints, as JSON, what ParaView read from each: the number of
# cells, and per material its cells and their volume (the volume array the file carries, and
# ParaView's own measure of the cells). Usage: pvpython read_in_paraview.py OUTDIR
import json
import os
import sys

import numpy as np
from paraview import servermanager as sm
from paraview.simple import CellSize, ExodusIIReader, MergeBlocks, OpenFOAMReader, XMLUnstructuredGridReader
from vtkmodules.numpy_interface import dataset_adapter as dsa

out = sys.argv[1]


def fetch(source):
    """The cells of `source` with ParaView's measure of each (Volume) added, as numpy arrays."""
    measured = CellSize(Input=MergeBlocks(Input=source))
    measured.UpdatePipeline()
    data = dsa.WrapDataObject(sm.Fetch(measured))
    return data.GetNumberOfCells(), {k: np.asarray(data.CellData[k]) for k in data.CellData.keys()}


def per_material(labels, names, carried, measured):
    materials = {}
    for label in np.unique(labels):
        mine = labels == label
        materials[names(int(label))] = {
            "cells": int(np.sum(mine)),
            "volume": float(np.sum(carried[mine])) if carried is not None else None,
            "measured": float(np.sum(measured[mine])),
        }
    return materials


read = {}

vtu = XMLUnstructuredGridReader(FileName=[os.path.join(out, "mesh.vtu")])
n, cells = fetch(vtu)
read["vtu"] = {"cells": n, "materials": per_material(cells["material"], str, cells["volume"], cells["Volume"])}

exo = ExodusIIReader(FileName=os.path.join(out, "mesh.exo"))
exo.UpdatePipelineInformation()
exo.ElementBlocks = list(exo.ElementBlocks.Available)
n, cells = fetch(exo)
# ObjectId is the block id: the material's label. Block names come with the reader's info.
info = exo.GetProperty("ElementBlocks").Available
read["exodus"] = {"cells": n, "blocks": list(info),
                  "variables": sorted(cells.keys()),
                  "materials": per_material(cells["ObjectId"], str, cells["volume"], cells["Volume"])}

case = os.path.join(out, "case")
open(os.path.join(case, "case.foam"), "a").close()
# Polyhedra as they are (not decomposed), and the zones as blocks beside the internal mesh.
foam = OpenFOAMReader(FileName=os.path.join(case, "case.foam"), Readzones=1, Decomposepolyhedra=0)
foam.MeshRegions = ["internalMesh"]
measured = CellSize(Input=foam)
measured.UpdatePipeline()
blocks = sm.Fetch(measured)
read["openfoam"] = {"zones": {}}
leaf = blocks.NewIterator()
leaf.InitTraversal()
while not leaf.IsDoneWithTraversal():
    name = leaf.GetCurrentMetaData().Get(blocks.NAME())
    data = leaf.GetCurrentDataObject()
    if name == "internalMesh":
        read["openfoam"]["cells"] = data.GetNumberOfCells()
    elif data.IsA("vtkUnstructuredGrid"):  # a cell zone (face zones come as polygons)
        volume = dsa.WrapDataObject(data).CellData["Volume"]
        read["openfoam"]["zones"][name] = {"cells": data.GetNumberOfCells(), "measured": float(np.sum(volume))}
    leaf.GoToNextItem()

print(json.dumps(read))
