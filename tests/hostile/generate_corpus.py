#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes the regression corpus of hostile inputs: tests/data/bad/ (scene, mesh and data files)
and tests/data/bad/cases.json (one entry per run of `lightcone`: its arguments, whether it must
fail or succeed, and a text its output must contain). tests/hostile/test_hostile_corpus.cpp runs
every case and checks: no crash, no hang, the expected exit, the text, no non-finite number in
the output, the old output untouched after a failure, nothing written outside the output folder
and no temporary names left.

Expectations come from the documented contract (docs/SCENES.md: every error names the file,
line and field, or the option), not from captured output. Run from anywhere:
    python3 tests/hostile/generate_corpus.py
"""
import base64
import copy
import json
import os
import shutil
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
BAD = os.path.join(ROOT, "tests", "data", "bad")
if os.path.isdir(BAD):
    shutil.rmtree(BAD)
os.makedirs(BAD)

# Placeholders the runner replaces: {bad} this folder, {data} the project's data/, {out} a fresh
# output folder per case that holds old.png (must survive failures) and old/ (an earlier export).
cases = []


def case(name, args, expect, text):
    assert expect in ("error", "ok")
    assert not any(c["name"] == name for c in cases), name
    cases.append({"name": name, "args": args, "expect": expect, "text": text})


def write(name, content, binary=False):
    with open(os.path.join(BAD, name), "wb" if binary else "w") as f:
        f.write(content)
    return "{bad}/" + name


def scene(name, doc):
    if isinstance(doc, str):
        return write(name, doc)
    text = json.dumps(doc, indent=1)
    return write(name, text if len(text) < 20000 else json.dumps(doc))  # long lists on one line


def render(scene_path, *extra, out="{out}/old.png", size=(48, 24)):
    return ["render", scene_path, "-o", out, "--width", str(size[0]), "--height", str(size[1]), "--quiet", *extra]


BASES = {
    "godel": {
        "metric": {"name": "godel", "a": 1.0},
        "observer": {"position": [0, 0, 0, 0]},
        "camera": {"projection": "panorama", "width": 48, "height": 24, "fov": [360, 120],
                   "forward": [1, 0, 0], "up": [0, 0, 1]},
        "objects": [{"type": "sphere", "name": "ball", "centre": [0, 1.0, 0.0, 0.0], "radius": 0.25,
                     "texture": {"type": "checker", "cells": [16, 8],
                                 "colors": [[0.95, 0.95, 0.9], [0.8, 0.15, 0.1]]}}],
        "lights": [{"name": "sun", "position": [0, 1.5, 0, 0], "temperature": 6500, "intensity": 1.0}],
        "background": [0.02, 0.02, 0.05],
        "render": {"stepper": "dopri5", "tolerance": 1e-9, "windings": 1, "max_affine": 100,
                   "max_steps": 100000, "initial_step": 0.01, "threads": 0},
    },
    "sr": {
        "metric": {"name": "minkowski"},
        "camera": {"projection": "pinhole", "width": 48, "height": 24, "fov": [100, 75],
                   "forward": [0, 0, -1], "up": [0, 1, 0]},
        "objects": [{"type": "box", "name": "cube", "centre": [0, 9.5, 0, -10], "size": [4, 4, 4],
                     "subdivisions": 4, "temperature": 6000,
                     "motion": {"type": "constant_velocity", "beta": [0.95, 0, 0]}}],
    },
    "kerr": {
        "metric": {"name": "kerr", "M": 1.0, "a": 0.9},
        "observer": {"position": [0, 30, 0, 0]},
        "camera": {"projection": "pinhole", "width": 48, "height": 24, "fov": [60, 32.2],
                   "forward": [-1, 0, 0], "up": [0, 0, 1]},
        "sky": {"type": "checker", "cells": [36, 18], "colors": [[0.9, 0.9, 0.85], [0.1, 0.15, 0.3]]},
    },
    "disk": {
        "metric": {"name": "kerr", "M": 1.0, "a": 0.9},
        "observer": {"position": [0, 48.3, 0, 12.9]},
        "camera": {"projection": "pinhole", "width": 48, "height": 27, "fov": [48, 27], "look_at": [0, 0, 0],
                   "up": [0, 0, 1]},
        "objects": [{"type": "disk", "name": "disk", "inner_radius": 3, "outer_radius": 20, "temperature": 9000}],
    },
    "fall": {
        "metric": {"name": "godel", "a": 1.0},
        "camera": {"projection": "panorama", "width": 48, "height": 24, "fov": [220, 25]},
        "objects": [{"type": "sphere", "name": "earth", "centre": [0, 0.3, 0.3, 0], "radius": 0.2,
                     "temperature": 6000, "motion": {"type": "free_fall", "speed": 0.7, "phi0": 1.9, "k3": 0}}],
        "render": {"windings": 0, "mesh_resolution": [8, 16]},
    },
}


def numeric_paths(node, path=""):
    """Every number in a document, with the reader's field path (a.b[0].c)."""
    if isinstance(node, dict):
        for k, v in node.items():
            yield from numeric_paths(v, f"{path}.{k}" if path else k)
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from numeric_paths(v, f"{path}[{i}]")
    elif isinstance(node, (int, float)) and not isinstance(node, bool):
        yield path


def set_path(doc, path, value):
    parts = path.replace("[", ".[").split(".")
    node = doc
    for p in parts[:-1]:
        node = node[int(p[1:-1])] if p.startswith("[") else node[p]
    last = parts[-1]
    if last.startswith("["):
        node[int(last[1:-1])] = value
    else:
        node[last] = value


INTEGER_FIELDS = ("width", "height", "cells", "windings", "max_steps", "threads", "subdivisions",
                  "mesh_resolution")

# ---- 1. every number of every base scene, replaced by values no range accepts ------------------
WRONG = [("huge", 1e300), ("neghuge", -1e300), ("text", "1"), ("null", None)]
OTHER_TYPES = [("bool", True), ("array", []), ("object", {})]
for base_name, base in BASES.items():
    for index, path in enumerate(numeric_paths(base)):
        tag = path.replace(".", "_").replace("[", "").replace("]", "")
        variants = list(WRONG) + (OTHER_TYPES if index % 4 == 0 else [])
        if any(k in path for k in INTEGER_FIELDS):
            variants.append(("fraction", 2.5))
        for vname, value in variants:
            doc = copy.deepcopy(base)
            set_path(doc, path, value)
            f = scene(f"{base_name}_{tag}_{vname}.json", doc)
            # Physical events (observer, centres, lights) may be refused on their own terms
            # (Goedel distance from the axis): the field named is still this one.
            case(f"{base_name}_{tag}_{vname}", render(f), "error", f"field '{path}")
        # Tokens that are not JSON numbers at all: a syntax error naming the file and line.
        if index % 8:
            continue
        for vname, token in (("overflow", "1e400"), ("nan", "NaN"), ("inf", "-Infinity")):
            text = json.dumps(base, indent=1)
            doc = copy.deepcopy(base)
            set_path(doc, path, 123456.789)
            text = json.dumps(doc, indent=1).replace("123456.789", token, 1)
            f = scene(f"{base_name}_{tag}_{vname}.json", text)
            case(f"{base_name}_{tag}_{vname}", render(f), "error", f"{base_name}_{tag}_{vname}.json:")

# The star sky's own numbers (sky type stars), on the kerr base: each replaced as above.
stars = copy.deepcopy(BASES["kerr"])
stars["sky"] = {"type": "stars", "stars": 200, "seed": 3, "temperatures": [3000, 20000], "faintest_magnitude": 4,
                "size": 2}
for path in numeric_paths(stars["sky"], "sky"):
    tag = path.replace(".", "_").replace("[", "").replace("]", "")
    variants = list(WRONG) + ([("fraction", 2.5)] if path in ("sky.stars", "sky.seed") else [])
    for vname, value in variants:
        doc = copy.deepcopy(stars)
        set_path(doc, path, value)
        case(f"stars_{tag}_{vname}", render(scene(f"stars_{tag}_{vname}.json", doc)), "error", f"field '{path}")

