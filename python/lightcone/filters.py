# SPDX-License-Identifier: BSD-3-Clause
"""Lightcone's VTK sources and filters, wrapped by VTK's own Python wrapping (VTK builds), for
any VTK pipeline: vtkLightconeNullGeodesicSource, vtkLightconeGodelHorizonSource,
vtkLightconeKillingFieldSource, vtkLightconeIsometryOrbitSource, vtkLightconeWorldLineSource,
vtkLightconePhotoObjectFilter, vtkLightconeCurvatureSource, vtkLightconeKerrHorizonSource (filters/README.md).

    import vtkmodules.all
    import lightcone.filters
    source = lightcone.filters.vtkLightconeNullGeodesicSource()
"""
import sys

try:
    import vtkmodules.vtkCommonCore  # noqa: F401
except ImportError as error:
    # VTK comes from Debian's python3-vtk9, in /usr/lib/python3/dist-packages: another interpreter
    # (pyenv, conda, a venv without system packages) does not see it.
    raise ImportError(
        f"lightcone.filters needs VTK's Python modules (Debian: python3-vtk9), which this Python "
        f"({sys.executable}, {sys.version.split()[0]}) cannot import; run Debian's /usr/bin/python3, "
        f"or give this one the system packages (a venv with --system-site-packages)") from error

from .lightconeFilters import *  # noqa: F401,F403,E402
