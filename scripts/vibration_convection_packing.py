"""Keeps the grains of a box packing that lie wholly inside the convection cylinder.

usage: /usr/bin/python3 scripts/vibration_convection_packing.py RUN_DIR OUT.csv [R H]

RUN_DIR is the output of scenarios/dem/vibration_convection_packing.toml; the first particle
snapshot is read. Grains with sqrt(x^2 + y^2) + r <= R and r <= z <= H - r are kept (defaults
R = 0.0135 m, H = 0.065 m: Götz 2024 §6.2), written as 'x, y, z, radius' for a
[[particles]] source of type "file", and their count and solid fraction printed.
"""
import math
import sys
import xml.etree.ElementTree as ET

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader


def main():
    run, out = sys.argv[1], sys.argv[2]
    R = float(sys.argv[3]) if len(sys.argv) > 3 else 0.0135
    H = float(sys.argv[4]) if len(sys.argv) > 4 else 0.065
    first = ET.parse(f"{run}/particles.pvd").getroot().find(".//DataSet").get("file")
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(f"{run}/{first}")
    reader.Update()
    grid = reader.GetOutput()
    x = vtk_to_numpy(grid.GetPoints().GetData())
    r = vtk_to_numpy(grid.GetPointData().GetArray("radius"))
    keep = (np.hypot(x[:, 0], x[:, 1]) + r <= R) & (x[:, 2] >= r) & (x[:, 2] <= H - r)
    with open(out, "w") as f:
        f.write("x, y, z, radius\n")
        for p, q in zip(x[keep], r[keep]):
            f.write(f"{p[0]:.9g}, {p[1]:.9g}, {p[2]:.9g}, {q:.9g}\n")
    phi = np.sum(4.0 / 3.0 * math.pi * r[keep] ** 3) / (math.pi * R * R * H)
    print(f"{keep.sum()} of {len(r)} grains inside; solid fraction {phi:.4f}")


if __name__ == "__main__":
    main()