# ---- 2. structure ------------------------------------------------------------------------------
g = BASES["godel"]
structure = {
    "empty": "",
    "blank": "   \n",
    "array_root": "[]",
    "number_root": "42",
    "two_documents": json.dumps(g) + "\n{}",
    "trailing_text": json.dumps(g) + " xyz",
    "duplicate_key": '{"metric": {"name": "godel"}, "metric": {"name": "kerr"}}',
    "deep_nesting": '{"metric": ' + "[" * 5000 + "]" * 5000 + "}",
    "unterminated": '{"metric": {"name": "godel"',
    "binary_garbage": "\x00\x01\x02\xff",
    "no_metric": "{}",
    "metric_not_object": '{"metric": "godel"}',
    "unknown_metric": '{"metric": {"name": "vaidya"}}',
    "unknown_parameter": '{"metric": {"name": "godel", "b": 1}}',
    "unknown_top_field": '{"metric": {"name": "godel"}, "camrea": {}}',
    "objects_not_array": '{"metric": {"name": "godel"}, "objects": {"type": "sphere"}}',
    "object_not_object": '{"metric": {"name": "godel"}, "objects": [5]}',
    "object_no_type": '{"metric": {"name": "godel"}, "objects": [{"centre": [0,1,0,0]}]}',
    "object_bad_type": '{"metric": {"name": "godel"}, "objects": [{"type": "torus", "centre": [0,1,0,0]}]}',
    "sphere_no_radius": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,1,0,0]}]}',
    "centre_three": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [1,0,0], "radius": 0.1}]}',
    "cells_not_array": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,1,0,0], "radius": 0.1,'
                       ' "texture": {"type": "checker", "cells": 16}}]}',
    "cells_empty": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,1,0,0], "radius": 0.1,'
                   ' "texture": {"type": "checker", "cells": []}}]}',
    "colors_one": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,1,0,0], "radius": 0.1,'
                  ' "texture": {"type": "checker", "colors": [[1,1,1]]}}]}',
    "mesh_resolution_empty": '{"metric": {"name": "godel"}, "render": {"mesh_resolution": []}}',
    "mesh_resolution_budget": '{"metric": {"name": "godel"}, "render": {"mesh_resolution": [4096, 8192]}}',
    "bad_stepper": '{"metric": {"name": "godel"}, "render": {"stepper": "euler"}}',
    "bad_method": '{"metric": {"name": "godel"}, "render": {"method": "magic"}}',
    "bad_projection": '{"metric": {"name": "godel"}, "camera": {"projection": "fisheye"}}',
    "pinhole_180": '{"metric": {"name": "godel"}, "camera": {"projection": "pinhole", "fov": [180, 90]}}',
    "forward_zero": '{"metric": {"name": "godel"}, "camera": {"forward": [0, 0, 0]}}',
    "forward_parallel_up": '{"metric": {"name": "godel"}, "camera": {"forward": [0, 0, 2], "up": [0, 0, 1]}}',
    "forward_huge": '{"metric": {"name": "godel"}, "camera": {"forward": [1e308, 1e308, 0]}}',
    "look_at_and_forward": '{"metric": {"name": "godel"}, "camera": {"forward": [1, 0, 0], "look_at": [1, 1, 0]}}',
    "look_at_observer": '{"metric": {"name": "schwarzschild"}, "observer": {"position": [0, 10, 0, 0]},'
                        ' "camera": {"look_at": [10, 0, 0]}}',
    "look_at_along_up": '{"metric": {"name": "schwarzschild"}, "observer": {"position": [0, 10, 0, 0]},'
                        ' "camera": {"look_at": [10, 0, 5], "up": [0, 0, 1]}}',
    "look_at_huge": '{"metric": {"name": "godel"}, "camera": {"look_at": [1e308, 0, 0]}}',
    "segments_not_godel": '{"metric": {"name": "schwarzschild"}, "objects": [{"type": "sphere", "centre": [0,9,0,0],'
                          ' "radius": 0.1, "motion": {"type": "segments", "segments": [{"type": "rest", "proper_time": 1}]}}]}',
    "segments_circle_past": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,0.5,0,0], "radius": 0.1, "motion": {"type": "segments", "segments": [{"type": "circle", "dt_dphi": -0.8, "turns": 1}]}}]}',
    "segments_unknown": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,0.5,0,0], "radius": 0.1, "motion": {"type": "segments", "segments": [{"type": "warp"}]}}]}',
    "segments_empty": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,0.5,0,0], "radius": 0.1, "motion": {"type": "segments", "segments": []}}]}',
    "segments_turns_huge": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,0.5,0,0], "radius": 0.1, "motion": {"type": "segments", "segments": [{"type": "circle", "dt_dphi": -0.8, "turns": 1e9}]}}]}',
    "segments_rocket_direction": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,0.5,0,0], "radius": 0.1, "motion": {"type": "segments", "segments": [{"type": "rocket", "acceleration": 1, "proper_time": 1, "direction": "sideways"}]}}]}',
    "segments_rocket_huge": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,0.5,0,0], "radius": 0.1, "motion": {"type": "segments", "segments": [{"type": "rocket", "acceleration": 1e9, "proper_time": 1}]}}]}',
    "segments_samples_elsewhere": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,0.5,0,0], "radius": 0.1, "motion": {"type": "segments", "segments": [{"type": "samples", "points": [[0, 0, 2, 0, 0], [1, 1, 2, 0, 0]]}]}}]}',
    "segments_samples_spacelike": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,0.5,0,0], "radius": 0.1, "motion": {"type": "segments", "segments": [{"type": "samples", "points": [[0, 0, 0.5, 0, 0], [1, 0.1, 1.5, 0, 0]]}]}}]}',
    "segments_radial_light": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,0.5,0,0], "radius": 0.1, "motion": {"type": "segments", "segments": [{"type": "radial", "speed": 1, "to_radius": 2}]}}]}',
    "segments_rocket_long": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,0.5,0,0], "radius": 0.1, "motion": {"type": "segments", "segments": [{"type": "rocket", "acceleration": 1e-3, "proper_time": 6e5}]}}]}',
    "segments_rocket_too_fast": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,0.5,0,0], "radius": 0.1, "motion": {"type": "segments", "segments": [{"type": "rocket", "acceleration": 1000, "proper_time": 1, "direction": "up"}]}}]}',
    "segments_trip_too_long": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,0.5,0,0], "radius": 0.1, "motion": {"type": "segments", "segments": [{"type": "rest", "proper_time": 1e6}, {"type": "rest", "proper_time": 1}]}}]}',
    "pixels_over_budget": '{"metric": {"name": "godel"}, "camera": {"width": 16384, "height": 16384}}',
    "name_escape": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "name": "../../../../tmp/escaped",'
                   ' "centre": [0,1,0,0], "radius": 0.1}]}',
    "name_hidden": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "name": ".x", "centre": [0,1,0,0], "radius": 0.1}]}',
    "name_control": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "name": "a\\nb", "centre": [0,1,0,0], "radius": 0.1}]}',
    "name_long": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "name": "' + "x" * 100 +
                 '", "centre": [0,1,0,0], "radius": 0.1}]}',
    "beyond_axis_limit": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,1e308,0,0], "radius": 0.1}]}',
    "goedel_far_event": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,2e4,0,0], "radius": 0.1}]}',
    "observer_t_huge": '{"metric": {"name": "godel"}, "observer": {"position": [1e308,0,0,0]}}',
    "observer_spacelike": '{"metric": {"name": "godel"}, "observer": {"velocity": [1, 2, 0, 0]}}',
    "observer_gamma_too_high": '{"metric": {"name": "godel"}, "observer": {"velocity": [1, 0.999999999999, 0, 0]}}',
    "observer_past": '{"metric": {"name": "godel"}, "observer": {"velocity": [-1, 0, 0, 0]}}',
    "observer_moving_minkowski": '{"metric": {"name": "minkowski"}, "observer": {"velocity": [1.25, 0.75, 0, 0]}}',
    "ergoregion_static": '{"metric": {"name": "kerr", "a": 0.9}, "observer": {"position": [0, 1.5, 0, 0]}}',
    "ergoregion_named_static": '{"metric": {"name": "kerr", "a": 0.9}, "observer": {"position": [0, 1.5, 0, 0], "velocity": "static"}}',
    "observer_on_black_hole_centre": '{"metric": {"name": "schwarzschild"}, "observer": {"position": [0, 0, 0, 0]}}',
    "observer_on_polar_axis": '{"metric": {"name": "godel-cylindrical"}, "observer": {"position": [0, 0, 0, 0]}}',
    "observer_warp_static": '{"metric": {"name": "alcubierre"}, "observer": {"position": [0, 0, 0, 0]}}',
    "observer_named_unknown": '{"metric": {"name": "kerr", "a": 0.9}, "observer": {"position": [0, 8, 0, 0], "velocity": "hovering"}}',
    "observer_named_inside_horizon": '{"metric": {"name": "kerr", "a": 0.9}, "observer": {"position": [0, 1, 0, 0], "velocity": "zamo"}}',
    "observer_carter_on_goedel": '{"metric": {"name": "godel"}, "observer": {"velocity": "carter"}}',
    "kerr_naked": '{"metric": {"name": "kerr", "M": 1, "a": 1.5}}',
    "alcubierre_v_huge": '{"metric": {"name": "alcubierre", "v": 1e308}}',
    "goedel_a_huge": '{"metric": {"name": "godel", "a": 1e300}}',
    "beta_light": '{"metric": {"name": "minkowski"}, "objects": [{"type": "box", "centre": [0,0,0,-5], "size": [1,1,1],'
                  ' "motion": {"type": "constant_velocity", "beta": [0.8, 0.7, 0]}}]}',
    "beta_almost_light": '{"metric": {"name": "minkowski"}, "objects": [{"type": "box", "centre": [0,0,0,-5], "size": [1,1,1],'
                         ' "motion": {"type": "constant_velocity", "beta": [0.9999999999999999, 0, 0]}}]}',
    "constant_velocity_curved": '{"metric": {"name": "godel"}, "objects": [{"type": "box", "centre": [0,1,0,0], "size": [1,1,1],'
                                ' "motion": {"type": "constant_velocity", "beta": [0.5, 0, 0]}}]}',
    "free_fall_speed_one": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,1,0,0], "radius": 0.1,'
                           ' "motion": {"type": "free_fall", "speed": 1}}]}',
    "free_fall_k0_huge": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,1,0,0], "radius": 0.1,'
                         ' "motion": {"type": "free_fall", "k0": 1e308}}]}',
    "free_fall_not_timelike": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,1,0,0], "radius": 0.1,'
                              ' "motion": {"type": "free_fall", "k0": 1, "k3": 5}}]}',
    "free_fall_both": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,1,0,0], "radius": 0.1,'
                      ' "motion": {"type": "free_fall", "k0": 2, "speed": 0.5}}]}',
    "world_line_one_event": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,1,0,0], "radius": 0.1,'
                            ' "motion": {"type": "world_line", "points": [[0,1,0,0]]}}]}',
    "world_line_backwards": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,1,0,0], "radius": 0.1,'
                            ' "motion": {"type": "world_line", "points": [[0,1,0,0], [-1,1,0,0]]}}]}',
    "world_line_not_array": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,1,0,0], "radius": 0.1,'
                            ' "motion": {"type": "world_line", "points": 3}}]}',
    "motion_unknown": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,1,0,0], "radius": 0.1,'
                      ' "motion": "spinning"}]}',
    "light_temperature_huge": '{"metric": {"name": "godel"}, "lights": [{"position": [0,1,0,0], "temperature": 1e308}]}',
    "light_intensity_zero": '{"metric": {"name": "godel"}, "lights": [{"position": [0,1,0,0], "intensity": 0}]}',
    "background_huge": '{"metric": {"name": "godel"}, "background": [1e308, 0, 0]}',
    "background_negative": '{"metric": {"name": "godel"}, "background": [-1, 0, 0]}',
    "checker_colour_huge": '{"metric": {"name": "kerr"}, "sky": {"type": "checker", "colors": [[1e300,0,0],[0,0,0]]}}',
    "temperature_low": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,1,0,0], "radius": 0.1,'
                       ' "temperature": 10}]}',
    "texture_unknown_type": '{"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,1,0,0], "radius": 0.1,'
                            ' "texture": {"type": "plasma"}}]}',
    "windings_huge": '{"metric": {"name": "godel"}, "render": {"windings": 1e9}}',
    "max_steps_negative": '{"metric": {"name": "godel"}, "render": {"max_steps": -1}}',
    "tolerance_zero": '{"metric": {"name": "godel"}, "render": {"tolerance": 0}}',
    "threads_negative": '{"metric": {"name": "godel"}, "render": {"threads": -1}}',
    "max_affine_zero": '{"metric": {"name": "godel"}, "render": {"max_affine": 0}}',
    "max_affine_beyond_range": '{"metric": {"name": "kerr"}, "render": {"max_affine": 1e300}}',
    "escape_radius_negative": '{"metric": {"name": "kerr"}, "render": {"escape_radius": -1}}',
    "escape_angle_zero": '{"metric": {"name": "kerr"}, "render": {"escape_angle": 0}}',
    "escape_angle_huge": '{"metric": {"name": "kerr"}, "render": {"escape_angle": 1e300}}',
    "disk_in_godel": '{"metric": {"name": "godel"}, "objects": [{"type": "disk"}]}',
    "disk_inside_isco": '{"metric": {"name": "kerr", "a": 0.9}, "observer": {"position": [0, 30, 0, 8]}, "camera": {"look_at": [0, 0, 0]}, "objects": [{"type": "disk", "inner_radius": 2}]}',
    "disk_outer_inside_inner": '{"metric": {"name": "kerr", "a": 0.9}, "observer": {"position": [0, 30, 0, 8]}, "camera": {"look_at": [0, 0, 0]}, "objects": [{"type": "disk", "inner_radius": 10, "outer_radius": 5}]}',
    "disk_two": '{"metric": {"name": "kerr", "a": 0.9}, "observer": {"position": [0, 30, 0, 8]}, "camera": {"look_at": [0, 0, 0]}, "objects": [{"type": "disk"}, {"type": "disk", "inner_radius": 30, "outer_radius": 40}]}',
    "disk_sense": '{"metric": {"name": "kerr", "a": 0.9}, "observer": {"position": [0, 30, 0, 8]}, "camera": {"look_at": [0, 0, 0]}, "objects": [{"type": "disk", "sense": "sideways"}]}',
    "disk_emission": '{"metric": {"name": "kerr", "a": 0.9}, "observer": {"position": [0, 30, 0, 8]}, "camera": {"look_at": [0, 0, 0]}, "objects": [{"type": "disk", "emission": "laser"}]}',
    "disk_inner_text": '{"metric": {"name": "kerr", "a": 0.9}, "observer": {"position": [0, 30, 0, 8]}, "camera": {"look_at": [0, 0, 0]}, "objects": [{"type": "disk", "inner_radius": "inside"}]}',
    "disk_unknown_field": '{"metric": {"name": "kerr", "a": 0.9}, "observer": {"position": [0, 30, 0, 8]}, "camera": {"look_at": [0, 0, 0]}, "objects": [{"type": "disk", "thickness": 0.1}]}',
    "disk_extremal_without_inner": '{"metric": {"name": "kerr", "a": 1}, "observer": {"position": [0, 30, 0, 8]}, '
                                   '"objects": [{"type": "disk"}]}',
    "disk_outer_huge": '{"metric": {"name": "kerr", "a": 0.9}, "observer": {"position": [0, 30, 0, 8]}, "camera": {"look_at": [0, 0, 0]}, "objects": [{"type": "disk", "outer_radius": 1e300}]}',
}
expect_text = {
    "empty": "is empty", "blank": "invalid JSON", "array_root": "expected an object", "number_root": "expected an object",
    "two_documents": "Extra non-whitespace", "trailing_text": "invalid JSON", "duplicate_key": "Duplicate key",
    "deep_nesting": "invalid JSON", "unterminated": "invalid JSON", "binary_garbage": "invalid JSON",
    "no_metric": "missing required field 'metric'", "metric_not_object": "field 'metric'",
    "unknown_metric": "unknown metric 'vaidya'", "unknown_parameter": "field 'metric.b': unknown field",
    "unknown_top_field": "field 'camrea': unknown field", "objects_not_array": "field 'objects': expected an array",
    "object_not_object": "field 'objects[0]'", "object_no_type": "missing required field 'type'",
    "object_bad_type": "unknown object type 'torus'", "sphere_no_radius": "missing required field 'radius'",
    "centre_three": "field 'objects[0].centre': expected an array of 4 numbers",
    "cells_not_array": "field 'objects[0].texture.cells': expected an array",
    "cells_empty": "field 'objects[0].texture.cells': expected an array of 1 to 2 elements",
    "colors_one": "expected two colours", "mesh_resolution_empty": "field 'render.mesh_resolution'",
    "mesh_resolution_budget": "field 'render.mesh_resolution'", "bad_stepper": "field 'render.stepper'",
    "bad_method": "field 'render.method'", "bad_projection": "unknown projection 'fisheye'",
    "pinhole_180": "below 180 degrees", "forward_zero": "must not be zero", "forward_parallel_up": "parallel",
    "forward_huge": "field 'camera.forward[0]'", "pixels_over_budget": "width x height",
    "look_at_and_forward": "field 'camera.look_at': both forward and look_at",
    "look_at_observer": "field 'camera.look_at': camera: look_at is the observer's own position",
    "look_at_along_up": "field 'camera.look_at': camera: forward and up point the same way",
    "look_at_huge": "field 'camera.look_at[0]'",
    "segments_not_godel": "segments are available in the godel metric",
    "segments_circle_past": "field 'objects[0].motion.segments[0]': world line segment 0 (circle): past-directed",
    "segments_unknown": "unknown segment type 'warp'", "segments_empty": "field 'objects[0].motion.segments'",
    "segments_turns_huge": "field 'objects[0].motion.segments[0].turns'",
    "segments_radial_light": "field 'objects[0].motion.segments[0].speed'",
    "segments_rocket_long": "field 'objects[0].motion.segments[0].proper_time'",
    "segments_rocket_too_fast": "passes the Lorentz factor 7071.07",
    "segments_trip_too_long": "the trip's proper time reaches",
    "segments_rocket_direction": "unknown direction 'sideways'",
    "segments_rocket_huge": "field 'objects[0].motion.segments[0].acceleration'",
    "segments_samples_elsewhere": "the first sample is not where the world line is",
    "segments_samples_spacelike": "chord 0 to 1 is not future timelike",
    "name_escape": "field 'objects[0].name'", "name_hidden": "field 'objects[0].name'",
    "name_control": "field 'objects[0].name'", "name_long": "field 'objects[0].name'",
    "beyond_axis_limit": "field 'objects[0].centre[1]'", "goedel_far_event": "within r = 10000 a of the axis",
    "observer_t_huge": "field 'observer.position[0]'", "observer_spacelike": "not future timelike",
    "observer_gamma_too_high": "Lorentz factor", "observer_past": "not future timelike",
    "observer_moving_minkowski": "field 'observer.velocity': special relativity draws from an observer at rest",
    "ergoregion_static": "field 'observer': the observer is static unless observer.velocity says otherwise, and no static observer here", "kerr_naked": "naked singularity",
    "ergoregion_named_static": "field 'observer.velocity': no static observer here",
    "observer_on_black_hole_centre": "field 'observer.position': the metric cannot serve at the observer's event (0, 0, 0, 0): g_tt = nan",
    "observer_on_polar_axis": "field 'observer.position': the metric cannot serve at the observer's event (0, 0, 0, 0): the metric is singular (det g = 0)",
    "observer_warp_static": "d/dt is not timelike",
    "observer_named_unknown": "field 'observer.velocity': unknown observer 'hovering'",
    "observer_named_inside_horizon": "no zamo observer here: the event is at or inside the metric's horizon",
    "observer_carter_on_goedel": "it is defined for Kerr-Newman holes",
    "alcubierre_v_huge": "field 'metric.v'", "goedel_a_huge": "field 'metric.a'",
    "beta_light": "speed |beta|", "beta_almost_light": "speed |beta|", "constant_velocity_curved": "minkowski",
    "free_fall_speed_one": "field 'objects[0].motion.speed'", "free_fall_k0_huge": "field 'objects[0].motion.k0'",
    "free_fall_not_timelike": "timelike geodesic", "free_fall_both": "either speed or k0",
    "world_line_one_event": "2 to 1000000 elements", "world_line_backwards": "increasing time",
    "world_line_not_array": "expected an array", "motion_unknown": "unknown motion 'spinning'",
    "light_temperature_huge": "field 'lights[0].temperature'", "light_intensity_zero": "field 'lights[0].intensity'",
    "background_huge": "field 'background[0]'", "background_negative": "field 'background[0]'",
    "checker_colour_huge": "field 'sky.colors[0][0]'", "temperature_low": "field 'objects[0].temperature'",
    "texture_unknown_type": "unknown texture type 'plasma'", "windings_huge": "field 'render.windings'",
    "max_steps_negative": "field 'render.max_steps'", "tolerance_zero": "field 'render.tolerance'",
    "threads_negative": "field 'render.threads'", "max_affine_zero": "field 'render.max_affine'",
    "max_affine_beyond_range": "field 'render.max_affine'", "escape_radius_negative": "field 'render.escape_radius'",
    "escape_angle_zero": "field 'render.escape_angle'", "escape_angle_huge": "field 'render.escape_angle'",
    "disk_in_godel": "field 'objects[0].type': a thin disk needs a stationary, axisymmetric hole",
    "disk_inside_isco": "field 'objects[0].inner_radius': inner radius 2 M lies inside the innermost stable",
    "disk_outer_inside_inner": "field 'objects[0].outer_radius': outer radius 5 M must exceed",
    "disk_two": "field 'objects[1].type': a second disk", "disk_sense": "unknown sense 'sideways'",
    "disk_emission": "unknown emission 'laser'", "disk_inner_text": "expected \"isco\" or a number in [1, 1e+05], got 'inside'",
    "disk_unknown_field": "field 'objects[0].thickness': unknown field",
    "disk_extremal_without_inner": "give the disk an inner radius", "disk_outer_huge": "field 'objects[0].outer_radius'",
}
for name, text in structure.items():
    f = write(f"structure_{name}.json", text)
    case(f"structure_{name}", render(f), "error", expect_text[name])

