#!/usr/bin/env bash
# A grain that falls out of the domain carries its kinetic energy into
# summary.json's removed_kinetic_energy_J (the energy check counts it, issue 28
# §5): a disk (2D: energies per metre, m = rho pi r^2) dropped from rest at
# y0 = 0.5 m and removed when its centre leaves y >= 0 has fallen h = 0.5 m,
# so the energy is m g h (free fall, no contact). Particles leave at a
# neighbour-list build, which comes once a grain has moved half the skin: the
# grain has fallen up to skin/2 more (skin 0.1 mm here, so m g h to m g (h +
# skin/2), 1e-4 of it), and the removal falls within a step (with the
# half-kicked velocity: m g v dt, 6e-5 of it with dt = 1e-5 s, v = 3.1 m/s).
# Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"
echo '{ position = [0.0, 0.5], radius = 0.01 },' |
  dem_list_scenario drop 2 "[0.0, -9.81]" >"$tmp/drop.toml"
"$talus" run "$tmp/drop.toml" --out "$tmp/run" --quiet --set run.duration=0.5 \
  --set run.time_step=1e-5 --set run.skin=1e-4 \
  --set "run.domain={min=[-1, 0], max=[1, 1]}" --set output.snapshot_interval=0 >"$tmp/py" 2>&1
rc=$?; check_rc "the drop runs"
/usr/bin/python3 - "$tmp/run/summary.json" >"$tmp/py" 2>&1 <<'PY'; rc=$?
import json, math, sys
m = json.load(open(sys.argv[1]))["metrics"]
assert m["particles"] == 0 and m["particles_removed"] == 1, m
mg = 2000 * math.pi * 0.01**2 * 9.81  # rho pi r^2 g, N/m
got, step = m["removed_kinetic_energy_J"], mg * 3.2 * 1e-5
assert mg * 0.5 - step <= got <= mg * (0.5 + 0.5e-4) + step, (got, mg * 0.5)
PY
check_rc "removed_kinetic_energy_J = m g h, up to half the skin and a step"
finish removed_energy
