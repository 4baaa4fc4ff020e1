"""Lightcone's VTK sources and filters, wrapped by VTK's own Python wrapping (VTK builds), for
any VTK pipeline: vtkLightconeNullGeodesicSource, vtkLightconeGodelHorizonSource,
vtkLightconeKillingFieldSource, vtkLightconeIsometryOrbitSource, vtkLightconeWorldLineSource,
vtkLightconePhotoObjectFilter (filters/README.md).

    import vtkmodules.all
    import lightcone.filters
    source = lightcone.filters.vtkLightconeNullGeodesicSource()
"""
from .lightconeFilters import *  # noqa: F401,F403
