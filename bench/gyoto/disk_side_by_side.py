#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""GYOTO's Page-Thorne image beside Lightcone's (written by ./build/bench/bench_gyoto_disk) and their
relative difference, as one PNG: /usr/bin/python3 bench/gyoto/disk_side_by_side.py [N=128] [--spin 0.9]
[--out docs/images/disk_vs_gyoto.png]."""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__)
parser.add_argument("n", nargs="?", type=int, default=128)
parser.add_argument("--spin", type=float, default=0.9)
parser.add_argument("--out", default="docs/images/disk_vs_gyoto.png")
args = parser.parse_args()

stem = "bench/gyoto/out/gyoto_disk_a%g_n%d" % (args.spin, args.n)
gyoto = np.fromfile(stem + ".f64", dtype="<f8").reshape(args.n, args.n)
ours = np.fromfile(stem + "_lightcone.f64", dtype="<f8").reshape(args.n, args.n)
both = (gyoto > 0) & (ours > 0)
rel = np.full(gyoto.shape, np.nan)
rel[both] = np.abs(gyoto[both] / ours[both] - 1)

top = max(gyoto.max(), ours.max())
fig, axes = plt.subplots(1, 3, figsize=(12, 4.8))
for ax, image, title in ((axes[0], gyoto, "GYOTO 1.4.4 (RKF78, 1e-6)"), (axes[1], ours, "Lightcone (dopri5, 1e-12)")):
    ax.imshow(np.sqrt(image / top), cmap="inferno", origin="upper", vmin=0, vmax=1)
    ax.set_title(title + "\n$\\sqrt{g^4 F / \\pi}$, a = %g, i = 69.9°" % args.spin, fontsize=10)
    ax.set_xticks([])
    ax.set_yticks([])
shown = axes[2].imshow(np.log10(np.maximum(rel, 1e-9)), cmap="viridis", origin="upper", vmin=-9, vmax=-3)
axes[2].set_title("log10 |GYOTO / Lightcone - 1|\nmedian %.1e" % np.nanmedian(rel), fontsize=10)
axes[2].set_xticks([])
axes[2].set_yticks([])
fig.colorbar(shown, ax=axes[2], fraction=0.046)
fig.tight_layout(rect=(0, 0, 1, 0.97))
fig.savefig(args.out, dpi=90)
print("wrote", args.out)
