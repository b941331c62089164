#!/usr/bin/env bash
# talus analyse contacts | rdf | d2min | packing on tiny real runs: a 4 x 4 x 4 cubic lattice of
# grains (spacing a = 2.2 mm, radius 1 mm: 0.2 mm gaps, no contacts, no gravity) expanding
# homogeneously at strain rate 1/s, with one interior grain given an extra 0.01 m/s; and a 2D
# square lattice of disks at rest. Known values: contacts within a 0.21 mm gap = the lattice's,
# g(r) shell of 6 at a, Voronoi phi = grain / a^3, D2min zero away from the odd grain and
# 18 delta^2 at it; its autocorrelation C(r) equal to an O(N^2) recomputation from d2min.csv.
# Bad input exits 2 and writes nothing. Args: <talus binary> <source dir>.
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
open(f"{sys.argv[1]}/lattice.list", "w").write("\n".join(rows) + "\n")
open(f"{sys.argv[1]}/disks.list", "w").write("\n".join(disks) + "\n")
PY
dem_list_scenario lattice 3 "[0, 0, 0]" < "$tmp/lattice.list" > "$tmp/lattice.toml"
dem_list_scenario disks 2 "[0, 0]" < "$tmp/disks.list" > "$tmp/disks.toml"
run_check "tiny 3D lattice run" "$tmp/lattice.toml" "$tmp/lattice"
run_check "tiny 2D lattice run" "$tmp/disks.toml" "$tmp/disks"
run=$tmp/lattice
"$talus" analyse contacts "$run" --gap 2.1e-4 --min-contacts 3 --quiet > "$tmp/py" 2>&1
rc=$?; check_rc "contacts exit status"
"$talus" analyse rdf "$run" --time 0 --rmax 2.6e-3 --bins 13 --quiet > "$tmp/py" 2>&1
rc=$?; check_rc "rdf exit status"
"$talus" analyse d2min "$run" --cutoff 3.3e-3 --quiet > "$tmp/py" 2>&1
rc=$?; check_rc "d2min exit status"
"$talus" analyse packing "$run" --time 0 --quiet > "$tmp/py" 2>&1
rc=$?; check_rc "packing exit status"
"$talus" analyse d2min "$run" --cutoff 3.3e-3 --correlation 1e-3 --correlation-rmax 8e-3 \
  --out "$tmp/corr" --quiet > "$tmp/py" 2>&1
rc=$?; check_rc "d2min --correlation exit status"
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
# C(r) of D_min (Götz eq. 48-49) recomputed here from d2min.csv by the O(N^2) double loop over
# the 64 grains, with D_min = d_min_norm * d_mean: the command's bins [k w, (k+1) w), C(0) =
# mean D_min^2 / d, means over the grains with a partner in the bin, pairs counted once. Also
# the same d2min.csv as without --correlation. Round-off only: 1e-9 relative.
/usr/bin/python3 - "$tmp/corr" "$run/analysis" > "$tmp/py" 2>&1 <<'PY'
import csv, json, math, sys
d, ref = sys.argv[1], sys.argv[2]
assert open(f"{d}/d2min.csv").read() == open(f"{ref}/d2min.csv").read()
meta = json.load(open(f"{d}/d2min.json"))
dm = meta["mean_diameter"]
g = [(float(x["x"]), float(x["y"]), float(x["z"]), float(x["d_min_norm"]) * dm)
     for x in csv.DictReader(open(f"{d}/d2min.csv"))]
g = [p for p in g if not math.isnan(p[3])]
w, bins = 1e-3, 8
c0 = sum(p[3] ** 2 for p in g) / len(g) / dm
sums, grains, pairs = [0.0] * bins, [0] * bins, [0] * bins
for i, p in enumerate(g):
    s, m = [0.0] * bins, [0] * bins
    for j, q in enumerate(g):
        r = math.dist(p[:3], q[:3])
        if j != i and r < bins * w:
            b = min(int(r / w), bins - 1)
            s[b] += q[3]; m[b] += 1; pairs[b] += j > i
    for b in range(bins):
        if m[b]:
            sums[b] += p[3] * s[b] / m[b] / dm; grains[b] += 1
rows = list(csv.DictReader(open(f"{d}/d2min_correlation.csv")))
assert len(rows) == bins + 1, len(rows)
assert float(rows[0]["r"]) == 0 and abs(float(rows[0]["C"]) - c0) < 1e-9 * c0, (rows[0], c0)
assert meta["correlation"]["bin_width"] == w and abs(meta["correlation"]["r_max"] - 8e-3) < 1e-15
assert sum(pairs) > 0 and sum(pairs) < 64 * 63 // 2
for b, row in enumerate(rows[1:]):
    assert abs(float(row["r"]) - (b + 0.5) * w) < 1e-15, row
    assert int(float(row["grains"])) == grains[b] and int(float(row["pairs"])) == pairs[b], (b, row)
    if grains[b]:
        c = sums[b] / grains[b]
        assert abs(float(row["C"]) - c) < 1e-9 * c0, (b, row, c)
        assert abs(float(row["C_over_C0"]) - c / c0) < 1e-9, (b, row)
    else:
        assert row["C"] == "nan", row
PY
rc=$?; check_rc "C(r) of D_min recomputed from d2min.csv"
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
bad "zero correlation bin" "--correlation" "$talus" analyse d2min "$run" --correlation 0
bad "correlation rmax alone" "--correlation" "$talus" analyse d2min "$run" --correlation-rmax 1e-3
bad "negative margin" "--margin" "$talus" analyse packing "$run" --margin -1
bad "empty interval" "no snapshot in that interval" "$talus" analyse contacts "$run" --from 1 --to 2
finish structure
