#!/usr/bin/env bash
# talus analyse contacts | rdf | d2min | packing on tiny real runs: a 4 x 4 x 4 cubic lattice of
# grains (spacing a = 2.2 mm, radius 1 mm: 0.2 mm gaps, no contacts, no gravity) expanding
# homogeneously at strain rate 1/s, with one interior grain given an extra 0.01 m/s; and a 2D
# square lattice of disks at rest. Known values: contacts within a 0.21 mm gap = the lattice's,
# g(r) shell of 6 at a, Voronoi phi = grain / a^3, D2min zero away from the odd grain and
# 18 delta^2 at it. Bad input exits 2 and writes nothing. Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"
/usr/bin/python3 - "$tmp" <<'PY'
import sys
a, r = 2.2e-3, 1e-3
rows = []
for i in range(4):
    for j in range(4):
        for k in range(4):
            x = [a * i, a * j, a * k]
            v = [1.0 * (c - 1.5 * a) for c in x]  # homogeneous expansion about the centre
            if (i, j, k) == (1, 1, 1):
                v[0] += 0.01  # the non-affine grain
            rows.append(f"  {{ position = {x}, radius = {r}, velocity = {v} }},")
disks = [f"  {{ position = [{a * i}, {a * j}], radius = {r} }}," for i in range(4) for j in range(4)]
head = """method = "dem"
name = "{name}"
[run]
dimension = {dim}
duration = 0.01
gravity = {g}
[contact]
model = "viscoelastic_hertz"
[[materials]]
name = "grain"
density = 2000
youngs_modulus = 1e8
poisson_ratio = 0.245
friction = 0.5
dissipation = 7e-9
[[particles]]
type = "list"
material = "grain"
list = [
"""
tail = "]\n[output]\nsnapshot_interval = 0.0025\n"
open(f"{sys.argv[1]}/lattice.toml", "w").write(
    head.format(name="lattice", dim=3, g="[0, 0, 0]") + "\n".join(rows) + "\n" + tail)
open(f"{sys.argv[1]}/disks.toml", "w").write(
    head.format(name="disks", dim=2, g="[0, 0]") + "\n".join(disks) + "\n" + tail)
PY
"$talus" run "$tmp/lattice.toml" --out "$tmp/lattice" --quiet > "$tmp/py" 2>&1
rc=$?; check_rc "tiny 3D lattice run"
"$talus" run "$tmp/disks.toml" --out "$tmp/disks" --quiet > "$tmp/py" 2>&1
rc=$?; check_rc "tiny 2D lattice run"
run=$tmp/lattice
"$talus" analyse contacts "$run" --gap 2.1e-4 --min-contacts 3 --quiet > "$tmp/py" 2>&1
rc=$?; check_rc "contacts exit status"
"$talus" analyse rdf "$run" --time 0 --rmax 2.6e-3 --bins 13 --quiet > "$tmp/py" 2>&1
rc=$?; check_rc "rdf exit status"
"$talus" analyse d2min "$run" --cutoff 3.3e-3 --quiet > "$tmp/py" 2>&1
rc=$?; check_rc "d2min exit status"
"$talus" analyse packing "$run" --time 0 --quiet > "$tmp/py" 2>&1
rc=$?; check_rc "packing exit status"
"$talus" analyse packing "$tmp/disks" --quiet > "$tmp/py" 2>&1
rc=$?; check_rc "2D packing exit status"
"$talus" analyse contacts "$tmp/disks" --gap 2.1e-4 --quiet > "$tmp/py" 2>&1
rc=$?; check_rc "2D contacts exit status"
for f in contacts.csv rdf.csv rdf.json d2min.csv d2min.json d2min.pvd d2min_000000.vtu \
  packing.csv packing.json; do
  check "writes $f" "[ -s '$run/analysis/$f' ]"
