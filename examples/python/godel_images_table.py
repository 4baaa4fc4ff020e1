#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Every image of a point in the Goedel universe, as a table (the inverse problem, docs/PHYSICS.md
section 3): the observer on the axis, a point at cylindrical (r, phi, z) = (1.0 a, 0.7, 0.3 a).

    PYTHONPATH=build/python python3 examples/python/godel_images_table.py [WINDINGS]

Each image is a closed-form null geodesic from the observer to the point: its winding and branch,
the direction it is seen in (psi from the axis, phi), when the light left (t) and the frequency
ratio. The first row is docs/PHYSICS.md's worked example: t = -0.931438, psi = 1.294019 rad.
Exits 1 if that row disagrees."""
import math
import sys

import lightcone

windings = int(sys.argv[1]) if len(sys.argv) > 1 else 3
r, phi, z = 1.0, 0.7, 0.3
result = lightcone.godel_images(a=1.0, point=[r * math.cos(phi), r * math.sin(phi), z], windings=windings)
print(f"status: {result['status']}, {len(result['images'])} images for windings 0 to {windings}")
print("| winding | branch | psi (deg) | phi (deg) | emission t | nu_obs/nu_em | affine length |")
print("|---|---|---|---|---|---|---|")
for im in result["images"]:
    print(f"| {im['winding']} | {im['branch']} | {math.degrees(im['psi']):.4f} | {math.degrees(im['phi0']):.4f} | "
          f"{im['emission_time']:.6f} | {im['frequency_ratio']:.6f} | {im['affine']:.4f} |")

first = min((im for im in result["images"] if im["winding"] == 0 and im["branch"] == "outbound"),
            key=lambda im: im["affine"])
ok = abs(first["emission_time"] + 0.931438) < 1e-5 and abs(first["psi"] - 1.294019) < 1e-5
print("worked example:", "matches" if ok else "DIFFERS", f"(t = {first['emission_time']:.6f})")
sys.exit(0 if ok else 1)
