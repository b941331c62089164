#!/usr/bin/python3
"""A real talus run's snapshots open in VTK's own XML reader (what ParaView uses):
particle count, radius, velocity and ids match summary.json and the scenario.

Args: <talus binary> <source dir>. Run with Debian's /usr/bin/python3 (python3-vtk9).
"""
import json
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import vtk
from vtk.util.numpy_support import vtk_to_numpy

from checks import Checks

talus, src = sys.argv[1], sys.argv[2]
check = Checks()


with tempfile.TemporaryDirectory() as tmp:
    out = os.path.join(tmp, "run")
    subprocess.run([talus, "run", os.path.join(src, "scenarios", "dem", "column_collapse.toml"), "--out", out,
                    "--quiet", "--set", "run.duration=0.002",
                    "--set", "particles.0.box={min=[0,0,0],max=[0.01206,0.00804,0.02412]}",
                    "--set", "output.snapshot_interval=0.001"], check=True)
    summary = json.load(open(os.path.join(out, "summary.json")))
    n = summary["metrics"]["particles"]
    frames = ET.parse(os.path.join(out, "particles.pvd")).getroot().findall(".//DataSet")
    times = [float(f.get("timestep")) for f in frames]
    check("pvd lists the frames at 0, 1, 2 ms", [round(t, 9) for t in times] == [0.0, 0.001, 0.002])
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(os.path.join(out, frames[-1].get("file")))
    reader.Update()
    grid = reader.GetOutput()
    check("particle count", grid.GetNumberOfPoints() == n == 6 * 4 * 12)
    pd = grid.GetPointData()
    radius = vtk_to_numpy(pd.GetArray("radius"))
    check("radius is the scenario's 1 mm", abs(radius.min() - 0.001) < 1e-15 and abs(radius.max() - 0.001) < 1e-15)
    vel = vtk_to_numpy(pd.GetArray("velocity"))
    ke = 0.5 * (2500 * 4 / 3 * 3.141592653589793 * 0.001 ** 3) * (vel ** 2).sum()
    check("kinetic energy from the snapshot equals summary.json",
          abs(ke - summary["metrics"]["kinetic_energy_J"]) <= 1e-9 * max(ke, 1e-30))
    ids = sorted(vtk_to_numpy(pd.GetArray("id")).tolist())
    check("ids are 0..n-1", ids == list(range(n)))
    for name in ("angular_velocity", "material", "contacts"):
        check(f"array {name} present", pd.GetArray(name) is not None)
    wreader = vtk.vtkXMLUnstructuredGridReader()
    wframes = ET.parse(os.path.join(out, "walls.pvd")).getroot().findall(".//DataSet")
    wreader.SetFileName(os.path.join(out, wframes[-1].get("file")))
    wreader.Update()
    walls = wreader.GetOutput()
    check("four plane walls drawn as 8 triangles", walls.GetNumberOfCells() == 8)

check.finish("vtk_run")