done
/usr/bin/python3 - "$run/analysis" "$tmp/disks/analysis" > "$tmp/py" 2>&1 <<'PY'
import csv, json, math, sys
d, d2 = sys.argv[1], sys.argv[2]
a, r = 2.2e-3, 1e-3
# Contacts within a 0.21 mm gap at t = 0: the cubic lattice's 3 n^2 (n - 1) = 144 pairs,
# z = 288 / 64 = 4.5; every grain has >= 3 (corners), so no rattler at threshold 3. The DEM saw
# no contact (z_snapshot 0). By the end the expansion has opened every gap to 0.222 mm except
# the odd grain's towards its +x neighbour (0.2 + 0.022 - 0.1 = 0.122 mm): one pair, z = 2/64.
rows = list(csv.DictReader(open(f"{d}/contacts.csv")))
assert len(rows) >= 5, len(rows)
assert float(rows[0]["time"]) == 0 and float(rows[0]["z"]) == 4.5, rows[0]
assert float(rows[0]["rattlers"]) == 0 and float(rows[0]["z_no_rattlers"]) == 4.5, rows[0]
assert float(rows[0]["z_snapshot"]) == 0, rows[0]
assert float(rows[-1]["z"]) == 2 / 64, rows[-1]
# g(r) at t = 0, bins of 0.2 mm: the 6 neighbours at a = 2.2 mm fall in bin 11 ([2.2, 2.4) mm
# - a lies on its lower edge up to round-off, so accept bins 10-11); reference grains: centres
# 2.6 mm inside the box [-1, 7.6] mm: the 8 grains with i, j, k in {1, 2}.
meta = json.load(open(f"{d}/rdf.json"))
assert meta["reference_grains"] == 8, meta
rdf = list(csv.DictReader(open(f"{d}/rdf.csv")))
assert len(rdf) == 13
coord = [float(x["coordination"]) for x in rdf]
assert coord[9] == 0 and coord[11] == 6 and coord[12] == 6, coord
# D2min from t = 0 to the end (cutoff 1.5 a: 6 face + 12 edge neighbours): the expansion is
# affine, so only grains seeing the odd grain, and the odd grain itself, are non-zero. The odd
# grain's neighbourhood is symmetric, so J = the expansion and D2min = 18 delta^2 with
# delta = 0.01 m/s * t (free flight: no contacts, no gravity).
meta = json.load(open(f"{d}/d2min.json"))
t = meta["to"]
assert abs(t - 0.01) < 1e-4, t
delta = 0.01 * t
per = {int(float(x["id"])): x for x in csv.DictReader(open(f"{d}/d2min.csv"))}
assert len(per) == 64 and meta["evaluated"] == 64, (len(per), meta["evaluated"])
odd = 1 * 16 + 1 * 4 + 1  # id of (1, 1, 1) in list order
pos = {i: (i // 16, (i // 4) % 4, i % 4) for i in range(64)}
for i, row in per.items():
    v = float(row["d2min"])
    near = sum((p - q) ** 2 for p, q in zip(pos[i], pos[odd])) <= 2
    if i == odd:
        assert abs(v - 18 * delta**2) < 1e-6 * 18 * delta**2, (v, 18 * delta**2)
        assert int(float(row["neighbours"])) == 18
    elif near:
        assert v > 1e-3 * delta**2, (i, v)
    else:
        assert v < 1e-12 * delta**2, (i, v)
assert meta["mean_d2min"] > 0
# Voronoi packing at t = 0: the 8 interior grains have cubic cells a^3: phi = 4/3 pi r^3 / a^3.
meta = json.load(open(f"{d}/packing.json"))
phi = 4 / 3 * math.pi * r**3 / a**3
assert meta["interior_grains"] == 8, meta
assert abs(meta["mean_phi_interior"] - phi) < 1e-9, (meta["mean_phi_interior"], phi)
# 2D disks at rest: 4 interior disks with square cells a^2, phi = pi r^2 / a^2; contacts
# within 0.21 mm: 2 n (n - 1) = 24 pairs of 16 disks, z = 3 at every snapshot.
meta = json.load(open(f"{d2}/packing.json"))
assert meta["dimension"] == 2 and meta["interior_grains"] == 4, meta
assert abs(meta["mean_phi_interior"] - math.pi * r**2 / a**2) < 1e-9, meta
for row in csv.DictReader(open(f"{d2}/contacts.csv")):
    assert float(row["z"]) == 3, row
PY
rc=$?; check_rc "analytic values recovered"
# ParaView reads the D2min file as a particle snapshot with the values as point data.
/usr/bin/python3 - "$run/analysis/d2min_000000.vtu" > "$tmp/py" 2>&1 <<'PY'
import sys
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
reader = vtkXMLUnstructuredGridReader()
reader.SetFileName(sys.argv[1])
reader.Update()
grid = reader.GetOutput()
assert grid.GetNumberOfPoints() == 64, grid.GetNumberOfPoints()
for name in ("d2min", "d_min_norm", "neighbours", "radius", "id"):
    assert grid.GetPointData().GetArray(name) is not None, name
PY
rc=$?; check_rc "d2min vtu readable by VTK"
# Bad input: exit 2, a message naming the problem, nothing written.
bad() {  # name, expected text, command...
  local name=$1 text=$2; shift 2
  "$@" --out "$tmp/bad" --quiet 2> "$tmp/err"
  check "$name: exit 2" "[ $? -eq 2 ] && grep -q -- '$text' '$tmp/err' && [ ! -e '$tmp/bad' ] \
    || { cat '$tmp/err'; false; }"
}
bad "no run folder" "particles.pvd" "$talus" analyse contacts "$tmp/nothing"
bad "negative rmax" "--rmax" "$talus" analyse rdf "$run" --rmax -1e-3
bad "rmax too large" "too large" "$talus" analyse rdf "$run" --rmax 5e-3
bad "zero bins" "--bins" "$talus" analyse rdf "$run" --bins 0
bad "time after the run" "no snapshot near" "$talus" analyse rdf "$run" --time 5
bad "d2min backwards" "must come after" "$talus" analyse d2min "$run" --from 0.01 --to 0
bad "negative cutoff" "--cutoff" "$talus" analyse d2min "$run" --cutoff -1
bad "negative margin" "--margin" "$talus" analyse packing "$run" --margin -1
bad "empty interval" "no snapshot in that interval" "$talus" analyse contacts "$run" --from 1 --to 2
finish structure
