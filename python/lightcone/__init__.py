# SPDX-License-Identifier: BSD-3-Clause
"""Lightcone for Python: scenes, renders into numpy arrays, rays, Goedel images and shadows.

    import lightcone
    scene = lightcone.read_scene("data/kerr.json", edits={"metric.a": 0.5})
    image = lightcone.render(scene, width=160, height=80)
    image.arrays["rgb"]          # (80, 160, 3) linear RGB
    lightcone.measure_shadow(scene)["width_deg"]

Metrics written as formulas (docs/METRICS.md), from text, a dict or a sympy matrix:

    wormhole = lightcone.metric_from_formula(open("data/metrics/ellis_wormhole.json").read(), b=1.3)
    wormhole.g([0, 2, 0, 0])
    scene = lightcone.read_scene({"metric": wormhole.scene_block(), "observer": ...})

The work is done by the same C++ as the `lightcone` command line (lightcone._core).
"""
import enum
import json
import sys

try:
    from . import _core
except ImportError as error:
    # The C++ module is built for one interpreter (CMake's PYTHON_EXECUTABLE, Debian's
    # /usr/bin/python3): another version cannot load it and numpy must be importable.
    raise ImportError(
        f"lightcone's C++ module (build/python/lightcone/_core*.so) cannot be loaded by this Python "
        f"({sys.executable}, {sys.version.split()[0]}): {error}. It is built for Debian's /usr/bin/python3 "
        f"with python3-numpy; run that one") from error
from ._core import (Scene, Render, Metric, read_scene, render, measure_shadow,  # noqa: F401
                    shadow_outline, trace, godel_images, __version__)

__all__ = ["Scene", "Render", "Metric", "read_scene", "render", "measure_shadow", "shadow_outline", "trace",
           "godel_images", "metric_from_formula", "metric_from_sympy", "metrics", "PixelKind", "StopReason"]

# The codes of Render.arrays["kind"] and ["stop_reason"] (docs/SCENES.md, "Per-pixel codes"), named as
# `lightcone render` prints them: image.arrays["kind"] == lightcone.PixelKind.sky
PixelKind = enum.IntEnum("PixelKind", {name: code for code, name in enumerate(_core._pixel_kind_names)})
StopReason = enum.IntEnum("StopReason", {name: code for code, name in enumerate(_core._stop_reason_names)})


def metric_from_formula(formula, **parameters):
    """A Metric from a metric file's text or the same as a dict (docs/METRICS.md), with parameter
    values; errors name the field and the column, as for a file."""
    text = formula if isinstance(formula, str) else json.dumps(formula)
    return Metric._from_text(text, {k: float(v) for k, v in parameters.items()})


# sympy's names that the formula language spells otherwise.
_SYMPY_NAMES = {"Abs": "abs", "Min": "min", "Max": "max"}


def _formula_text(expr):
    import sympy
    from sympy.printing.str import StrPrinter

    class Printer(StrPrinter):
        def _print_Function(self, e):
            name = _SYMPY_NAMES.get(type(e).__name__, type(e).__name__)
            return name + "(" + ", ".join(self._print(a) for a in e.args) + ")"

        def _print_besselj(self, e):  # besselj(order, x): the language has orders 0 and 1
            return f"besselj{int(e.args[0])}({self._print(e.args[1])})"

        def _print_Pi(self, e):
            return "pi"

        def _print_Exp1(self, e):
            return "exp(1)"

        def _print_ImaginaryUnit(self, e):
            raise ValueError("the metric must be real: found I in " + str(expr))

    for f in sympy.preorder_traversal(expr):
        if isinstance(f, (sympy.Abs, sympy.Min, sympy.Max)):
            continue
        if isinstance(f, sympy.besselj):
            if f.args[0] not in (0, 1):
                raise ValueError(f"besselj of order {f.args[0]}: the formula language has orders 0 and 1 "
                                 "(besselj0, besselj1; docs/METRICS.md)")
            continue
        if isinstance(f, sympy.Function) and type(f).__name__ not in (
                "sqrt", "exp", "log", "sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sinh", "cosh", "tanh"):
            raise ValueError(f"{type(f).__name__} has no counterpart in the formula language (docs/METRICS.md)")
    return Printer({"order": "none"}).doprint(expr)


def metric_from_sympy(g, coordinates, parameters=None, signature="-+++", chart="cartesian", name="sympy",
                      horizon=None, far_field=None, **values):
    """A Metric from a 4x4 sympy matrix of the coordinates (sympy Symbols, time first) and parameter
    Symbols. parameters: {Symbol: (default, (min, max))}; values: parameter values by name."""
    import sympy
    g = sympy.Matrix(g)
    if g.shape != (4, 4) or g != g.T:
        raise ValueError("g must be a symmetric 4x4 matrix")
    names = [str(c) for c in coordinates]
    components = {}
    for m in range(4):
        for n in range(m, 4):
            if g[m, n] != 0:
                components[names[m] + "," + names[n]] = _formula_text(sympy.simplify(g[m, n]))
    formula = {"name": name, "coordinates": names, "chart": chart, "signature": signature, "g": components,
               "parameters": {str(p): {"default": float(d), "range": [float(r[0]), float(r[1])]}
                              for p, (d, r) in (parameters or {}).items()}}
    if horizon is not None:
        formula["horizon"] = _formula_text(sympy.sympify(horizon))
    if far_field is not None:
        formula["far_field"] = {k: _formula_text(sympy.sympify(v)) for k, v in far_field.items()}
    return metric_from_formula(formula, **values)


def metrics():
    """Every metric file found, as `lightcone metric list` shows them: LIGHTCONE_DATA_PATH's
    folders, then the installed (or the checkout's) data/metrics; the first file of each name.
    A list of dicts: 'name' (the file's stem, as `metric check NAME` and scenes take it), 'metric'
    (its own name), 'file', 'chart', 'summary' and 'parameters' (name -> default). Files that do
    not read as metrics, and scenes, are left out."""
    import pathlib
    found = []
    for file in _core._catalogue_files():
        path = pathlib.Path(file)
        try:
            text = path.read_text()
            metric = metric_from_formula(text)
        except (OSError, ValueError, RuntimeError):
            continue
        doc = json.loads(text)
        found.append({"name": path.stem, "metric": metric.name, "file": str(path),
                      "chart": doc.get("chart", "cartesian"), "summary": doc.get("summary", ""),
                      "parameters": metric.parameters})
    return found


def _scene_block(self):
    """This metric as a scene's "metric" block: the formula inline, with its parameter values."""
    block = {"formula": json.loads(self.text)}
    block.update(self.parameters)
    return block


Metric.scene_block = _scene_block
# The spelling too: lightcone.Metric.from_formula(text), Metric.from_sympy(g, ...).
Metric.from_formula = staticmethod(metric_from_formula)
Metric.from_sympy = staticmethod(metric_from_sympy)