# ---- 3. mesh files -----------------------------------------------------------------------------
V3 = "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
PLY_HEAD = ("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
            "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n")


def ply_binary(endian, count, indices):
    fmt = "<" if endian == "little" else ">"
    head = (f"ply\nformat binary_{endian}_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
            "property float z\nelement face 1\nproperty list int int vertex_indices\nend_header\n").encode()
    body = struct.pack(fmt + "9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack(fmt + "i", count)
    body += b"".join(struct.pack(fmt + "i", i) for i in indices)
    return head + body


STL_HEADER = b" " * 80


def stl_binary(triangles, *values):
    """A binary STL announcing `triangles` triangles, then the float values of its facets (normal and
    three corners, 12 floats, then 2 attribute bytes each)."""
    body = b"".join(struct.pack("<12fH", *values[12 * k:12 * k + 12], 0) for k in range(len(values) // 12))
    return STL_HEADER + struct.pack("<I", triangles) + body


def mesh_case(fname, content, expect, text):
    """The mesh file, a Goedel scene holding it, and the render case expecting `text`."""
    write(fname, content, binary=isinstance(content, bytes))
    doc = {"metric": {"name": "godel"}, "objects": [{"type": "mesh", "centre": [0, 1, 0, 0], "file": fname}],
           "render": {"windings": 0, "method": "per_vertex"}}
    f = scene(f"meshscene_{fname.replace('.', '_')}.json", doc)
    case(f"mesh_{fname.replace('.', '_')}", render(f), expect, text)


VTP_BAD = ('<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">\n'
           '<PolyData><Piece NumberOfPoints="3" NumberOfPolys="1"><Points>'
           '<DataArray type="Float32" NumberOfComponents="3" format="ascii">0 0 0 1 0 0 0 1 0</DataArray></Points>'
           '<Polys><DataArray type="Int64" Name="connectivity" format="ascii">0 1 {idx}</DataArray>'
           '<DataArray type="Int64" Name="offsets" format="ascii">{off}</DataArray></Polys></Piece></PolyData></VTKFile>\n')
meshes = {
    "obj_index_far.obj": (V3 + "f 1 2 99999\n", "refers to vertex 99999"),
    "obj_index_zero.obj": (V3 + "f 0 1 2\n", "index 0"),
    "obj_index_negative_far.obj": (V3 + "f -1 -2 -99\n", "refers back further than the 3 defined"),
    "obj_texcoord_far.obj": (V3 + "vt 0 0\nf 1/9 2/9 3/9\n", "texture coordinate 9"),
    "obj_texcoord_one_number.obj": (V3 + "vt 0\nf 1/1 2/1 3/1\n", "'vt' needs 2"),
    "obj_normal_far.obj": (V3 + "vn 0 0 1\nf 1//7 2//7 3//7\n", "normal 7"),
    "obj_trailing_slash.obj": ("v 1 1 1\nf\t1/ 1 1\n", "not a vertex reference"),
    "obj_two_corners.obj": (V3 + "f 1 2\n", "at least 3 vertices"),
    "obj_nan_vertex.obj": ("v 0 nan 0\n" + V3 + "f 1 2 3\n", "finite numbers"),
    "obj_huge_exponent.obj": ("v 0 1e999 0\n" + V3 + "f 1 2 3\n", "finite numbers"),
    "obj_text_vertex.obj": ("v a b c\n" + V3 + "f 1 2 3\n", "finite numbers"),
    "obj_word_index.obj": (V3 + "f 1 2 three\n", "not a vertex reference"),
    "obj_no_faces.obj": (V3, "no triangles"),
    "obj_empty.obj": ("", "is empty"),
    "obj_binary.obj": ("\x00\x01\x02\x03" * 16, "not printable ASCII"),
    "ply_negative_list.ply": (PLY_HEAD + "-3 0 1 2\n", "list 'vertex_indices' has length -3"),
    "ply_huge_list.ply": (PLY_HEAD + "200 0 1 2\n", "fewer values on the line"),
    "ply_short_line.ply": (PLY_HEAD.replace("0 0 0\n1 0 0\n", "0 0\n1 0 0 0\n") + "3 0 1 2\n", "fewer values on the line"),
    "ply_long_line.ply": (PLY_HEAD + "3 0 1 2 7\n", "more values on the line"),
    "ply_duplicate_element.ply": ("ply\nformat ascii 1.0\nelement vertex 1\nelement vertex 1\nend_header\n", "a second element"),
    "ply_empty_element.ply": ("ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                              "property float z\nelement facg 9\nobj_info list uchar int vertex_indices\nend_header\n",
                              "element 'facg' has no properties"),
    "ply_no_face.ply": ("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
                        "element facg 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n3 0 0 0\n",
                        "no face element"),
    "ply_blank_header_line.ply": ("ply\nformat ascii 1.0\n\nelement vertex 1\nend_header\n", "an empty header line"),
    "ply_no_final_newline.ply": (PLY_HEAD + "3 0 1 2", "no newline at its end"),
    "ply_garbled_element.ply": ("ply\nformat ascii 1.0\nelement fac=\"3\"y 1\nend_header\n", "not an identifier"),
    "ply_index_far.ply": (PLY_HEAD + "3 0 1 7\n", "vertex index 7"),
    "ply_index_negative.ply": (PLY_HEAD + "3 0 1 -1\n", "vertex index -1"),
    "ply_truncated.ply": (PLY_HEAD, "ends before"),
    "ply_no_end_header.ply": ("ply\nformat ascii 1.0\nelement vertex 3\n", "end_header"),
    "ply_bad_magic.ply": ("plx\n", "not a PLY file"),
    "ply_bad_format.ply": ("ply\nformat ebcdic 1.0\nend_header\n", "unknown PLY format"),
    "ply_negative_count.ply": ("ply\nformat ascii 1.0\nelement vertex -5\nend_header\n", "not a whole number"),
    "ply_count_huge.ply": ("ply\nformat ascii 1.0\nelement vertex 1e15\nproperty float x\nend_header\n", "over the limit"),
    "ply_nan_vertex.ply": (PLY_HEAD.replace("1 0 0\n", "nan 0 0\n") + "3 0 1 2\n", "not a finite number"),
    "ply_property_first.ply": ("ply\nformat ascii 1.0\nproperty float x\nend_header\n", "before any element"),
    "ply_bad_type.ply": ("ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n", "unknown property type"),
    "stl_size_mismatch.stl": (STL_HEADER + struct.pack("<I", 1000000) + b"\0" * 50, "announces 1000000 triangles"),
    "stl_short.stl": ("xx", "an ASCII STL (which starts with 'solid')"),
    "stl_ascii_four_vertices.stl": ("solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
                                    "vertex 1 1 0\nendloop\nendfacet\nendsolid t\n", "stl_ascii_four_vertices.stl:7: 'vertex' where 'endloop'"),
    "stl_ascii_nan.stl": ("solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 nan 0\n", "'nan' is not a finite number"),
    "stl_ascii_truncated.stl": ("solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n", "ends inside a facet"),
    "stl_ascii_no_facets.stl": ("solid t\nendsolid t\n", "no triangles"),
    "stl_ascii_binary_bytes.stl": ("solid t\n\x01\x02\n", "not printable ASCII"),
    "vtp_index_far.vtp": (VTP_BAD.format(idx=99, off=3), "refers to vertex 99"),
    "vtp_negative_points.vtp": (VTP_BAD.format(idx=2, off=3).replace('NumberOfPoints="3"', 'NumberOfPoints="-14"'),
                                'NumberOfPoints="-14"'),
    "vtp_components_zero.vtp": (VTP_BAD.format(idx=2, off=3).replace('NumberOfComponents="3"', 'NumberOfComponents="0"'),
                                'NumberOfComponents="0"'),
    "vtp_offsets_past_ids.vtp": (VTP_BAD.format(idx=2, off=5), "cannot use mesh"),
    "vtp_garbage.vtp": ("<VTKFile><<<", "no <Piece> element"),
    "stl_binary_nan.stl": (stl_binary(1, 0, 0, 1, 0, 0, 0, 1, float("nan"), 0, 0, 1, 0), "facet 0: a corner coordinate is not finite"),
    "mesh_unknown.xyz": ("1 2 3\n", "unknown mesh format"),
}
for fname, (content, text) in meshes.items():
    mesh_case(fname, content, "error", text)
# Found by fuzz_mesh_loader: a binary VTP strip whose offsets run past its ids (VTK's triangle
# filter crashed in vtkTriangleStrip::DecomposeStrip).
CORRUPT_STRIP_VTP = base64.b64decode("PD94bWwgdmVyc2lvbj0iMS4wIj8+CjxWVEtGaWxlIHR5cGU9IlBvbHlEYXRhIiB2ZXJzaW9uPSIxLjAiIGJ5dGVfb3JkZXI9IkxpdHRsZUVuZGlhbiIgaGVhZGVyX3R5cGU9IlVJbnQzMiI+CjxQb2x5RGF0YT4KPFBpZWNlIE51bWJlck9mUG9pbnRzPSI0IiBOdW1iZXJPZlZlcnRzPSIwIiBOdW1iZXJPZkxpbmVzPSIwIiBOdW1iZXJPZlN0cmlwcz0iMSIgTnVtYmVyT2ZQb2x5cz0iMSI+CjxQb2ludHM+PERhdGFBcnJheSB0eXBlPSJGbG9hdDY0IiBOdW1iZXJPZkNvbXBvbmVudHM9IjMiIGZvcm1hdD0iYmluYXJ5Ij5ZQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBOEQ4QUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBRHdQdz09PC9EYXRhQXJyYXk+PC9Qb2ludHM+CjxTdHJpcHM+PERhdGFBcnJheSB0eXBlPSJJbnQ2NCIgTmFtZT0iY29ubmVjdGl2aXR5IiBmb3JtYXQ9ImJpbmFyeSI+SUFpbmZBQUFBQUFBQUFBQUFBQUFRQUFBQUFBQUFBQ0FBQUFBUUFBQUFNQUFBQUFBQUFBPC9EYXRhQXJyYXk+CjxEYXRhQXJyYXkgdHlwZT0iSW50NjQiIE5hbWU9Im9mZnNldHMiIGZvcm1hdD0iYmluYXJ5Ij5DQVFBQUFBQUFBQUFBQUFBPC9EYXRhQXJyYXk+PC9TdHJpcHM+CjxQb2x5cz48RGF0YUFycmF5IHR5cGU9IkludDY0IiBOYW1lPSJjb25uZWN0aXZpdHkiIGZvcm1hdD0iYmluYXJ5Ij5HQUFBQUFBQUFBQUFycmF5IHR5cGU9IkludDY0IiBOYW1lPSJvZmZzZXRzIiBmb3JtYXQ9ImJpbmFyeSI+Q0FBQUFBTUFBQUFBQUFBQTwvRGF0YUFycmF5PjwvUG9seXM+CjwvUGllY2U+CjwvUG9seURhdGE+CjwvVlRLRmlsZT4K")
for fname, blob, text in (
        ("vtp_corrupt_strip.vtp", CORRUPT_STRIP_VTP, "cannot use mesh"),
        ("ply_binary_negative_list_le.ply", ply_binary("little", -7, [0]), "length -7"),
        ("ply_binary_negative_list_be.ply", ply_binary("big", -7, [0]), "length -7"),
        ("ply_binary_index_far_le.ply", ply_binary("little", 3, [0, 1, 3]), "vertex index 3"),
        ("ply_binary_truncated_le.ply", ply_binary("little", 3, [0]), "ends before"),
        ("ply_binary_huge_list_be.ply", ply_binary("big", 2**31 - 1, [0, 1, 2]), "length 2147483647")):
    mesh_case(fname, blob, "error", text)
# Valid meshes the walkers must accept (and render): relative OBJ indices, faces mixing
# reference forms, an ASCII STL (vertices merged) and a binary one.
STL_TRIANGLE = "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 0.1 0 0\nvertex 0 0.1 0\nendloop\nendfacet\n"
for fname, content in (("ok_obj_relative.obj", "v 0 0 0\nv 0.1 0 0\nv 0 0.1 0\nf -3 -2 -1\n"),
                       ("ok_obj_mixed_forms.obj", "v 0 0 0\nv 0.1 0 0\nv 0 0.1 0\nvt 0 0\nvn 0 0 1\nf 1/1 2/1 3/1\nf 1//1 2 3/1/1\n"),
                       ("ok_stl_ascii.stl", "solid t\n" + STL_TRIANGLE * 2 + "endsolid t\n"),
                       ("ok_stl_binary.stl", stl_binary(1, 0, 0, 1, 0, 0, 0, 0.1, 0, 0, 0, 0.1, 0))):
    mesh_case(fname, content, "ok", "object pixels")
for name, path, text in (("missing", "no_such_mesh.obj", "does not exist"), ("device", "/dev/zero", "not a regular file"),
                         ("folder", ".", "is a directory")):
    doc = {"metric": {"name": "godel"}, "objects": [{"type": "mesh", "centre": [0, 1, 0, 0], "file": path}]}
    f = scene(f"meshscene_{name}.json", doc)
    case(f"mesh_file_{name}", render(f), "error", text)

# ---- 4. textures -------------------------------------------------------------------------------
write("texture_garbage.png", "not a png at all")
write("texture_empty.png", "")
for name, tex, text in (("device", "/dev/zero", "not a regular file"), ("folder", ".", "is a directory"),
                        ("missing", "no_such.png", "does not exist"), ("garbage", "texture_garbage.png", "cannot load texture"),
                        ("empty", "texture_empty.png", "is empty")):
    doc = copy.deepcopy(BASES["godel"])
    doc["objects"][0]["texture"] = tex
    f = scene(f"texture_{name}.json", doc)
    case(f"texture_{name}", render(f), "error", "field 'objects[0].texture'")
    doc["objects"][0].pop("texture")
    doc["objects"][0]["night_texture"] = tex
    f = scene(f"night_texture_{name}.json", doc)
    case(f"night_texture_{name}", render(f), "error", text)

# ---- 5. command lines --------------------------------------------------------------------------
D = "{data}/default.json"
cli = [
    ("render_width_fraction", ["render", D, "-o", "{out}/old.png", "--width", "2.5"], "option --width"),
    ("render_width_negative", ["render", D, "-o", "{out}/old.png", "--width", "-1"], "option --width"),
    ("render_width_huge", ["render", D, "-o", "{out}/old.png", "--width", "100000", "--height", "100000"], "option --width"),
    ("render_pixels_budget", ["render", D, "-o", "{out}/old.png", "--width", "16384", "--height", "16384"], "width x --height"),
    ("render_width_nan", ["render", D, "-o", "{out}/old.png", "--width", "nan"], "option --width"),
    ("render_width_text", ["render", D, "-o", "{out}/old.png", "--width", "12px"], "option --width"),
    ("render_width_empty", ["render", D, "-o", "{out}/old.png", "--width", ""], "option --width"),
    ("render_width_missing", ["render", D, "-o", "{out}/old.png", "--width"], "needs a value"),
    ("render_threads_negative", ["render", D, "-o", "{out}/old.png", "--threads", "-1"], "option --threads"),
    ("render_threads_huge", ["render", D, "-o", "{out}/old.png", "--threads", "100000"], "option --threads"),
    ("render_tolerance_nan", ["render", D, "-o", "{out}/old.png", "--tolerance", "nan"], "option --tolerance"),
    ("render_tolerance_inf", ["render", D, "-o", "{out}/old.png", "--tolerance", "inf"], "option --tolerance"),
    ("render_tolerance_negative", ["render", D, "-o", "{out}/old.png", "--tolerance", "-1"], "option --tolerance"),
    ("render_tolerance_zero", ["render", D, "-o", "{out}/old.png", "--tolerance", "0"], "option --tolerance"),
    ("render_max_affine_nan", ["render", D, "-o", "{out}/old.png", "--max-affine", "nan"], "option --max-affine"),
    ("render_max_affine_inf", ["render", D, "-o", "{out}/old.png", "--max-affine", "inf"], "option --max-affine"),
    ("render_escape_radius_negative", ["render", D, "-o", "{out}/old.png", "--escape-radius", "-5"],
     "option --escape-radius"),
    ("render_escape_angle_zero", ["render", D, "-o", "{out}/old.png", "--escape-angle", "0"], "option --escape-angle"),
    ("render_look_at_two_numbers", ["render", D, "-o", "{out}/old.png", "--look-at", "1,2"], "option --look-at"),
    ("render_look_at_nan", ["render", D, "-o", "{out}/old.png", "--look-at", "nan,0,0"], "option --look-at"),
    ("render_look_at_observer", ["render", D, "-o", "{out}/old.png", "--look-at", "0,0,0"],
     "option --look-at: camera: look_at is the observer's own position"),
    ("animate_escape_angle_text", ["animate", D, "-o", "{out}/f_%02d.png", "--pan", "0:10:2", "--escape-angle", "tiny"],
     "option --escape-angle"),
    ("render_windings_negative", ["render", D, "-o", "{out}/old.png", "--windings", "-1"], "option --windings"),
    ("render_windings_huge", ["render", D, "-o", "{out}/old.png", "--windings", "1001"], "option --windings"),
    ("render_method_bogus", ["render", D, "-o", "{out}/old.png", "--method", "magic"], "magic"),
    ("render_stepper_bogus", ["render", D, "-o", "{out}/old.png", "--stepper", "euler"], "euler"),
    ("render_unknown_option", ["render", D, "-o", "{out}/old.png", "--colour", "red"], "unknown option '--colour'"),
    ("render_flag_with_value", ["render", D, "-o", "{out}/old.png", "--quiet=yes"], "takes no value"),
    ("render_no_scene", ["render", "-o", "{out}/old.png"], "expects one scene file"),
    ("render_two_scenes", ["render", D, D, "-o", "{out}/old.png"], "expects one scene file"),
    ("render_output_folder", ["render", D, "-o", "{out}"], "is a folder"),
    ("render_output_no_folder", ["render", D, "-o", "{out}/no/such/x.png"], "does not exist"),
    ("render_output_extension", ["render", D, "-o", "{out}/x.bmpx"], "unknown file type"),
    ("render_output_hidden", ["render", D, "-o", "{out}/.png"], "visible file name"),
    ("render_data_proc", ["render", D, "-o", "{out}/old.png", "--data", "/proc/x.exr"], "--data '/proc/x.exr'"),
    ("render_data_png", ["render", D, "-o", "{out}/old.png", "--data", "{out}/d.png"], "--data"),
    ("render_data_same", ["render", D, "-o", "{out}/old.exr", "--data", "{out}/old.exr"], "same file"),
    ("render_data_with_gpu", ["render", D, "-o", "{out}/old.png", "--data", "{out}/d.exr", "--gpu"], "give --data or --gpu, not both"),
    ("render_orbit_frames_zero", ["render", D, "-o", "{out}/old.png", "--gpu", "--orbit-frames", "0"], "--orbit-frames"),
    ("render_scene_missing", ["render", "{bad}/no_such_scene.json", "-o", "{out}/old.png"], "does not exist"),
    ("render_scene_device", ["render", "/dev/zero", "-o", "{out}/old.png"], "not a regular file"),
    ("render_scene_folder", ["render", "{bad}", "-o", "{out}/old.png"], "is a directory"),
    ("trace_max_steps_negative", ["trace", "--metric", "godel", "--event", "0,0,0,0", "--direction", "1,0,0",
                                  "--max-steps", "-1"], "option --max-steps"),
    ("trace_max_steps_nan", ["trace", "--metric", "godel", "--event", "0,0,0,0", "--direction", "1,0,0",
                             "--max-steps", "nan"], "option --max-steps"),
    ("trace_max_steps_huge", ["trace", "--metric", "godel", "--event", "0,0,0,0", "--direction", "1,0,0",
                              "--max-steps", "1e30"], "option --max-steps"),
    ("trace_max_steps_zero", ["trace", "--metric", "godel", "--event", "0,0,0,0", "--direction", "1,0,0",
                              "--max-steps", "0"], "option --max-steps"),
    ("trace_tolerance_nan", ["trace", "--metric", "godel", "--event", "0,0,0,0", "--direction", "1,0,0",
                             "--tolerance", "nan"], "option --tolerance"),
    ("trace_tolerance_negative", ["trace", "--impact", "10", "--tolerance", "-1"], "option --tolerance"),
    ("trace_event_nan", ["trace", "--metric", "godel", "--event", "nan,0,0,0", "--direction", "1,0,0"], "option --event"),
    ("trace_event_inf", ["trace", "--metric", "godel", "--event", "0,inf,0,0", "--direction", "1,0,0"], "option --event"),
    ("trace_event_three", ["trace", "--metric", "godel", "--event", "0,0,0", "--direction", "1,0,0"], "option --event"),
    ("trace_event_huge", ["trace", "--metric", "godel", "--event", "1e308,0,0,0", "--direction", "1,0,0"], "option --event"),
    ("trace_direction_zero", ["trace", "--metric", "godel", "--event", "0,0,0,0", "--direction", "0,0,0"], "zero vector"),
    ("trace_direction_nan", ["trace", "--metric", "godel", "--event", "0,0,0,0", "--direction", "nan,0,0"], "option --direction"),
    ("trace_param_suffix", ["trace", "--metric", "godel", "--param", "a=0.5xyz", "--event", "0,0,0,0", "--direction", "1,0,0"],
     "--param a"),
    ("trace_param_text", ["trace", "--metric", "godel", "--param", "a=abc", "--event", "0,0,0,0", "--direction", "1,0,0"],
     "--param a"),
    ("trace_param_no_name", ["trace", "--metric", "godel", "--param", "=1", "--event", "0,0,0,0", "--direction", "1,0,0"],
     "NAME=VALUE"),
    ("trace_param_unknown", ["trace", "--metric", "godel", "--param", "b=1", "--event", "0,0,0,0", "--direction", "1,0,0"],
     "no parameter 'b'"),
    ("trace_param_range", ["trace", "--metric", "godel", "--param", "a=1e300", "--event", "0,0,0,0", "--direction", "1,0,0"],
     "--param a"),
    ("trace_metric_bogus", ["trace", "--metric", "vaidya", "--impact", "3"], "option --metric: expected one of"),
    ("trace_impact_negative", ["trace", "--impact", "-1"], "option --impact"),
    ("trace_impact_curved", ["trace", "--metric", "godel", "--impact", "3"], "asymptotically flat"),
    ("trace_distance_zero", ["trace", "--impact", "10", "--distance", "0"], "option --distance"),
    ("trace_nothing", ["trace", "--metric", "godel"], "needs --event"),
    ("trace_both", ["trace", "--impact", "3", "--event", "0,0,0,0", "--direction", "1,0,0"], "not both"),
    ("trace_inside_horizon", ["trace", "--metric", "schwarzschild", "--event", "0,1,0,0", "--direction", "1,0,0"],
     "no static observer here: the event is at or inside the metric's horizon"),
    ("trace_alcubierre_v_huge", ["trace", "--metric", "alcubierre", "--param", "v=1e308", "--event", "0,0,0,0",
                                 "--direction", "1,0,0"], "--param v"),
    ("images_observer_nan", ["images", "--observer", "nan,0,0,0", "--point", "1,0,0"], "option --observer"),
    ("images_a_zero", ["images", "--a", "0", "--point", "1,0,0"], "option --a"),
    ("images_a_huge", ["images", "--a", "1e300", "--point", "1,0,0"], "option --a"),
    ("images_point_far", ["images", "--point", "1e9,0,0"], "within r = 10000 a"),
    ("images_point_nan", ["images", "--point", "1,nan,0"], "option --point"),
    ("images_cylindrical_negative", ["images", "--cylindrical", "-1,0,0"], "radius r must be >= 0"),
    ("images_both_points", ["images", "--point", "1,0,0", "--cylindrical", "1,0,0"], "give --point or --cylindrical, not both"),
    ("images_no_point", ["images"], "exactly one"),
    ("images_windings_huge", ["images", "--point", "1,0,0", "--windings", "2000"], "option --windings"),
    ("images_observer_far", ["images", "--observer", "0,1e6,0,0", "--point", "1,0,0"], "option --observer"),
    ("export_rays_zero", ["export", D, "-o", "{out}/old", "--rays", "0"], "option --rays"),
    ("export_rays_huge", ["export", D, "-o", "{out}/old", "--rays", "1e6"], "option --rays"),
    ("export_into_file", ["export", D, "-o", "{out}/old.png"], "not a folder"),
    ("export_no_parent", ["export", D, "-o", "{out}/no/such/dir"], "does not exist"),
    ("diagram_size_small", ["diagram", D, "-o", "{out}/d.svg", "--size", "10"], "option --size"),
    ("diagram_windings_huge", ["diagram", D, "-o", "{out}/d.svg", "--windings", "60"], "option --windings"),
    ("diagram_extension", ["diagram", D, "-o", "{out}/d.bmpx"], "unknown file type"),
    ("diagram_rays_negative", ["diagram", D, "-o", "{out}/d.svg", "--rays", "-3"], "option --rays"),
    ("diagram_kind_unknown", ["diagram", D, "-o", "{out}/d.svg", "--kind", "phi-t"], "option --kind"),
    ("diagram_kind_empty", ["diagram", D, "-o", "{out}/d.svg", "--kind", ""], "option --kind"),
    ("shade_missing_data", ["shade", D, "{bad}/no_such.exr", "-o", "{out}/old.png"], "does not exist"),
    ("shade_device_data", ["shade", D, "/dev/zero", "-o", "{out}/old.png"], "pixel data '/dev/zero' is not a regular file"),
    ("shade_folder_data", ["shade", D, "{bad}", "-o", "{out}/old.png"], "is a directory, not a file"),
    ("shade_png_data", ["shade", D, "{bad}/texture_garbage.png", "-o", "{out}/old.png"], "cannot read image"),
    ("shade_window_reversed", ["shade", D, "{bad}/no_such.exr", "-o", "{out}/old.png", "--time-window", "1,0"],
     "must not exceed"),
    ("shade_window_nan", ["shade", D, "{bad}/no_such.exr", "-o", "{out}/old.png", "--time-window", "nan,0"],
     "option --time-window"),
    ("shade_temperature_huge", ["shade", D, "{bad}/no_such.exr", "-o", "{out}/old.png", "--temperature", "1e308"],
     "option --temperature"),
    ("shade_one_file", ["shade", D, "-o", "{out}/old.png"], "expects a scene file and a data file"),
    ("shade_uv_offset_nan", ["shade", D, "{bad}/no_such.exr", "-o", "{out}/old.png", "--uv-offset", "nan,0"],
     "option --uv-offset"),
    ("shade_uv_scale_huge", ["shade", D, "{bad}/no_such.exr", "-o", "{out}/old.png", "--uv-scale", "1,1e300"],
     "option --uv-scale"),
    ("shade_blink_period_zero", ["shade", D, "{bad}/no_such.exr", "-o", "{out}/old.png", "--blink", "0,0.5,0,0.1"],
     "option --blink (period)"),
    ("shade_blink_duty_above_one", ["shade", D, "{bad}/no_such.exr", "-o", "{out}/old.png", "--blink", "1,2,0,0.1"],
     "option --blink (duty)"),
    ("shade_blink_three_numbers", ["shade", D, "{bad}/no_such.exr", "-o", "{out}/old.png", "--blink", "1,0.5,0"],
     "option --blink"),
    ("shade_outside_texture_without_window",
     ["shade", D, "{bad}/no_such.exr", "-o", "{out}/old.png", "--outside-texture", "checker"], "--outside-texture goes with --time-window"),
    ("shade_texture_empty_object", ["shade", D, "{bad}/no_such.exr", "-o", "{out}/old.png", "--texture", "=earth"],
     "option --texture"),
    ("shade_sweep_unknown_field", ["shade", D, "{bad}/no_such.exr", "-o", "{out}/%03d.png", "--sweep", "gamma=1:2:3"],
     "cannot sweep 'gamma'"),
    ("shade_sweep_no_pattern", ["shade", D, "{bad}/no_such.exr", "-o", "{out}/old.png", "--sweep", "temperature=3000:9000:5"],
     "exactly one frame number"),
    ("shade_sweep_temperature_low", ["shade", D, "{bad}/no_such.exr", "-o", "{out}/%03d.png", "--sweep", "temperature=10:9000:5"],
     "option --sweep (temperature)"),
    ("shade_sweep_frames_huge", ["shade", D, "{bad}/no_such.exr", "-o", "{out}/%03d.png", "--sweep", "u-offset=0:1:1e9"],
     "--sweep (FRAMES)"),
    ("shade_sweep_window_without_window", ["shade", D, "{bad}/no_such.exr", "-o", "{out}/%03d.png", "--sweep", "time-window=0:1:3"],
     "give --time-window too"),
    # curvature: grids, events and world lines refused before any work.
    ("curvature_dims_zero", ["curvature", "--metric", "kerr", "--dims", "0,5,1", "-o", "{out}/old.vti"], "option --dims"),
    ("curvature_values_budget", ["curvature", "--metric", "kerr", "--dims", "4096,4096,4", "--quantity",
                                 "tidal_eigenvalues", "-o", "{out}/old.vti"], "lower the resolution"),
    ("curvature_at_inf", ["curvature", "--metric", "kerr", "--at", "inf,0,0,0"], "option --at"),
    ("curvature_at_singularity", ["curvature", "--metric", "schwarzschild", "--at", "0,0,0,0"], "not finite"),
    ("curvature_bounds_reversed", ["curvature", "--metric", "kerr", "--bounds", "1,0,0,1,0,0", "--dims", "5,5,1",
                                   "-o", "{out}/old.vti"], "lower bound of axis 1"),
    ("curvature_quantity_bogus", ["curvature", "--metric", "kerr", "--quantity", "torsion", "-o", "{out}/old.vti"],
     "option --quantity"),
    ("curvature_tides_without_scene", ["curvature", "--metric", "kerr", "--tides", "{out}/old.csv"], "give a scene file"),
    ("curvature_lambda_nan", ["curvature", "--metric", "kerr", "--lambda", "nan", "--at", "0,5,0,0"], "option --lambda"),
    ("curvature_scene_and_metric", ["curvature", D, "--metric", "kerr", "--at", "0,0.5,0,0"], "gives one already"),
    ("curvature_proper_time_zero", ["curvature", D, "--tides", "{out}/old.csv", "--proper-time", "0"],
     "--proper-time must not be 0"),
    ("curvature_nothing_asked", ["curvature", "--metric", "kerr"], "curvature needs --at"),
    ("trace_source_plane_zero_normal", ["trace", "--metric", "schwarzschild", "--event", "0,-100,0,0", "--direction",
                                        "1,0.1,0", "--source-plane", "100,0,0,0,0,0"], "the normal"),
    ("trace_source_plane_missed", ["trace", "--metric", "schwarzschild", "--event", "0,-100,0,0", "--direction",
                                   "-1,0,0", "--source-plane", "100,0,0,1,0,0", "--max-steps", "2000"],
     "does not meet the plane"),
    ("unknown_command", ["paint", D], "unknown command"),
    # animate and sweep: every path part and option checked before the first frame.
    ("animate_no_pattern", ["animate", D, "-o", "{out}/old.png", "--pan", "0:10:2"], "exactly one frame number"),
    ("animate_two_numbers", ["animate", D, "-o", "{out}/%d_%d.png", "--pan", "0:10:2"], "exactly one frame number"),
    ("animate_bad_conversion", ["animate", D, "-o", "{out}/%s.png", "--pan", "0:10:2"], "may hold only %d"),
    ("animate_no_path", ["animate", D, "-o", "{out}/%d.png"], "animate needs a path"),
    ("animate_frames_zero", ["animate", D, "-o", "{out}/%d.png", "--pan", "0:10:0"], "--pan (FRAMES)"),
    ("animate_frames_huge", ["animate", D, "-o", "{out}/%d.png", "--pan", "0:10:1e9"], "--pan (FRAMES)"),
    ("animate_pan_nan", ["animate", D, "-o", "{out}/%d.png", "--pan", "nan:10:3"], "--pan (FROM)"),
    ("animate_pan_two_parts", ["animate", D, "-o", "{out}/%d.png", "--pan", "0:10"], "FROM:TO:FRAMES"),
    ("animate_proper_time_inf", ["animate", D, "-o", "{out}/%d.png", "--proper-time", "0:inf:3"], "--proper-time (TO)"),
    ("animate_counts_differ", ["animate", D, "-o", "{out}/%d.png", "--pan", "0:10:2", "--orbit", "0:10:3"],
     "same number of frames"),
    ("animate_motion_alone", ["animate", D, "-o", "{out}/%d.png", "--pan", "0:10:2", "--motion", "static"],
     "--motion goes with --proper-time"),
    ("animate_motion_bogus", ["animate", D, "-o", "{out}/%d.png", "--proper-time", "0:1:2", "--motion", "hover"],
     "option --motion: expected one of static, free_fall; got 'hover'"),
    ("animate_sweep_no_field", ["animate", D, "-o", "{out}/%d.png", "--sweep", "0:1:3"], "FIELD=FROM:TO:FRAMES"),
    ("animate_sweep_unknown_field", ["animate", D, "-o", "{out}/%d.png", "--sweep", "metric.b=0:1:3"], "metric.b"),
    ("animate_sweep_out_of_range", ["animate", D, "-o", "{out}/%d.png", "--sweep", "objects[0].radius=0.1:-1:3"],
     "objects[0].radius"),
    ("animate_frames_range_reversed", ["animate", D, "-o", "{out}/%d.png", "--pan", "0:10:3", "--frames", "2-1"],
     "must not exceed"),
    ("animate_frames_range_outside", ["animate", D, "-o", "{out}/%d.png", "--pan", "0:10:3", "--frames", "0-7"],
     "frames 0 to 2"),
    ("animate_fps_without_movie", ["animate", D, "-o", "{out}/%d.png", "--pan", "0:10:2", "--fps", "30"],
     "--fps goes with --movie"),
    ("animate_fps_zero", ["animate", D, "-o", "{out}/%d.png", "--pan", "0:10:2", "--movie", "{out}/m.mp4", "--fps", "0"],
     "option --fps"),
    ("animate_movie_extension", ["animate", D, "-o", "{out}/%d.png", "--pan", "0:10:2", "--movie", "{out}/m.txt"],
     "--movie"),
    ("animate_movie_from_exr", ["animate", D, "-o", "{out}/%d.exr", "--pan", "0:10:2", "--movie", "{out}/m.mp4"],
     "PNG or JPEG frames"),
    ("animate_output_no_folder", ["animate", D, "-o", "{out}/no/such/%d.png", "--pan", "0:10:2"], "does not exist"),
    ("animate_orbit_frames", ["animate", D, "-o", "{out}/%d.png", "--pan", "0:10:2", "--orbit-frames", "3"],
     "unknown option"),
    ("sweep_no_table", ["sweep", D, "--sweep", "metric.a=1:2:3"], "--table"),
    ("sweep_no_sweep", ["sweep", D, "--table", "{out}/t.csv"], "needs --sweep"),
    ("sweep_table_extension", ["sweep", D, "--sweep", "metric.a=1:2:3", "--table", "{out}/t.png"], "--table"),
    ("sweep_plot_same", ["sweep", D, "--sweep", "metric.a=1:2:3", "--table", "{out}/t.csv", "--plot", "{out}/t.csv"],
     "same file"),
    ("sweep_a_negative", ["sweep", D, "--sweep", "metric.a=1:-2:3", "--table", "{out}/t.csv"], "metric.a"),
]
for name, args, text in cli:
    case(f"cli_{name}", args, "error", text)

# ---- 6. hard but valid: a correct result, finite, exit 0 ---------------------------------------
valid = {
    # Far beyond the horizon (r = 9000 a): the closed form must report no object pixels.
    "goedel_far_sphere": ({"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0, 9000, 0, 0],
                                                                      "radius": 0.25}],
                           "camera": {"projection": "panorama", "fov": [360, 120]}}, "object pixels 0;"),
    "goedel_sphere_on_axis_above": ({"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0, 0, 0, 1],
                                                                                "radius": 0.25}],
                                     "camera": {"projection": "panorama", "fov": [360, 120]}}, "object pixels"),
    "goedel_observer_late": ({"metric": {"name": "godel"}, "observer": {"position": [1e12, 0, 0, 0]},
                              "objects": [{"type": "sphere", "centre": [0, 1, 0, 0], "radius": 0.25}],
                              "camera": {"projection": "panorama", "fov": [360, 120]}}, "object pixels"),
    "goedel_observer_gamma_1000": ({"metric": {"name": "godel"}, "observer": {"velocity": [999, (999**2 - 1) ** 0.5, 0, 0]},
                                    "objects": [{"type": "sphere", "centre": [0, 1, 0, 0], "radius": 0.25}],
                                    "render": {"windings": 0}}, "stops:"),
    "goedel_horizon_sphere": ({"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0, 2, 0, 0],
                                                                          "radius": 0.1}],
                               "camera": {"projection": "panorama", "fov": [360, 120]}}, "object pixels"),
    "goedel_many_windings": ({"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0, 1, 0, 0.5],
                                                                         "radius": 0.25}],
                              "camera": {"projection": "panorama", "fov": [360, 120]},
                              "render": {"windings": 100}}, "object pixels"),
    "goedel_free_fall_fast": ({"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0, 0.3, 0.3, 0],
                                                                          "radius": 0.2, "temperature": 6000,
                                                                          "motion": {"type": "free_fall", "speed": 0.99999999}}],
                               "camera": {"projection": "panorama", "fov": [360, 60]},
                               "render": {"windings": 0, "mesh_resolution": [8, 16]}}, "object pixels"),
    "sr_cube_almost_light": ({"metric": {"name": "minkowski"},
                              "camera": {"projection": "pinhole", "fov": [100, 75], "forward": [0, 0, -1], "up": [0, 1, 0]},
                              "objects": [{"type": "box", "centre": [0, 9.5, 0, -10], "size": [4, 4, 4], "subdivisions": 2,
                                           "temperature": 6000,
                                           "motion": {"type": "constant_velocity", "beta": [0.99999999, 0, 0]}}]},
                             "special relativity"),
    "kerr_extremal": ({"metric": {"name": "kerr", "M": 1, "a": 1}, "observer": {"position": [0, 30, 0, 0]},
                       "camera": {"fov": [40, 20], "forward": [-1, 0, 0], "up": [0, 0, 1]}}, "stops:"),
    "kerr_far_observer": ({"metric": {"name": "schwarzschild"}, "observer": {"position": [0, 1e5, 0, 0]},
                           "camera": {"fov": [0.01, 0.005], "forward": [-1, 0, 0], "up": [0, 0, 1]}}, "stops:"),
    "alcubierre_fast": ({"metric": {"name": "alcubierre", "v": 100}, "observer": {"position": [0, -10, 0, 0]},
                         "camera": {"fov": [60, 30]}}, "stops:"),
    "hdr_background": ({"metric": {"name": "godel"}, "background": [1000, 1000, 1000]}, "object pixels"),
    "light_hot": ({"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0, 1, 0, 0], "radius": 0.25}],
                   "lights": [{"position": [0, 1.5, 0, 0], "temperature": 1e6, "intensity": 1e6}],
                   "render": {"windings": 0}}, "object pixels"),
    "world_line_many_events": ({"metric": {"name": "godel"},
                                "objects": [{"type": "sphere", "centre": [0, 1, 0, 0], "radius": 0.25,
                                             "motion": {"type": "world_line",
                                                        "points": [[-20 + 40 * k / 1999, 1, 0, 0] for k in range(2000)]}}],
                                "camera": {"projection": "panorama", "fov": [360, 120]},
                                "render": {"windings": 0, "mesh_resolution": [8, 16]}}, "object pixels"),
    "name_with_spaces": ({"metric": {"name": "godel"}, "objects": [{"type": "sphere", "name": "Earth (day)",
                                                                      "centre": [0, 1, 0, 0], "radius": 0.25}]},
                         "object pixels"),
    "zero_objects": ({"metric": {"name": "godel"}, "objects": []}, "object pixels 0;"),
    "disk_extremal_with_inner": ({"metric": {"name": "kerr", "a": 1}, "observer": {"position": [0, 30, 0, 8]},
                                  "camera": {"fov": [40, 20], "look_at": [0, 0, 0], "up": [0, 0, 1]},
                                  "objects": [{"type": "disk", "inner_radius": 1.5, "outer_radius": 12}]}, "disk pixels"),
    "disk_edge_on": ({"metric": {"name": "kerr", "a": 0.998}, "observer": {"position": [0, 40, 0, 0]},
                      "camera": {"fov": [40, 20], "look_at": [0, 0, 0], "up": [0, 0, 1]},
                      "objects": [{"type": "disk", "outer_radius": 30, "emission": "flux"}]}, "disk pixels"),
    "disk_face_on_axis": ({"metric": {"name": "kerr", "a": -0.9}, "observer": {"position": [0, 0, 0, 40]},
                           "camera": {"fov": [60, 30], "forward": [0, 0, -1], "up": [1, 0, 0]},
                           "objects": [{"type": "disk", "sense": "retrograde", "outer_radius": 1e5,
                                        "emission": "texture"}]}, "disk pixels"),
    "trailing_whitespace": ({"metric": {"name": "godel"}}, "object pixels 0;"),
    "star_sky_one_big_star": ({"metric": {"name": "schwarzschild"}, "observer": {"position": [0, 20, 0, 0]},
                               "camera": {"fov": [60, 30], "forward": [-1, 0, 0], "up": [0, 0, 1]},
                               "sky": {"type": "stars", "stars": 1, "seed": 0, "size": 10}}, "stops:"),
    "star_sky_hottest_faintest": ({"metric": {"name": "kerr", "a": 0.998}, "observer": {"position": [0, 3, 0, 0]},
                                   "camera": {"projection": "panorama", "fov": [360, 180]},
                                   "sky": {"type": "stars", "stars": 5000, "seed": 2147483647,
                                           "temperatures": [1e6, 1e6], "faintest_magnitude": 15,
                                           "size": 0.18}}, "stops:"),
}
for name, (doc, text) in valid.items():
    f = scene(f"valid_{name}.json", doc)
    case(f"valid_{name}", render(f), "ok", text)
