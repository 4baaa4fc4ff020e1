"""Lightcone for Python: scenes, renders into numpy arrays, rays, Goedel images and shadows.

    import lightcone
    scene = lightcone.read_scene("data/kerr.json", edits={"metric.a": 0.5})
    image = lightcone.render(scene, width=160, height=80)
    image.arrays["rgb"]          # (80, 160, 3) linear RGB
    lightcone.measure_shadow(scene)["width_deg"]

The work is done by the same C++ as the `lightcone` command line (lightcone._core).
"""
from ._core import Scene, Render, read_scene, render, measure_shadow, trace, godel_images  # noqa: F401

__all__ = ["Scene", "Render", "read_scene", "render", "measure_shadow", "trace", "godel_images"]
