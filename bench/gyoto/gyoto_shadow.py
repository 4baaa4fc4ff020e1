#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Render kerr_ks_shadow.xml with GYOTO (Python Scenery, 2 threads) and write its shadow mask.

A pixel is in the shadow when its ray (traced backwards from the screen) ended at GYOTO's
numerical horizon. GYOTO records MinDistance = min over steps inside RMax of x^2 + y^2 + z^2
(Cartesian Kerr-Schild coordinates). A captured ray stops at r ~ r+ + HorizonSecurity, where
x^2 + y^2 + z^2 = r^2 + a^2 sin^2(theta) <= (r+ + 2 HorizonSecurity)^2 + a^2 = C, while an
escaping ray never gets closer than the smallest R^2 on a spherical photon orbit (= 9 for
a = 0, 3.225 for a = 0.9). The cut is halfway; gap_pixels counts pixels between the two bounds
(0 means the classification is unambiguous). Refuses spins above about 0.96 (no gap left).

Mask: plain PGM (P2, maxval 1, 1 = shadow), rows top to bottom and columns left to right as
seen by the observer (spin axis +z up; the observer sits at -y, so +x is on the right).
GYOTO's own arrays are [j-1, i-1] with j = 1 at the top and i = 1 on the observer's right,
i.e. mirrored left-right; the mask is GYOTO's array with its columns reversed.
Timing: wall time of Scenery.rayTrace() only, fastest of --repeat renders; cpu_seconds is the
process CPU time of the same call (all threads), less sensitive to other jobs on the machine.
bardeen_mismatch: pixels that differ from Bardeen's analytic edge-on shadow seen from infinity.
One JSON object per line on stdout; the first one describes the camera.
"""
import argparse
import json
import math
import os
import time

import numpy as np
import gyoto.core
import gyoto.std  # registers KerrKS and FixedStar

HERE = os.path.dirname(os.path.abspath(__file__))


def photon_orbits(a):
    """Spherical photon orbits of Kerr (M = 1, a > 0): radius r, xi = L/E, eta = Q/E^2."""
    r_pro, r_retro = (2 * (1 + math.cos(2 / 3 * math.acos(s * a))) for s in (-1, 1))
    r = np.linspace(r_pro, r_retro, 200001)[1:-1]
    xi = -(r**3 - 3 * r**2 + a * a * r + a * a) / (a * (r - 1))
    eta = -r**3 * (r**3 - 6 * r**2 + 9 * r - 4 * a * a) / (a * a * (r - 1) ** 2)
    return r, xi, eta


def escape_min_r2(a):
    """Smallest x^2 + y^2 + z^2 reached on a spherical photon orbit."""
    if a < 1e-8:
        return 9.0
    r, xi, eta = photon_orbits(a)
    b = a * a - eta - xi**2
    cos2_max = (b + np.sqrt(b * b + 4 * a * a * eta)) / (2 * a * a)  # turning latitude
    return float(np.min(r**2 + a * a * (1 - cos2_max)))


def bardeen_mask(a, n, pixel_M):
    """Edge-on shadow seen from infinity (Bardeen 1973), same layout as the mask:
    alpha = -xi to the right, beta = +-sqrt(eta) up, pixel centres as in the camera."""
    k = (np.arange(n) + 0.5 - n / 2) * pixel_M
    alpha, beta = k[None, :], -k[:, None]
    if a < 1e-8:
        return alpha**2 + beta**2 < 27
    _, xi, eta = photon_orbits(a)
    edge = np.interp(alpha, -xi, np.sqrt(eta), left=-1, right=-1)  # -xi increases with r
    return np.abs(beta) < edge


def camera(scenery):
    scr, m = scenery.screen(), scenery.metric()
    pos = np.zeros(4)
    scr.getObserverPos(pos)
    n, fov = scr.resolution(), scr.fieldOfView()
    return {"observer_ks_cartesian_M": [float(v) for v in pos[1:]],
            "distance_M": scr.distance() / m.unitLength(),
            "fov_rad": fov, "pixel_rad": fov / n,
            "pixel_centres": "offset (k + 0.5 - N/2) * fov/N, k = 0..N-1, from the left column / top row",
            "view": "looking along +y, up = +z (spin axis), right = +x",
            "observer_kind": scr.get("ObserverKind"), "angle_kind": scr.get("AngleKind")}


def write_pgm(path, mask):
    with open(path, "w") as f:
        f.write(f"P2\n# shadow mask, 1 = ray ended at the horizon; observer's view, row 0 = top\n"
                f"{mask.shape[1]} {mask.shape[0]}\n1\n")
        for row in mask:
            f.write(" ".join(str(int(v)) for v in row) + "\n")


def render(xml, spin, n, tol, rmax, threads, repeat, out_dir):
    scenery = gyoto.core.Factory(xml).scenery()
    metric, star = scenery.metric(), scenery.astrobj()
    metric.set("Spin", spin)
    scenery.screen().resolution(n)
    scenery.relTol(tol)
    scenery.absTol(tol)
    star.set("RMax", rmax)
    scenery.nThreads(threads)

    r_plus = 1 + math.sqrt(1 - spin * spin)
    captured_max = (r_plus + 2 * metric.get("HorizonSecurity")) ** 2 + spin * spin
    escaped_min = escape_min_r2(spin)
    if not captured_max < escaped_min < rmax * rmax:
        raise SystemExit(f"MinDistance cannot separate captured from escaping rays at spin {spin}")
    cut = 0.5 * (captured_max + escaped_min)

    times, cpu = [], []
    for _ in range(repeat):  # the fastest of `repeat` identical renders (other jobs share the CPUs)
        t0, c0 = time.perf_counter(), time.process_time()
        result = scenery.rayTrace()
        times.append(time.perf_counter() - t0)
        cpu.append(time.process_time() - c0)
    seconds = min(times)

    dmin = np.asarray(result["MinDistance"])  # [j-1, i-1]
    gap = int(np.count_nonzero((dmin > captured_max) & (dmin < escaped_min)))
    mask = (dmin < cut)[:, ::-1]  # observer's view: column 0 = left = -x
    os.makedirs(out_dir, exist_ok=True)
    path = os.path.join(out_dir, f"gyoto_shadow_a{spin:g}_n{n}_tol{tol:g}.pgm")
    write_pgm(path, mask)
    cols = np.nonzero(mask)[1]
    pixel_M = scenery.screen().fieldOfView() / n * scenery.screen().distance() / metric.unitLength()
    bardeen = int(np.count_nonzero(mask != bardeen_mask(spin, n, pixel_M)))
    return scenery, {"spin": spin, "resolution": n, "tolerance": tol, "seconds": round(seconds, 4),
                     "rays_per_second": round(n * n / seconds, 1),
                     "all_seconds": [round(t, 4) for t in times],
                     "cpu_seconds": round(min(cpu), 4),
                     "rays_per_cpu_second": round(n * n / min(cpu), 1), "shadow_pixels": int(mask.sum()),
                     "mask": os.path.abspath(path), "threads": threads, "rmax": rmax,
                     "cut_R2": cut, "gap_pixels": gap, "bardeen_mismatch": bardeen,
                     "centroid_right_px": float(cols.mean() - (n - 1) / 2) if cols.size else None,
                     "load_avg_1min": os.getloadavg()[0]}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--xml", default=os.path.join(HERE, "kerr_ks_shadow.xml"))
    ap.add_argument("--spin", nargs="+", type=float, default=[0.0, 0.9])
    ap.add_argument("--resolution", type=int, default=128)
    ap.add_argument("--tol", nargs="+", type=float, default=[1e-8], help="RelTol = AbsTol")
    ap.add_argument("--rmax", type=float, default=10.0,
                    help="Astrobj RMax in M: MinDistance is tracked inside it, outgoing rays stop beyond it")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--repeat", type=int, default=3, help="renders per row; the fastest is reported")
    ap.add_argument("--out-dir", default=os.path.join(HERE, "out"))
    args = ap.parse_args()

    gyoto.core.verbose(0)  # no per-row progress or thread messages
    first = True
    for spin in args.spin:
        for tol in args.tol:
            scenery, row = render(args.xml, spin, args.resolution, tol, args.rmax, args.threads, args.repeat, args.out_dir)
            if first:
                print(json.dumps({"camera": camera(scenery)}), flush=True)
                first = False
            print(json.dumps(row), flush=True)


if __name__ == "__main__":
    main()