case("valid_export_twice_same_folder", ["export", "{bad}/valid_name_with_spaces.json", "-o", "{out}/old"], "ok",
     "photo_0_Earth__day_.vtm")
case("valid_export_into_new_folder", ["export", "{bad}/valid_goedel_far_sphere.json", "-o", "{out}/new"], "ok",
     "horizon.vtp")
case("valid_trace_godel_many_windings", ["trace", "--metric", "godel", "--event", "0,0,0,0", "--direction", "1,0,0",
                                          "--max-affine", "1000", "--max-steps", "100000"], "ok", "\"reason\"")
case("valid_trace_into_horizon", ["trace", "--metric", "kerr", "--event", "0,10,0,0", "--direction", "-1,0,0"], "ok",
     "\"reason\" : \"horizon\"")
case("valid_images_beyond_horizon", ["images", "--point", "5000,0,0"], "ok", "beyond_horizon")
case("valid_images_on_axis", ["images", "--point", "0,0,1", "--windings", "3"], "ok", "\"status\"")

# GUI sessions rendered by the CLI (docs/SESSIONS.md): malformed files, refused edits, a missing scene.
session_scene = scene("session_scene.json", BASES["godel"])


def session(name, doc):
    return write(name, doc if isinstance(doc, str) else json.dumps(doc, indent=1))


