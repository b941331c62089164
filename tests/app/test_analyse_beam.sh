#!/usr/bin/env bash
# talus analyse beam on a made-up 4-point beam run: beam.csv holds σ = E ε - B ε² + C ε³
# from bending_start on (concave below ε* = B/(3C) = 0.02, convex above) and junk before it.
# Known values: the yield point at ε* with σ(ε*), E_b of the line through the origin over the
# samples with ε <= 0.002 (computed here), the largest stress at the end. Bad input exits 2.
# Args: <talus binary> <source dir>.
source "$(dirname "$0")/check_lib.sh"
run=$tmp/beam
mkdir -p "$run"
/usr/bin/python3 - "$run" <<'PY'
import json, sys
run = sys.argv[1]
E, C, e_star, start = 1e7, 2e8, 0.02, 0.06
B = 3 * C * e_star
json.dump({"scenario": {"beam": {"test": "four_point", "bending_start": start,
                                 "yield_smoothing": 0.002}}}, open(f"{run}/summary.json", "w"))
with open(f"{run}/beam.csv", "w") as f:
    f.write("time,rod_travel,rod_force,bottom_centre_z,deflection,strain,stress,support_reaction_z,kinetic_energy\n")
    for i in range(100):  # before bending_start: must be left out
        f.write(f"{0.0006 * i},0,0,0,0,0.01,1e9,0,0\n")
    for i in range(4001):
        e = 0.08 * i / 4000
        f.write(f"{start + 1e-3 * i},0,0,0,0,{e!r},{E * e - B * e * e + C * e ** 3!r},0,0\n")
# E_b of the same samples: sum(sigma eps) / sum(eps^2) over 0 < eps <= 0.002.
es = [0.08 * i / 4000 for i in range(1, 4001) if 0.08 * i / 4000 <= 0.002]
s = [E * e - B * e * e + C * e ** 3 for e in es]
json.dump({"E_b": sum(a * b for a, b in zip(s, es)) / sum(e * e for e in es),
           "Y_b": E * e_star - B * e_star ** 2 + C * e_star ** 3,
           "top": E * 0.08 - B * 0.0064 + C * 0.08 ** 3}, open(f"{run}/expected.json", "w"))
PY
"$talus" analyse beam "$run" --quiet > "$tmp/py" 2>&1
rc=$?; check_rc "analyse beam exit status"
/usr/bin/python3 - "$run" > "$tmp/py" 2>&1 <<'PY'
import json, sys
run = sys.argv[1]
got = json.load(open(f"{run}/analysis/beam_four_point.json"))
want = json.load(open(f"{run}/expected.json"))
assert got["yield_smoothing"] == 0.002, got  # the run's own width
assert got["rows"] == 4001, got  # the junk before bending_start left out
assert abs(got["youngs_modulus"] - want["E_b"]) < 1e-9 * want["E_b"], (got, want)
assert got["fit_points"] == 100, got
# A Gaussian keeps a linear second derivative: ε* up to the kernel's cutoff (see
# tests/analysis/test_beam_four_point.cpp, which measured 1.7e-6).
assert got["yield_found"] and abs(got["yield_strain"] - 0.02) < 1e-5, got
assert abs(got["yield_strength"] - want["Y_b"]) < 2e-4 * want["Y_b"], (got, want)
assert abs(got["largest_stress"] - want["top"]) < 1e-9 * want["top"], (got, want)
PY
rc=$?; check_rc "E_b, Y_b and the largest stress of the cubic"
"$talus" analyse beam "$run" --yield-smoothing 0.03 --out "$tmp/wide" --quiet > "$tmp/py" 2>&1
rc=$?; check_rc "analyse beam with a wide smoothing"
check "a smoothing wider than the curve allows finds no yield point" \
  "grep -q '\"yield_found\": false' '$tmp/wide/beam_four_point.json'"
"$talus" analyse beam "$run" --yield-smoothing -1 --quiet > "$tmp/err" 2>&1
check "negative smoothing: exit 2 naming the option" \
  "[ $? -eq 2 ] && grep -q -- '--yield-smoothing' '$tmp/err'"
"$talus" analyse beam "$tmp" --quiet > "$tmp/err" 2>&1
check "no run: exit 2 naming summary.json" "[ $? -eq 2 ] && grep -q 'summary.json' '$tmp/err'"
mkdir -p "$tmp/three"
echo '{"scenario": {"beam": {"test": "three_point"}}}' > "$tmp/three/summary.json"
"$talus" analyse beam "$tmp/three" --quiet > "$tmp/err" 2>&1
check "a three-point run: exit 2" "[ $? -eq 2 ] && grep -q 'not a four-point' '$tmp/err'"
finish "analyse beam"
