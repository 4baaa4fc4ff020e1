#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Schwarzschild light deflection with GYOTO's integrators: error against cost.

Run with /usr/bin/python3 (the interpreter that has GYOTO's bindings). Metric: GYOTO's KerrKS
(Cartesian Kerr-Schild, ingoing) with spin 0; lengths in units of M. Each ray starts at
x = -D, z = 0 with covariant momentum p = (-E, 1, 0, 0) (moving along +x), y = b E found by
fixed-point iteration so that L/E = b exactly, E from the null condition with GYOTO's own
inverse metric. Photon.xFill(2 D + 10 ln D + 100) integrates forward in time; GYOTO stops at
the first step past that time, once the ray is back out at r > D (end_radius is printed).

deflection = accumulated signed turning of the covariant spatial momentum p_i over GYOTO's
stored steps (same measure as Lightcone's measureDeflection, exceeds pi for the grazer).
exact = the D = infinity value (Darwin's elliptic integral, Carlson R_F, double precision);
exact_at_ends = the same turning measure, exact, between the actual start and end radii
(differs from exact by O(M b / D^2): ~1e-11 at D = 1e6, ~1e-5 at D = 1e3).
Steps = accepted steps (stored points - 1); rejected trial steps are not visible.
us_per_ray = wall time of setInitialCondition + xFill, 1 thread: average over a batch of
>= min-seconds, fastest of --repeat batches (cpu_us_per_ray: the same in process CPU time).
One JSON object per line on stdout.
"""
import argparse
import json
import math
import os
import time

import numpy as np
import gyoto.core
import gyoto.std

GRAZER = 3 * math.sqrt(3) * (1 + 1e-3)


def carlson_rf(x, y, z):
    """Carlson's symmetric elliptic integral R_F (duplication + DLMF 19.36.1 series)."""
    while True:
        a = (x + y + z) / 3
        dx, dy = 1 - x / a, 1 - y / a
        if max(abs(dx), abs(dy), abs(dx + dy)) < 1e-4:
            break
        sx, sy, sz = math.sqrt(x), math.sqrt(y), math.sqrt(z)
        lam = sx * sy + sy * sz + sz * sx
        x, y, z = (x + lam) / 4, (y + lam) / 4, (z + lam) / 4
    dz = -dx - dy
    e2, e3 = dx * dy - dz * dz, dx * dy * dz
    return (1 - e2 / 10 + e3 / 14 + e2 * e2 / 24 - 3 * e2 * e3 / 44) / math.sqrt(a)


def orbit_roots(b):
    """Roots u1 < 0 < u0 <= u3 of P(u) = 2u^3 - u^2 + 1/b^2 (u = M/r, u0 = 1/r_min)."""
    r = b  # Newton on r^3 - b^2 r + 2 b^2 = 0 from above: converges to r_min
    for _ in range(100):
        step = (r**3 - b * b * r + 2 * b * b) / (3 * r * r - b * b)
        r -= step
        if abs(step) < 1e-15 * r:
            break
    u0 = 1 / r
    p = u0 - 0.5  # P = 2 (u - u0)(u^2 + p u + u0 p)
    s = math.sqrt(p * p - 4 * u0 * p)
    return (-p - s) / 2, u0, (-p + s) / 2


def half_sweep(b, u):
    """Azimuth swept from u = M/r to the turning point: int_u^u0 du / sqrt(P(u))."""
    u1, u0, u3 = orbit_roots(b)
    y1, y2, y3 = math.sqrt(u - u1), math.sqrt(u0 - u), math.sqrt(u3 - u)
    x1, x3, h = math.sqrt(u0 - u1), math.sqrt(u3 - u0), u0 - u
    return math.sqrt(2) * carlson_rf((y1 * y2 * x3 / h) ** 2, (x1 * x3 * y2 / h) ** 2, (y2 * y3 * x1 / h) ** 2)


def exact_deflection(b):
    return 2 * half_sweep(b, 0.0) - math.pi


def exact_turning(b, r_start, r_end):
    """Exact turning of the covariant spatial momentum (ingoing Kerr-Schild, E = 1, L = b)."""
    def p_bl(r):
        return math.sqrt(1 - (1 - 2 / r) * b * b / (r * r)) / (1 - 2 / r)
    p_in = -p_bl(r_start) + 2 / (r_start - 2)  # p_r(KS) = p_r(BL) + 2 M E / (r - 2 M)
    p_out = p_bl(r_end) + 2 / (r_end - 2)
    sweep = half_sweep(b, 1 / r_start) + half_sweep(b, 1 / r_end)
    return sweep + math.atan2(b / r_end, p_out) - math.atan2(b / r_start, p_in)


def start_state(metric, b, distance):
    """8-coordinate (t, x, y, z, contravariant 4-velocity) of a ray with L/E = b exactly."""
    gu = np.zeros((4, 4))
    y = b
    for _ in range(50):
        x = np.array([0.0, -distance, y, 0.0])
        metric.gmunu_up(gu, x)
        a, c, d = gu[0, 0], gu[0, 1], gu[1, 1]  # a E^2 - 2 c E + d = 0 for p = (-E, 1, 0, 0)
        energy = max(r for r in ((c + sg * math.sqrt(c * c - a * d)) / a for sg in (1, -1))
                     if -a * r + c > 0)  # future directed: u^t = -a E + c > 0
        if abs(b * energy - y) <= 1e-16 * b:
            break
        y = b * energy
    x = np.array([0.0, -distance, y, 0.0])
    metric.gmunu_up(gu, x)
    return np.concatenate([x, gu @ np.array([-energy, 1.0, 0.0, 0.0])])


def turning(metric, photon):
    """Signed turning of the covariant spatial momentum over the stored points."""
    n = photon.get_nelements()
    arrays = [np.zeros(n) for _ in range(8)]
    photon.get_t(arrays[0])
    photon.get_xyz(*arrays[1:4])
    photon.get_dot(*arrays[4:])
    pts = np.array(arrays).T
    gl = np.zeros((4, 4))
    dirs = []
    for q in pts:
        metric.gmunu(gl, q[:4])
        p = gl @ q[4:]
        dirs.append(p[1:] / np.linalg.norm(p[1:]))
    normal = np.cross(pts[0, 1:4], dirs[0])
    normal /= np.linalg.norm(normal)
    total = sum(math.atan2(np.dot(np.cross(d0, d1), normal), np.dot(d0, d1)) for d0, d1 in zip(dirs, dirs[1:]))
    return abs(total), n - 1, math.sqrt(pts[-1, 1] ** 2 + pts[-1, 2] ** 2 + pts[-1, 3] ** 2)


def run(metric, b, distance, integrator, tol, min_seconds, repeat):
    coord = start_state(metric, b, distance)
    ph = gyoto.core.Photon()
    ph.metric(metric)
    ph.integrator(integrator)
    if tol is not None:
        ph.absTol(tol)
        ph.relTol(tol)
    tlim = 2 * distance + 10 * math.log(distance) + 100  # past the Shapiro delay: ends at r > D

    def one():
        ph.setInitialCondition(metric, coord, 1)
        ph.xFill(tlim)

    one()
    defl, steps, r_end = turning(metric, ph)
    batches, cpu = [], []
    for _ in range(repeat):  # fastest batch average (other jobs share the CPUs)
        rays, t0, c0 = 0, time.perf_counter(), time.process_time()
        while rays < 3 or time.perf_counter() - t0 < min_seconds:
            one()
            rays += 1
        batches.append(1e6 * (time.perf_counter() - t0) / rays)
        cpu.append(1e6 * (time.process_time() - c0) / rays)
    us = min(batches)
    assert ph.get_nelements() == steps + 1  # every timed ray redid the same integration
    r_start = math.hypot(distance, coord[2])
    exact = exact_deflection(b)
    exact_ends = exact_turning(b, r_start, r_end) if r_end > 0.5 * distance else math.nan  # nan: lost
    return {"b": b, "distance": distance, "tolerance": tol, "integrator": integrator, "deflection": defl,
            "steps": steps, "us_per_ray": round(us, 2), "cpu_us_per_ray": round(min(cpu), 2),
            "rays_timed": rays, "exact": exact,
            "error": defl - exact, "exact_at_ends": exact_ends, "error_at_ends": defl - exact_ends,
            "end_radius": r_end, "load_avg_1min": os.getloadavg()[0]}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--b", nargs="+", default=["6", "10", "20", "grazer"],
                    help="impact parameters in M; 'grazer' = 3 sqrt(3) (1 + 1e-3)")
    ap.add_argument("--distance", nargs="+", type=float, default=[1e6, 1e3], help="start distance D in M")
    ap.add_argument("--tol", nargs="+", type=float, default=[1e-6, 1e-8, 1e-10, 1e-12], help="AbsTol = RelTol")
    ap.add_argument("--integrators", nargs="+", default=["runge_kutta_fehlberg78", "Legacy"],
                    help="GYOTO Integrator names; Legacy ignores AbsTol/RelTol and is run once")
    ap.add_argument("--min-seconds", type=float, default=0.3, help="length of one timing batch")
    ap.add_argument("--repeat", type=int, default=3, help="timing batches per row; the fastest is reported")
    args = ap.parse_args()

    metric = gyoto.std.KerrKS()
    metric.spin(0.0)
    metric.mass(1.0)  # only sets the unit of length; coordinates are in units of M anyway
    for bs in args.b:
        b = GRAZER if bs == "grazer" else float(bs)
        for distance in args.distance:
            for integrator in args.integrators:
                for tol in [None] if integrator == "Legacy" else args.tol:
                    print(json.dumps(run(metric, b, distance, integrator, tol, args.min_seconds, args.repeat)), flush=True)


if __name__ == "__main__":
    main()