def render_session(session_path):
    return ["render", "--session", session_path, "-o", "{out}/old.png", "--quiet"]


SESSION_BASE = {"lightcone_session": 1, "scene": {"path": "session_scene.json"}}
bad_sessions = {
    "not_json": ("{\"lightcone_session\": 1,", "invalid JSON"),
    "version_3": ({"lightcone_session": 3, "scene": {"path": "session_scene.json"}}, "expected an integer in [1, 2]"),
    "no_version": ({"scene": {"path": "session_scene.json"}}, "lightcone_session"),
    "missing_scene": ({"lightcone_session": 1, "scene": {"path": "nowhere.json"}}, "nowhere.json is not there"),
    "edit_refused": (dict(SESSION_BASE, scene={"path": "session_scene.json",
                                                "edits": [{"field": "objects[0].radius", "value": -1}]}),
                     "scene.edits[0] (objects[0].radius)"),
    "edit_no_such_object": (dict(SESSION_BASE, scene={"path": "session_scene.json",
                                                       "edits": [{"field": "objects[7].radius", "value": 1}]}),
                            "no element [7]"),
    "edit_huge": (dict(SESSION_BASE, scene={"path": "session_scene.json",
                                             "edits": [{"field": "metric.a", "value": 1e300}]}), "metric.a"),
    "edit_unknown_field": (dict(SESSION_BASE, scene={"path": "session_scene.json",
                                                      "edits": [{"field": "metric.b", "value": 1}]}), "unknown field"),
    "edit_into_number": (dict(SESSION_BASE, scene={"path": "session_scene.json",
                                                    "edits": [{"field": "metric.a.x", "value": 1}]}), "has no fields"),
    "window_not_base64": (dict(SESSION_BASE, window={"state": "<not base64>"}), "not base64"),
    "edit_path_deep": (dict(SESSION_BASE, scene={"path": "session_scene.json",
                                                  "edits": [{"field": "a" + ".b" * 100000, "value": 1}]}),
                       "scene fields are at most 64 levels"),
    "many_edits_one_refused": (dict(SESSION_BASE, scene={"path": "session_scene.json", "edits": [
        {"field": "objects[0].radius", "value": -1} if k == 2500 else {"field": "metric.a", "value": 0.5 + 1e-5 * k}
        for k in range(3000)]}), "scene.edits[2500] (objects[0].radius)"),
    "picked_pixel_nan": ("{\"lightcone_session\": 1, \"scene\": {\"path\": \"session_scene.json\"},"
                         " \"view\": {\"picked_pixel\": [1e999, 0]}}", "picked_pixel"),
    "document_not_object": (dict(SESSION_BASE, scene={"path": "session_scene.json", "document": [1, 2]}),
                            "scene.document"),
}
for name, (doc, text) in bad_sessions.items():
    case(f"session_{name}", render_session(session(f"session_{name}.lcsession", doc)), "error", text)
