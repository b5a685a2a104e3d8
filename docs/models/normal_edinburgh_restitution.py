#!/usr/bin/python3
"""Restitution against impact speed for the edinburgh normal model's two dashpots, from the
table test_edinburgh prints in its section 7 (elastic limit, kappa21 = 1.0001, no adhesion,
limitForce on). Writes normal_edinburgh_restitution.png beside this script.

usage: docs/models/normal_edinburgh_restitution.py [build/tests/test_edinburgh]"""
import os
import subprocess
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = os.path.dirname(os.path.abspath(__file__))
prog = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "..", "build", "tests", "test_edinburgh")
out = subprocess.run([prog], capture_output=True, text=True).stdout
rows = {}   # (d_ex, where, e) -> [(v, e default, e eq. 8)]
in_table = False
for line in out.splitlines():
    if line.startswith("7. default dashpot"):
        in_table = True
        continue
    if in_table and line.startswith("8."):
        break
    w = line.split()
    if in_table and len(w) == 6 and w[0].startswith("d_ex="):
        key = (float(w[0][5:]), w[1], float(w[2][2:]))
        rows.setdefault(key, []).append((float(w[3]), float(w[4]), float(w[5])))
if not rows:
    sys.exit("no section-7 table in the output of " + prog)

fig, ax = plt.subplots(figsize=(7, 6))
colours = {0.3: "tab:blue", 0.5: "tab:orange", 0.9: "tab:green"}
for (d, where, e), pts in sorted(rows.items()):
    if where != "wall":
        continue
    v = [p[0] for p in pts]
    style = "-" if d == 1.5 else ":"
    ax.plot(v, [p[1] for p in pts], style + "o", color=colours[e], label=f"e={e}, d_ex={d:g}, default (restitution)")
    ax.plot(v, [p[2] for p in pts], style + "x", color=colours[e], alpha=0.6, label=f"e={e}, d_ex={d:g}, seedEq8")
ax.set_xscale("log")
ax.set_xlabel("impact speed [m/s]")
ax.set_ylabel("restitution [-]")
ax.set_ylim(-0.02, 1.0)
ax.set_title("edinburgh, sphere on a wall, kappa21 = 1.0001, no adhesion, limitForce on")
ax.legend(fontsize=7, ncol=2, loc="upper center", bbox_to_anchor=(0.5, -0.14))
ax.grid(True, which="both", alpha=0.3)
fig.tight_layout()
png = os.path.join(here, "normal_edinburgh_restitution.png")
fig.savefig(png, dpi=110)
print("wrote", png)
