#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Render GYOTO's Page-Thorne (Novikov-Thorne) thin-disk example and write a reference image.

Usage: /usr/bin/python3 bench/gyoto/gyoto_disk.py [N=128] [--spin 0] [--threads 2]
           [--repeat 1] [--extras] [--out-dir bench/gyoto/out] [--png-dir /tmp]

Scene: GYOTO 1.4.4's example-page-thorne-disk-BL.xml (package libgyoto8, found at run time),
unchanged except Resolution = N and nThreads. --spin a != 0 rewrites <Spin> in the XML text
before it is parsed (copy in /tmp), so that the disk's InnerRadius is recomputed as the ISCO
of a; setting Metric Spin after loading would leave InnerRadius at 6 (checked).

Quantity: PageThorneDisk's only image quantity, User4 (the default; "Intensity" throws
"unimplemented"): frequency-integrated intensity I_obs = g^4 * F(r)/pi, with g = nu_obs/nu_em
and F the Page-Thorne flux for Mdot = 1, M = 1 (geometric units: multiply by
Mdot c^6 / (G^2 M^2) for cgs). Checked to 1e-14 against F(r)/pi * g^4 from the hit radius and
GYOTO's Redshift. BlackbodyMdot/BlackBody play no part in User4.

Orientation (how it was established): GYOTO's Screen::getRayCoord(i, j) (1-based) uses
equatorial angles alpha = -(i - (N+1)/2) fov/N, delta = (j - (N+1)/2) fov/N, and
Python's rayTrace() returns arrays indexed [j-1, i-1] (checked by tracing a single row j with
gyoto.util.rayTrace(j=...)). With the Screen set by <Position> (PALN = pi), pixel (1, 1) launches
a photon with dtheta/dt < 0 and dphi/dt > 0, i.e. it arrives moving north and towards +phi,
so the source is seen below (-z side) and on the -e_phi side. The observer looks along -e_r
with the spin axis (+z, i.e. -e_theta) up, so its right is e_r x e_theta = +e_phi: pixel (1, 1)
is BOTTOM-LEFT. Confirmed on the image: impact phi ~ 0 (near side of the disk) in array row 0,
phi ~ pi (far side) in the last row; phi ~ -pi/2 (approaching side, Redshift > 1) in column 0.
So GYOTO's array is [row 0 = bottom, column 0 = left] (matplotlib origin='lower', as GYOTO's own
plot-Image.py shows it), and the raw file is that array with its rows reversed:
row 0 = TOP (spin axis up), column 0 = LEFT, as the observer sees the sky. The script re-checks
the pixel (1, 1) direction at run time and stops if it differs.

Outputs (N = resolution, S = spin):
  <out-dir>/gyoto_disk_a<S>_n<N>.f64   N*N little-endian float64, row-major, row 0 = top
  <out-dir>/gyoto_disk_a<S>_n<N>.json  scene parameters, conventions, timing
  <png-dir>/gyoto_disk_a<S>_n<N>.png   preview (PGM if matplotlib is missing)
  with --extras also ..._redshift.f64 (g) and ..._rhit.f64 (BL r of the hit, 0 = no hit).