case("session_and_scene_both", ["render", session_scene, "--session", "{bad}/session_version_3.lcsession",
                                "-o", "{out}/old.png"], "error", "not both")
case("session_is_a_folder", render_session("{bad}"), "error", "is a directory")
moved = dict(BASES["godel"])
moved["objects"] = [dict(BASES["godel"]["objects"][0], radius=0.3)]
case("valid_session_scene_moved", render_session(session("valid_session_moved.lcsession", {
    "lightcone_session": 1, "scene": {"path": "gone.json", "document": moved}})), "ok", "(saved scene)")
case("valid_session_with_edits", render_session(session("valid_session_edits.lcsession", {
    "lightcone_session": 1, "scene": {"path": "session_scene.json", "edits": [
        {"field": "metric.a", "value": 0.8}, {"field": "lights", "value": None}]}})), "ok", "object pixels")

# ---- 8. metrics written as formulas (docs/METRICS.md) --------------------------------------------
# Each hostile formula is refused with its own message, in bounded time and memory; the scene
# names the file, the line of the field and, in a formula, the column.
FLAT = "-dt^2 + dx^2 + dy^2 + dz^2"


def formula_scene(name, formula, observer=(0, 30, 0, 0), params=None):
    metric = {"formula": formula}
    metric.update(params or {})
    return scene(name, {"metric": metric, "observer": {"position": list(observer)},
                        "camera": {"width": 48, "height": 24, "fov": [60, 30], "forward": [-1, 0, 0],
                                   "up": [0, 0, 1]}})


