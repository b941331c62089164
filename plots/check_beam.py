"""Granular beam check (scenarios/dem/granular_beam_3pt.toml): reads the last
particles_*.vtu and membrane_beam_*.vtu of a run folder (raw appended VTK XML as
talus writes them) and prints how many grain centres lie outside the closed
membrane (winding number by the triangles' solid angles), the enclosed
volume, the grains' volume and the solid fraction.
Usage: /usr/bin/python3 plots/check_beam.py RUN_FOLDER"""
import glob
import re
import sys

import numpy as np

TYPES = {"Float64": np.float64, "Int64": np.int64, "Int32": np.int32, "UInt8": np.uint8}


def read_vtu(path):
    raw = open(path, "rb").read()
    head, data = raw.split(b'<AppendedData encoding="raw">', 1)
    data = data[data.index(b"_") + 1:]
    arrays = {}
    for m in re.finditer(rb"<DataArray ([^>]*)/?>", head):
        attrs = dict(re.findall(rb'(\w+)="([^"]*)"', m.group(1)))
        name = attrs.get(b"Name", b"").decode()
        off = int(attrs[b"offset"])
        n = int(np.frombuffer(data[off:off + 8], np.uint64)[0])
        a = np.frombuffer(data[off + 8:off + 8 + n], TYPES[attrs[b"type"].decode()])
        comps = int(attrs.get(b"NumberOfComponents", b"1"))
        arrays[name or "Points"] = a.reshape(-1, comps) if comps > 1 else a
    return arrays


def winding(points, tris, p):
    a, b, c = (points[tris[:, k]] - p for k in range(3))
    la, lb, lc = (np.linalg.norm(v, axis=1) for v in (a, b, c))
    num = np.einsum("ij,ij->i", a, np.cross(b, c))
    den = la * lb * lc + np.einsum("ij,ij->i", a, b) * lc + np.einsum("ij,ij->i", b, c) * la \
        + np.einsum("ij,ij->i", c, a) * lb
    return 2 * np.arctan2(num, den).sum() / (4 * np.pi)


run = sys.argv[1]
grains = read_vtu(sorted(glob.glob(f"{run}/particles_*.vtu"))[-1])
mem = read_vtu(sorted(glob.glob(f"{run}/membrane_beam_*.vtu"))[-1])
x, r = grains["Points"], grains["radius"]
pts, tris = mem["Points"], mem["connectivity"].reshape(-1, 3)
outside = sum(abs(winding(pts, tris, p) - 1) > 1e-6 for p in x)
vol = np.einsum("ij,ij->i", pts[tris[:, 0]], np.cross(pts[tris[:, 1]], pts[tris[:, 2]])).sum() / 6
vg = (4 / 3 * np.pi * r**3).sum()
print(f"grains {len(x)}, outside the membrane {outside}; membrane particles {len(pts)}, "
      f"triangles {len(tris)}; enclosed volume {vol * 1e6:.1f} cm^3, grains {vg * 1e6:.1f} cm^3, "
      f"solid fraction {vg / vol:.3f}; membrane extent {np.ptp(pts, axis=0) * 100} cm")