Timing: wall time of Scenery.rayTrace() alone (fastest of --repeat); cpu_seconds = process CPU
time of the same call (all threads), less sensitive to other jobs on the machine.
"""
import argparse
import glob
import json
import math
import os
import re
import time

import numpy as np
import gyoto.core
import gyoto.std  # registers KerrBL and PageThorneDisk

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLE = "example-page-thorne-disk-BL.xml"


def find_example():
    for pat in ("/usr/share/doc/libgyoto*/examples/", "/usr/share/doc/gyoto*/examples/",
                "/usr/share/gyoto*/examples/"):
        for d in sorted(glob.glob(pat)):
            for name in (EXAMPLE, EXAMPLE + ".gz"):
                if os.path.exists(os.path.join(d, name)):
                    return os.path.join(d, name)
    raise SystemExit(f"{EXAMPLE} not found (apt-get install libgyoto8 gyoto-doc)")


def read_text(path):
    if path.endswith(".gz"):
        import gzip
        with gzip.open(path, "rt") as f:
            return f.read()
    with open(path) as f:
        return f.read()


def isco(a):
    z1 = 1 + (1 - a * a) ** (1 / 3) * ((1 + a) ** (1 / 3) + (1 - a) ** (1 / 3))
    z2 = math.sqrt(3 * a * a + z1 * z1)
    return 3 + z2 - math.sqrt((3 - z1) * (3 + z1 + 2 * z2))


def load(spin):
    src = find_example()
    text = read_text(src)
    if spin != 0.0:
        text, k = re.subn(r"<Spin>\s*[-+0-9.eE]+\s*</Spin>", f"<Spin> {spin!r} </Spin>", text)
        if k != 1:
            raise SystemExit("could not find <Spin> in the example XML")
    path = f"/tmp/gyoto_disk_a{spin:g}.xml"
    with open(path, "w") as f:
        f.write(text)
    return src, gyoto.core.Factory(path).scenery()


def check_orientation(scr, metric):
    """Pixel (1, 1) must be bottom-left: photon arrives with dtheta < 0 and dphi > 0."""
    c = np.zeros(8)
    scr.getRayCoord(1, 1, c)
    pos = np.zeros(4)
    scr.getObserverPos(pos)
    if not (c[6] < 0 and c[7] > 0 and 0 < pos[2] < math.pi / 2 and scr.get("AngleKind") == "EquatorialAngles"):
        raise SystemExit(f"unexpected Screen orientation: pixel (1,1) -> {c}")
    # launch normalisation: -p.u for a static observer at the screen (1 for a = 0)
    gtt, gtp = metric.gmunu(c[:4], 0, 0), metric.gmunu(c[:4], 0, 3)
    e_inf = -(gtt * c[4] + gtp * c[7])
    return e_inf, e_inf / math.sqrt(-gtt)


def write_preview(path_noext, img):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6, 5.2))
        im = ax.imshow(img, origin="upper", cmap="inferno", interpolation="nearest")
        ax.set_title("GYOTO PageThorneDisk User4 (row 0 = top, spin axis up)")
        ax.set_xlabel("column (left -> right as seen)")
        ax.set_ylabel("row (top -> bottom)")
        fig.colorbar(im, ax=ax)
        fig.savefig(path_noext + ".png", dpi=100)
        plt.close(fig)
        return path_noext + ".png"
    except ImportError:
        v = np.clip(img / img.max() * 255, 0, 255).astype(np.uint8) if img.max() > 0 else img.astype(np.uint8)
        with open(path_noext + ".pgm", "wb") as f:
            f.write(f"P5\n{img.shape[1]} {img.shape[0]}\n255\n".encode())
            f.write(v.tobytes())
        return path_noext + ".pgm"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("N", nargs="?", type=int, default=128, help="resolution (N x N)")
    ap.add_argument("--spin", type=float, default=0.0, help="Kerr spin a/M (example: 0)")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--repeat", type=int, default=1, help="renders; the fastest is reported")
    ap.add_argument("--extras", action="store_true", help="also write Redshift and hit radius")
    ap.add_argument("--out-dir", default=os.path.join(HERE, "out"))
    ap.add_argument("--png-dir", default="/tmp")
    args = ap.parse_args()

    gyoto.core.verbose(0)
    src, sc = load(args.spin)
    scr, metric, disk = sc.screen(), sc.metric(), sc.astrobj()
    n = args.N
    scr.resolution(n)
    sc.nThreads(args.threads)
    if args.extras:
        sc.requestedQuantitiesString("User4 Redshift User2")  # User2 = r of the hit (ThinDisk)
    assert "User4" in sc.requestedQuantitiesString().split()
    rin = disk.get("InnerRadius")
    if abs(rin - isco(args.spin)) > 1e-9:
        raise SystemExit(f"InnerRadius {rin} is not the ISCO {isco(args.spin)}")
    e_inf, e_static = check_orientation(scr, metric)

    times, cpu = [], []
    for _ in range(args.repeat):
        t0, c0 = time.perf_counter(), time.process_time()
        res = sc.rayTrace()
        times.append(time.perf_counter() - t0)
        cpu.append(time.process_time() - c0)
    seconds = min(times)

    img = np.ascontiguousarray(np.asarray(res["User4"])[::-1, :])  # GYOTO row 0 = bottom -> top
    os.makedirs(args.out_dir, exist_ok=True)
    base = os.path.join(args.out_dir, f"gyoto_disk_a{args.spin:g}_n{n}")
    img.astype("<f8").tofile(base + ".f64")
    extras = {}
    if args.extras:
        for key, suffix in (("Redshift", "_redshift"), ("User2", "_rhit")):
            a = np.ascontiguousarray(np.asarray(res[key])[::-1, :])
            a.astype("<f8").tofile(base + suffix + ".f64")
            extras[key] = base + suffix + ".f64"
    preview = write_preview(os.path.join(args.png_dir, f"gyoto_disk_a{args.spin:g}_n{n}"), img)

    pos = np.zeros(4)
    scr.getObserverPos(pos)
    fov = scr.fieldOfView()
    half = n // 2
    meta = {
        "image": base + ".f64", "dtype": "<f8", "shape": [n, n], "preview": preview, "extras": extras,
        "orientation": "row-major, row 0 = TOP, column 0 = LEFT as the observer sees the sky; "
                       "spin axis +z projects UP; right = +e_phi at the observer (GYOTO array "
                       "[j-1, i-1] has row 0 at the bottom, so its rows were reversed)",
        "pixel_angles": "column c, row r (0-based, from left/top): x = (c + 0.5 - N/2) fov/N "
                        "(+ = right), y = (N/2 - r - 0.5) fov/N (+ = up); arrival direction "
                        "(towards the source) in the observer frame: cos(y) cos(x) (-e_r) + "
                        "cos(y) sin(x) e_phi + sin(y) (-e_theta)  [GYOTO EquatorialAngles: x "
                        "azimuth, y elevation, not a pinhole/tangent-plane projection]",
        "quantity": "User4 = frequency-integrated intensity g^4 F(r)/pi, Page-Thorne F for "
                    "Mdot = M = 1 (x Mdot c^6/(G^2 M^2) for cgs); g = nu_obs/nu_em; 0 = no disk hit",
        "example_xml": src, "gyoto_version": gyoto_version(),
        "metric": metric.kind(), "spin": metric.get("Spin"), "mass_kg": metric.mass(),
        "observer_bl": {"t": pos[0], "r": pos[1], "theta_rad": pos[2], "phi_rad": pos[3]},
        "distance_M": scr.distance() / metric.unitLength(),
        "inclination_deg": math.degrees(pos[2]),
        "inclination_note": "observer polar angle theta from the +z spin axis (observer above the "
                            "disk's prograde side); GYOTO's own Euler angles differ, see below",
        "gyoto_screen_euler_deg": {"PALN": math.degrees(scr.PALN()),
                                   "Inclination": math.degrees(scr.inclination()),
                                   "Argument": math.degrees(scr.argument())},
        "observer": f"{scr.get('ObserverKind')}: p^r = cos(a)/sqrt(g_rr), p^theta = n_theta/sqrt(g_thth), "
                    "p^phi = n_phi/sqrt(g_phph), p^t from p.p = 0 (positive root); a static observer "
                    "at BL r for a = 0 (photon energy 1 in its frame)",
        "photon_E_inf": e_inf, "photon_E_static_observer": e_static,
        "fov_full_deg": math.degrees(fov), "fov_full_rad": fov,
        "rin": disk.get("InnerRadius"), "rin_is_isco": True,
        "rout": disk.get("OuterRadius"), "rout_note": "DBL_MAX: unbounded",
        "disk": {"CoRotating": disk.get("CoRotating"), "OpticallyThin": disk.get("OpticallyThin"),
                 "BlackbodyMdot": disk.get("BlackbodyMdot"), "RMax": disk.get("RMax"),
                 "DeltaMaxInsideRMax": disk.get("DeltaMaxInsideRMax")},
        "integration": {k: sc.get(k) for k in ("Integrator", "AbsTol", "RelTol", "Delta", "DeltaMin",
                                               "DeltaMax", "DeltaMaxOverR", "MaxIter", "MinimumTime")},
        "screen_time_M": pos[0],
        "resolution": n, "threads": args.threads, "seconds": round(seconds, 4),
        "all_seconds": [round(t, 4) for t in times], "rays_per_second": round(n * n / seconds, 1),
        "cpu_seconds": round(min(cpu), 4), "cpu_note": "process CPU time of rayTrace, all threads",
        "stats": {"max": float(img.max()), "sum": float(img.sum()), "hit_pixels": int((img > 0).sum()),
                  "left_half_sum": float(img[:, :half].sum()), "right_half_sum": float(img[:, half:].sum()),
                  "top_half_sum": float(img[:half].sum()), "bottom_half_sum": float(img[half:].sum())},
        "load_avg_1min": os.getloadavg()[0],
    }
    with open(base + ".json", "w") as f:
        json.dump(meta, f, indent=1)
    print(json.dumps({k: meta[k] for k in ("image", "preview", "spin", "resolution", "seconds",
                                           "cpu_seconds", "rays_per_second", "stats")}))


def gyoto_version():
    import subprocess
    try:
        out = subprocess.run(["dpkg-query", "-W", "-f=${Version}", "libgyoto8"],
                             capture_output=True, text=True).stdout.strip()
        return f"{out.split('-')[0]} (Debian libgyoto8 {out})" if out else "unknown"
    except OSError:
        return "unknown"


if __name__ == "__main__":
    main()
