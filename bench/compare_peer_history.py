#!/usr/bin/python3
"""Plots talus' column-collapse history (series.csv of a full run) against the
LIGGGHTS and LAMMPS thermo tables of ../shared/peers/README.md §4.

Usage: compare_peer_history.py RUN_DIR OUT.png
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# ../shared/peers/README.md §4, "Time history of the default run".
PEER_T = [0.00, 0.03, 0.06, 0.09, 0.12, 0.15, 0.18, 0.21, 0.24, 0.27, 0.30]
KE_LIGGGHTS = [0, 1.37e-4, 2.36e-3, 2.61e-3, 3.18e-3, 2.73e-3, 2.26e-3, 1.73e-3, 1.27e-3, 8.93e-4, 6.10e-4]
KE_LAMMPS = [0, 1.41e-4, 2.39e-3, 2.64e-3, 3.24e-3, 2.69e-3, 2.18e-3, 1.77e-3, 1.33e-3, 9.31e-4, 6.09e-4]
FRONT_LIGGGHTS = [0.039199, 0.04295, 0.05080, 0.05981, 0.07422, 0.09211, 0.10974, 0.12635, 0.14267, 0.15762, 0.17326]
FRONT_LAMMPS = [0.039199, 0.04293, 0.05079, 0.06097, 0.07639, 0.09292, 0.10828, 0.13040, 0.14810, 0.16358, 0.17853]

rows = list(csv.DictReader(open(sys.argv[1] + "/series.csv")))
t = [float(r["time"]) for r in rows]
fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4))
a.plot(t, [float(r["kinetic_energy"]) for r in rows], label="talus")
a.plot(PEER_T, KE_LIGGGHTS, "o", label="LIGGGHTS 3.8")
a.plot(PEER_T, KE_LAMMPS, "s", mfc="none", label="LAMMPS 2021")
a.set_xlabel("time [s]")
a.set_ylabel("translational kinetic energy [J]")
a.legend()
a.grid(alpha=0.3)
b.plot(t, [float(r["front_x"]) for r in rows], label="talus")
b.plot(PEER_T, FRONT_LIGGGHTS, "o", label="LIGGGHTS 3.8")
b.plot(PEER_T, FRONT_LAMMPS, "s", mfc="none", label="LAMMPS 2021")
b.set_xlabel("time [s]")
b.set_ylabel("front x (max centre x) [m]")
b.legend()
b.grid(alpha=0.3)
fig.suptitle("3D column collapse, 8000 spheres: talus vs the peers")
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=110)
print(sys.argv[2])
