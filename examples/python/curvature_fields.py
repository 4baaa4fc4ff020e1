#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Curvature and the matter it implies as numpy arrays, from Lightcone's VTK source in Python.

    PYTHONPATH=build/python python3 examples/python/curvature_fields.py

1. Kerr (a = 0.9): the Kretschmann scalar on the x-z plane around the ring singularity
   (vtkLightconeCurvatureSource), against its closed form in Boyer-Lindquist r and theta
   (Henry 2000, ApJ 535, 350, docs/PHYSICS.md section 13).
2. Alcubierre's warp bubble (v = 0.5, R = 1, sigma = 4): the energy density the Eulerian
   observers measure on the x-y plane, against Alcubierre (1994) eq. 19: negative in the wall.
Prints the worst relative errors and the total negative energy on the slice; exits 1 when an error
exceeds 1e-8."""
import math
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

import lightcone.filters as lf


def slice_arrays(source, name):
    """The grid's points (n x 3) and the named array, as numpy arrays."""
    source.Update()
    image = source.GetOutput()
    points = np.array([image.GetPoint(i) for i in range(image.GetNumberOfPoints())])
    return points, vtk_to_numpy(image.GetPointData().GetArray(name))


kerr = lf.vtkLightconeCurvatureSource()
kerr.SetMetricName("kerr")
kerr.SetMetricParameter("a", 0.9)
kerr.SetOrigin(-3.0, 0.0, -2.0)
kerr.SetSpacing(0.05, 1.0, 0.05)
kerr.SetDimensions(121, 1, 81)
kerr.AddQuantity("kretschmann")
points, K = slice_arrays(kerr, "kretschmann")
a = 0.9
x, y, z = points.T
rho2 = x * x + y * y + z * z - a * a
r2 = 0.5 * (rho2 + np.sqrt(rho2 * rho2 + 4 * a * a * z * z))
# Away from the disc r = 0 that the ring bounds (the chart's branch surface, where the closed
# form divides 0 by 0): Boyer-Lindquist r > 0.05 M.
away = r2 > 0.05**2
c2 = a * a * z * z / np.where(away, r2, 1)
with np.errstate(invalid="ignore", divide="ignore"):
    exact = 48 * (r2 - c2) * (r2 * r2 - 14 * c2 * r2 + c2 * c2) / (r2 + c2) ** 6
finite = away & np.isfinite(K) & (np.abs(exact) > 1e-12)
kerr_error = np.max(np.abs(K[finite] - exact[finite]) / np.abs(exact[finite]))
print(f"Kerr a = 0.9, Kretschmann on the x-z plane: {finite.sum()} points, "
      f"|K| up to {np.max(np.abs(K[finite])):.3g} near the ring, worst relative error {kerr_error:.2e}")

v, R, sigma = 0.5, 1.0, 4.0
warp = lf.vtkLightconeCurvatureSource()
warp.SetMetricName("alcubierre")
for name, value in (("v", v), ("R", R), ("sigma", sigma)):
    warp.SetMetricParameter(name, value)
warp.SetObserverFieldToNormal()
warp.SetOrigin(-2.0, -2.0, 0.0)
warp.SetSpacing(0.02, 0.02, 1.0)
warp.SetDimensions(201, 201, 1)
warp.AddQuantity("energy_density")
points, rho = slice_arrays(warp, "energy_density")
x, y, z = points.T
rs = np.sqrt(x * x + y * y + z * z)
sech2 = lambda u: 1 / np.cosh(u) ** 2
df = sigma * (sech2(sigma * (rs + R)) - sech2(sigma * (rs - R))) / (2 * math.tanh(sigma * R))
expected = -v * v * (y * y + z * z) / (4 * np.where(rs > 0, rs * rs, 1)) * df * df / (8 * math.pi)
warp_error = np.max(np.abs(rho - expected)) / np.max(np.abs(expected))
print(f"Alcubierre v = 0.5: Eulerian energy density on z = 0 from {rho.min():.4g} to {rho.max():.3g}, "
      f"negative energy on the slice {rho[rho < 0].sum() * 0.02 * 0.02:.4g} (per unit z), "
      f"worst error against eq. 19 {warp_error:.2e} of its largest value")
sys.exit(0 if kerr_error < 1e-8 and warp_error < 1e-8 else 1)
