#!/usr/bin/env python3
"""Settling sphere: check the coupled run against Schiller-Naumann and draw the curve.

Reads postProcessing/particles.dat (time [s], particles, mean position x y z [m], mean velocity
vx vy vz [m/s]; written by the coupling layer each fluid step) and the case's parameters.
Reference: the force balance of one sphere in an unbounded fluid at rest,
    m dv/dt = (rho_p - rho_f) V g - 3 pi mu d v (1 + 0.15 Re^0.687),  Re = rho_f v d / mu,
integrated with RK4 (the velocity-time curve), and its terminal velocity (root of the balance).
Checks (one CHECK line each; exit 1 on a FAIL):
  terminal velocity: mean |vz| over the last 20 % of the run vs the root, tolerance 1 %;
  the issue's figure: the root vs 0.1373 m/s (tolerance 0.1 %, a check of the reference itself);
  curve: max |vz(t) - v_ode(t)| over the run, relative to the terminal velocity, tolerance 2 %.
Usage: postProcess.py <d> <rho_p> <rho_f> <nu> <g>   (SI units)
"""
import os
import sys
import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
import foamcase as fc  # noqa: E402

d, rho_p, rho_f, nu, g = map(float, sys.argv[1:6])
mu = rho_f * nu
V = np.pi * d**3 / 6.0
m = rho_p * V

def drag(v):
    re = rho_f * abs(v) * d / mu
    return 3.0 * np.pi * mu * d * v * (1.0 + 0.15 * re**0.687)

def accel(v):
    return ((rho_p - rho_f) * V * g - drag(v)) / m

# terminal velocity: bisection on the force balance
lo, hi = 0.0, 10.0
for _ in range(200):
    mid = 0.5 * (lo + hi)
    lo, hi = (mid, hi) if accel(mid) > 0 else (lo, mid)
v_term = 0.5 * (lo + hi)

data = fc.table("postProcessing/particles.dat")
t, vz = data[:, 0], -data[:, 7]

# the ODE on the run's own times (RK4 with a step well below the relaxation time)
t_ode = np.linspace(0.0, t[-1], 20001)
v_ode = np.zeros_like(t_ode)
h = t_ode[1] - t_ode[0]
for k in range(len(t_ode) - 1):
    v = v_ode[k]
    k1 = accel(v); k2 = accel(v + 0.5 * h * k1); k3 = accel(v + 0.5 * h * k2); k4 = accel(v + h * k3)
    v_ode[k + 1] = v + h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4)

checks = fc.Checks()
tail = t >= 0.8 * t[-1]
checks.relative("terminal_velocity", float(np.mean(vz[tail])), v_term, 1.0)
checks.relative("schiller_naumann_reference", v_term, 0.1373, 0.1)
checks.deviation("velocity_curve", np.max(np.abs(vz - np.interp(t, t_ode, v_ode))) / v_term, 2.0)

plt.figure(figsize=(6, 4))
plt.plot(t_ode, v_ode, "k-", label="Schiller-Naumann ODE")
plt.plot(t, vz, "r.", ms=2, label="coupled run")
plt.axhline(v_term, color="grey", ls=":", label=f"terminal {v_term:.4f} m/s")
plt.xlabel("time [s]"); plt.ylabel("settling velocity [m/s]")
plt.title(f"settling sphere d = {d*1e6:.0f} um")
plt.legend(); plt.tight_layout(); plt.savefig("settling.png", dpi=120)
print("wrote settling.png")
sys.exit(1 if checks.failed else 0)
