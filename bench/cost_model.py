#!/usr/bin/env python3
"""The parallel DEM's cost model (issue 23; docs/parallel_cost_model.md explains it).

A rank holds n = N / P particles of a dense bed in a cube of side L = (n / rho_n)^(1/3); its halo
is the shell of width c (the list cutoff) around it, g = rho_n ((L + 2c)^3 - L^3) ghosts. Per
step it sends and receives each ghost's position, velocity and spin (72 B) and the force and
torque back (48 B), in up to 26 messages each way, and joins one all-reduce (the rebuild
decision). Its contacts cost n t_pair and the rest of its step n t_rest. Two costs of the code as it
is grow with P itself, once per list rebuild (every `rebuild` steps): the counts before each
message round are an all-to-all (2 per rebuild, P latencies each), and a particle near its box's
border is tested against every other box (P tests of t_box each); they are given apart, since both
have a known cure (counts from the neighbours only; a walk down the bisection tree).

usage: bench/cost_model.py [--particles N] [--t-pair S] [--t-rest S] [--latency S] [--bandwidth B/S]
                           [--diameter M] [--cutoff M] [--solid-fraction F]
Defaults: the 50k bench's bed (d = 5 mm, cutoff 2 r + skin = 6 mm, solid fraction 0.6) and its
measured serial costs; a cluster's network of 2 us latency and 10 GB/s per rank (InfiniBand class).
"""
import argparse
import math

ap = argparse.ArgumentParser()
ap.add_argument("--particles", type=float, default=1e7)
ap.add_argument("--t-pair", type=float, default=81e-9, help="pair contacts per particle-step [s] (50k settled, serial)")
ap.add_argument("--t-rest", type=float, default=25e-9, help="integration, lists, walls per particle-step [s] (the same)")
ap.add_argument("--latency", type=float, default=2e-6)
ap.add_argument("--bandwidth", type=float, default=1e10)
ap.add_argument("--diameter", type=float, default=5e-3)
ap.add_argument("--cutoff", type=float, default=6e-3)
ap.add_argument("--solid-fraction", type=float, default=0.6)
ap.add_argument("--bytes-per-ghost", type=float, default=120.0)
ap.add_argument("--rebuild", type=float, default=36.0, help="steps between list rebuilds (50k settling: 20000 / 559)")
ap.add_argument("--t-box", type=float, default=3e-9, help="one particle-box distance test [s]")
a = ap.parse_args()

rho = a.solid_fraction / (math.pi * a.diameter**3 / 6)   # particles per m^3


def per_rank(P):
    n = a.particles / P
    L = (n / rho) ** (1 / 3)
    g = rho * ((L + 2 * a.cutoff) ** 3 - L**3)
    neighbours = 26 if P >= 27 else (P - 1)
    t_msgs = 2 * neighbours * a.latency + 2 * g * a.bytes_per_ghost / a.bandwidth
    t_reduce = a.latency * math.ceil(math.log2(P)) if P > 1 else 0.0
    border = g / 2.0   # own particles within the cutoff of the box's faces: about half the ghosts' shell
    t_grow = (2 * P * a.latency + border * P * a.t_box) / a.rebuild if P > 1 else 0.0
    return n, L, g, t_msgs + t_reduce, n * a.t_pair, n * a.t_rest, t_grow


print(f"N = {a.particles:.3g} particles, d = {a.diameter * 1e3:g} mm, cutoff {a.cutoff * 1e3:g} mm, "
      f"solid fraction {a.solid_fraction}; t_pair {a.t_pair * 1e9:.0f} ns, t_rest {a.t_rest * 1e9:.0f} ns per "
      f"particle-step; latency {a.latency * 1e6:g} us, bandwidth {a.bandwidth / 1e9:g} GB/s")
print("per rank and step (the cube model: every face of the box borders another rank, so P < 27 is overestimated):")
print(f"{'ranks':>7} {'particles':>10} {'box side':>9} {'ghosts':>9} {'g/n':>6} {'exchange':>10} {'+P terms':>10} "
      f"{'contacts':>10} {'step':>10} {'efficiency':>10}")
serial = a.particles * (a.t_pair + a.t_rest)
for P in [1, 2, 8, 64, 128, 256, 512, 1000, 2000, 4000, 8000, 16000]:
    n, L, g, t_x, t_c, t_r, t_g = per_rank(P)
    if P == 1:
        g, t_x = 0.0, 0.0
    step = t_x + t_g + t_c + t_r
    print(f"{P:>7} {n:>10.4g} {L * 1e3:>7.1f}mm {g:>9.4g} {g / n:>6.3f} {t_x * 1e6:>8.1f}us {t_g * 1e6:>8.1f}us "
          f"{t_c * 1e6:>8.1f}us {step * 1e6:>8.1f}us {serial / P / step:>10.3f}")


def crossing(with_growth):
    lo, hi = 2, 10**7
    while hi - lo > 1:   # the rank count where the exchange first costs more than the contacts
        mid = (lo + hi) // 2
        n, L, g, t_x, t_c, t_r, t_g = per_rank(mid)
        if t_x + (t_g if with_growth else 0.0) > t_c:
            hi = mid
        else:
            lo = mid
    return hi, per_rank(hi)


for label, grow in [("as built (counts all-to-all, every box tested)", True), ("with both cures", False)]:
    P, (n, L, g, t_x, t_c, t_r, t_g) = crossing(grow)
    print(f"{label}: the exchange costs more than the contacts from {P} ranks on ({n:.4g} particles and "
          f"{g:.4g} ghosts per rank; exchange {(t_x + (t_g if grow else 0)) * 1e6:.1f} us, contacts {t_c * 1e6:.1f} us "
          f"per step)")
