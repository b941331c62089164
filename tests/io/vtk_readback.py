#!/usr/bin/python3
"""Reads the snapshots written by the vtk_sample program back with VTK.

Usage: vtk_readback.py VTK_SAMPLE_BINARY

VTK's vtkXMLUnstructuredGridReader is the reader ParaView itself uses for
.vtu files, so a clean read here means ParaView opens the snapshots. The .pvd
collection is parsed with Python's xml module (its reader lives in ParaView,
not in VTK). The expected values are the formulas in
tests/io/tools/vtk_sample_main.cpp, repeated below.
"""
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

VTK_VERTEX, VTK_LINE, VTK_TRIANGLE = 1, 3, 5


def check(condition, message):
    if not condition:
        sys.exit(f"FAIL: {message}")


def read_collection(pvd_path):
    root = ET.parse(pvd_path).getroot()
    check(root.get("type") == "Collection", f"{pvd_path} is not a VTK collection")
    return [(float(d.get("timestep")), d.get("file")) for d in root.iter("DataSet")]


def read_vtu(path):
    errors = []
    reader = vtkXMLUnstructuredGridReader()
    reader.AddObserver("ErrorEvent", lambda obj, event: errors.append(event))
    reader.SetFileName(path)
    reader.Update()
    check(not errors and reader.GetErrorCode() == 0, f"VTK could not read {path}")
    return reader.GetOutput()


def point_array(grid, name):
    array = grid.GetPointData().GetArray(name)
    check(array is not None, f"point array {name} missing")
    return vtk_to_numpy(array)


def cells_of(grid):
    types = [grid.GetCellType(c) for c in range(grid.GetNumberOfCells())]
    corners = []
    for c in range(grid.GetNumberOfCells()):
        ids = grid.GetCell(c).GetPointIds()
        corners.append([ids.GetId(k) for k in range(ids.GetNumberOfIds())])
    return types, corners


def check_particles(folder):
    frames = read_collection(os.path.join(folder, "particles.pvd"))
    # The sample writes t = 0, 0.5, 1, 1.5, then truncates after t = 1.
    check([t for t, _ in frames] == [0.0, 0.5, 1.0], f"particle times {frames}")
    check(not os.path.exists(os.path.join(folder, "particles_000003.vtu")),
          "the truncated frame's file was not deleted")
    i = np.arange(5.0)
    for t, name in frames:
        grid = read_vtu(os.path.join(folder, name))
        check(grid.GetNumberOfPoints() == 5, f"{name}: {grid.GetNumberOfPoints()} points")
        types, corners = cells_of(grid)
        check(types == [VTK_VERTEX] * 5 and corners == [[k] for k in range(5)],
              f"{name}: vertex cells {types} {corners}")
        # Doubles go through raw binary, so they come back bit for bit.
        expected = {
            "position": np.column_stack([i + t, 2 * i, -i]),
            "radius": 0.01 * (i + 1) + 0.001 * t,
            "velocity": np.column_stack([np.full(5, t), i, np.full(5, -1.5)]),
            "angular_velocity": np.column_stack([np.zeros(5), np.zeros(5), 10 * i + t]),
            "id": 1000 + np.arange(5),
            "material": np.arange(5) % 2,
            "contacts": np.arange(5),
            "layer": 0.5 * i,
        }
        for key, want in expected.items():
            got = (vtk_to_numpy(grid.GetPoints().GetData()) if key == "position"
                   else point_array(grid, key))
            check(got.shape == want.shape and np.array_equal(got, want),
                  f"{name}: {key} is {got}, expected {want}")
        check(grid.GetPointData().GetArray("id").GetDataTypeAsString() in ("long", "long long"),
              f"{name}: id is not a 64-bit integer")


def check_walls(folder):
    frames = read_collection(os.path.join(folder, "walls.pvd"))
    check(frames == [(0.0, "walls_000000.vtu")], f"wall frames {frames}")
    grid = read_vtu(os.path.join(folder, frames[0][1]))
    check(grid.GetNumberOfPoints() == 4, "wall points")
    types, corners = cells_of(grid)
    # Sample: lines (0,1), (1,2) of wall 0; triangles (0,1,2) of wall 1, (0,2,3) of wall 2.
    check(types == [VTK_LINE, VTK_LINE, VTK_TRIANGLE, VTK_TRIANGLE], f"wall cell types {types}")
    check(corners == [[0, 1], [1, 2], [0, 1, 2], [0, 2, 3]], f"wall cells {corners}")
    wall = vtk_to_numpy(grid.GetCellData().GetArray("wall"))
    check(list(wall) == [0, 0, 1, 2], f"wall index per cell {wall}")


def main():
    if len(sys.argv) < 2:
        sys.exit("usage: vtk_readback.py VTK_SAMPLE_BINARY")
    with tempfile.TemporaryDirectory(prefix="talus_vtk_") as folder:
        subprocess.run([sys.argv[1], folder], check=True)
        check_particles(folder)
        check_walls(folder)
    print("vtk readback: ok")


if __name__ == "__main__":
    main()