bad_formulas = {
    "typo": ({"ds2": FLAT + " + 2/rr*dt^2"}, "column 32: unknown name 'rr'"),
    "one_megabyte": ({"ds2": FLAT + " + 0*dt^2" * (1024 * 1024 // 9)}, "bytes long"),
    "nested_parens": ({"ds2": "(" * 100000 + "dt^2" + ")" * 100000}, "bytes long"),
    "nested_parens_small": ({"ds2": "(" * 5000 + "dt^2" + ")" * 5000}, "inside each other"),
    "long_sum": ({"ds2": "-dt^2" + " + dx^2" * 5000}, "operations deep"),
    "long_name": ({"ds2": FLAT + " + " + "q" * 100000 + "*dt^2"}, "bytes long"),
    "long_name_small": ({"ds2": FLAT + " + " + "q" * 1000 + "*dt^2"}, "a name of 1000 characters"),
    "nan_literal": ({"ds2": FLAT + " + nan*dt^2"}, "unknown name 'nan'"),
    "inf_literal": ({"ds2": FLAT + " + inf*dt^2"}, "unknown name 'inf'"),
    "huge_literal": ({"ds2": FLAT + " + 1e400*dt^2"}, "beyond double's range"),
    "unbalanced_open": ({"ds2": "-(dt^2 + dx^2 + dy^2 + dz^2"}, "never closed"),
    "unbalanced_close": ({"ds2": FLAT + ")"}, "without a matching"),
    "not_utf8": ({"ds2": FLAT + " + \u00ff*dt^2"}, "byte 0xC3"),
    "division_by_zero_at_observer": ({"ds2": FLAT + " + dx^2/(x - 30)"}, "the metric cannot serve at the observer"),
    "not_lorentzian": ({"ds2": "dt^2 + dx^2 + dy^2 + dz^2"}, "not Lorentzian"),
    "self_reference": ({"define": ["r = r + 1"], "ds2": FLAT}, "unknown name 'r'"),
    "cubic": ({"ds2": FLAT + " + dt^3"}, "may be squared"),
    "differential_in_function": ({"ds2": FLAT + " + sin(dt)*dt"}, "inside sin"),
    "unknown_function": ({"ds2": FLAT + " + sine(x)*dt^2"}, "unknown function 'sine'"),
    "empty": ({"ds2": ""}, "empty"),
    "no_line_element": ({}, "needs its line element"),
    "bad_signature": ({"ds2": FLAT, "signature": "++++"}, "expected \"-+++\" or \"+---\""),
    "three_coordinates": ({"ds2": FLAT, "coordinates": ["t", "x", "y"]}, "expected four coordinate names"),
    "coordinate_is_function": ({"ds2": FLAT, "coordinates": ["t", "sin", "y", "z"]}, "is a function"),
    "default_outside_range": ({"ds2": FLAT, "parameters": {"M": {"default": 5, "range": [0, 1]}}},
                              "lies outside the range"),
    "far_field_of_coordinates": ({"ds2": FLAT, "far_field": {"mass": "x"}}, "by the parameters alone"),
    "radius_unknown_name": ({"ds2": FLAT, "radius": "rr"}, "field 'metric.formula.radius': column 1: unknown name 'rr'"),
}
for name, (formula, text) in bad_formulas.items():
    case(f"formula_{name}", render(formula_scene(f"formula_{name}.json", formula)), "error", text)
# Thin disks around typed metrics: one without the symmetries, one whose radius label shrinks.
SCHWARZSCHILD_KS = "-dt^2 + dx^2 + dy^2 + dz^2 + 2*M/r*(dt - (x*dx + y*dy + z*dz)/r)^2"
disk_formulas = {
    "disk_not_stationary": ({"define": ["r = sqrt(x^2 + y^2 + z^2)"], "parameters": {"M": {"default": 1}},
                             "ds2": SCHWARZSCHILD_KS + " + 0.01*sin(t)*dt^2", "horizon": "r/(2*M) - 1",
                             "far_field": {"mass": "M"}},
                            "a thin disk needs a stationary, axisymmetric hole"),
    "disk_radius_shrinks": ({"define": ["r = sqrt(x^2 + y^2 + z^2)"], "parameters": {"M": {"default": 1}},
                             "ds2": SCHWARZSCHILD_KS, "horizon": "r/(2*M) - 1", "far_field": {"mass": "M"},
                             "radius": "100 - r"},
                            "must be finite and grow outwards"),
}
for name, (formula, text) in disk_formulas.items():
    doc = {"metric": {"formula": formula}, "observer": {"position": [0, 40, 0, 8]},
           "camera": {"width": 48, "height": 24, "fov": [60, 30], "look_at": [0, 0, 0], "up": [0, 0, 1]},
           "objects": [{"type": "disk"}]}
    case(f"formula_{name}", render(scene(f"formula_{name}.json", doc)), "error", text)
definitions = {"ds2": FLAT + " + d9999*dx^2",
               "define": ["d0 = x"] + [f"d{i} = d{i - 1} + x" for i in range(1, 10000)]}
case("formula_ten_thousand_definitions_deep", render(formula_scene("formula_deep_definitions.json", definitions)),
     "error", "nest")
wide = {"ds2": FLAT + " + 0*w9999^2*dx^2", "define": [f"w{i} = x*{i}" for i in range(10000)],
        "far_field": {"mass": 0}}
case("valid_formula_ten_thousand_definitions_wide", render(formula_scene("formula_wide_definitions.json", wide)),
     "ok", "object pixels")
case("formula_not_flat_without_max_affine", render(formula_scene("formula_no_end.json", {"ds2": FLAT})), "error",
     "need an end")
case("formula_parameter_out_of_range",
     render(formula_scene("formula_parameter_range.json", {"ds2": FLAT, "parameters": {"M": {"default": 1,
                                                                                             "range": [0, 2]}}},
                          params={"M": 1e300})), "error", "expected a number in [0, 2], got 1e+300")
case("formula_file_missing", render(scene("formula_file_missing.json", {
    "metric": {"file": "nowhere.json"}, "observer": {"position": [0, 30, 0, 0]}})), "error", "nowhere.json")
case("formula_file_is_a_folder", render(scene("formula_file_folder.json", {
    "metric": {"file": "."}, "observer": {"position": [0, 30, 0, 0]}})), "error", "directory")
case("valid_formula_schwarzschild_into_the_singularity",
     render(formula_scene("formula_no_horizon.json", {
         "define": ["r = sqrt(x^2 + y^2 + z^2)"],
         "ds2": FLAT + " + 2/r*(dt - (x*dx + y*dy + z*dz)/r)^2", "far_field": {"mass": 1}})), "ok", "object pixels")
case("metric_check_hostile_formula",
     ["metric", "check", write("formula_metric_nested.json", json.dumps({"ds2": "(" * 5000 + "dt^2" + ")" * 5000}))],
     "error", "formula_metric_nested.json:1: field 'ds2': column 101: more than 100 parentheses")
case("valid_metric_check_kerr", ["metric", "check", "{data}/metrics/kerr.json", "--param", "a=0.99"], "ok",
     "finite and Lorentzian there")
case("metric_check_parameter_out_of_range", ["metric", "check", "{data}/metrics/kerr.json", "--param", "a=1e9"],
     "error", "expected a number in [-1e+06, 1e+06], got 1e+09")
# The catalogue (data/metrics, issue #43) at the ends of each parameter's range: a finite image
# (32 x 16, from the view the file declares); just beyond, refused with the range. Where an end
# moves the metric's scale past the view, the case moves the observer (or shortens the rays) as a
# user would.
CATALOGUE_EDGES = {
    "reissner_nordstrom": [("Q", 0, 0.9999, 1.0001)],
    "janis_newman_winicour": [("gamma", 0.51, 1, 0.5)],
    "kerr_boyer_lindquist": [("a", -0.99, 0.99, 0.995)],
    "kerr_ingoing": [("a", -0.99, 0.99, 0.995)],
    "kerr_newman": [("a", -0.6, 0.6, 0.61), ("Q", 0, 0.6, 0.61)],
    "kerr_de_sitter": [("a", -0.6, 0.6, 0.61), ("Lambda", 0, 0.01, 0.011)],
    "schwarzschild_de_sitter": [("Lambda", 0, 0.03, 0.031)],
    "schwarzschild_anti_de_sitter": [("l", 1, 1e6, 0.99)],
    "bardeen_regular": [("g", 0, 0.75, 0.77)],
    "hayward_regular": [("l", 0, 0.75, 0.77)],
    "taub_nut": [("n", 0, 1, 1.01)],
    "majumdar_papapetrou": [("M2", 0, 10, -0.01), ("d", 0, 1000, -1)],
    "c_metric": [("A", 0, 0.2, 0.21)],
    "ernst": [("B", 0, 0.1, 0.11)],
    "gmghs_dilaton": [("Q", 0, 1.4, 1.41)],
    "de_sitter": [("alpha", 1e-3, 1e6, 0)],
    "de_sitter_static": [("l", 1e-3, 1e6, 0)],
    "anti_de_sitter": [("l", 1e-3, 1e6, 0)],
    "anti_de_sitter_static": [("l", 1e-3, 1e6, 0)],
    "flrw_einstein_de_sitter": [("H0", 1e-6, 1e6, 0)],
    "flrw_lambda_cdm": [("Om", 0.01, 0.99, 1)],
    "einstein_static": [("R", 1e-3, 1e6, 0)],
    "rindler": [("g", 1e-6, 1e6, 0)],
    "barriola_vilenkin": [("k", 0.5, 1, 0.49)],
    "cosmic_string": [("mu", 0, 0.2, 0.21)],
    "melvin": [("B", 1e-6, 1e3, 0)],
    "bertotti_kasner": [("Lambda", 1e-6, 1e6, 0)],
    "plane_wave": [("A", -1, 1, 1.01)],
    "natario": [("v", -100, 100, 101)],
    "van_den_broeck": [("alpha", 0, 100, -0.1)],
    "schwarzschild_rain": [("t_past", -1e3, 1e3, 2e6)],  # far back: the past horizon's rays underflow
    "kerr_rain": [("a", -0.99, 0.99, 0.995), ("t_past", -1e3, 1e3, 2e6)],
    "ellis_drainhole": [("mu", 0, 0.6, 0.61), ("n", 1e-3, 1e3, 0)],
    "morris_thorne_dneg": [("a", 0, 10, -0.01), ("M", 1e-3, 10, 0)],
    "krasnikov_tube": [("delta", 0.01, 1.5, 0), ("eps", 1e-3, 10, 0)],
    "bessel_gravitational_wave": [("C", -3, 3, 3.01)],
}
CATALOGUE_VIEW_CHANGES = {  # (stem, parameter, end): changes to the file's view
    ("de_sitter_static", "l", "low"): {"observer": [0, 3e-4, 0, 0], "max_affine": 0.01},
    ("anti_de_sitter_static", "l", "low"): {"observer": [0, 5e-4, 0, 0], "max_affine": 0.2},
    ("anti_de_sitter", "l", "low"): {"max_affine": 0.01},
    ("einstein_static", "R", "low"): {"observer": [0, 4e-4, 0, 0], "max_affine": 0.012},
    ("melvin", "B", "high"): {"observer": [0, 0.03, 0, 0], "max_affine": 0.1},
    ("bertotti_kasner", "Lambda", "high"): {"max_affine": 0.1},
    ("c_metric", "A", "high"): {"observer": [0, 4, 0, 1]},  # inside the acceleration horizon r = 5 m
    ("plane_wave", "A", "high"): {"observer": [0, 0.5, 0, 6]},  # at x = 3, A x^2 > 1: no static observer
    ("rindler", "g", "high"): {"observer": [0, 1e-6, 0, 0]},  # the observer at x = 1/g
}
for stem, edges in CATALOGUE_EDGES.items():
    metric_path = os.path.join(ROOT, "data", "metrics", stem + ".json")
    metric_file = os.path.relpath(metric_path, BAD)
    with open(metric_path) as f:
        view = json.load(f)["view"]
    for parameter, low, high, beyond in edges:
        for label, value, expect, text in (("low", low, "ok", "object pixels"), ("high", high, "ok", "object pixels"),
                                           ("beyond", beyond, "error", f"parameter '{parameter}': expected a number in")):
            v = dict(view, **CATALOGUE_VIEW_CHANGES.get((stem, parameter, label), {}))
            doc = {"metric": {"file": metric_file, parameter: value}, "observer": {"position": v["observer"]},
                   "camera": {"width": 16, "height": 8, "fov": [60, 30], "look_at": v["look_at"], "up": [0, 0, 1]}}
            if "max_affine" in v:
                doc["render"] = {"max_affine": v["max_affine"]}
            name = f"catalogue_{stem}_{parameter}_{label}"
            # 8 x 4 pixels: a finite image or a refusal is the point, and the extremes are slow.
            case(("valid_" if expect == "ok" else "") + name, render(scene(name + ".json", doc), size=(8, 4)), expect,
                 text)

with open(os.path.join(BAD, "cases.json"), "w") as f:
    json.dump(cases, f, indent=1)
print(f"{len(cases)} cases in {os.path.relpath(BAD, ROOT)}: "
      f"{sum(c['expect'] == 'error' for c in cases)} must fail, {sum(c['expect'] == 'ok' for c in cases)} must succeed")
