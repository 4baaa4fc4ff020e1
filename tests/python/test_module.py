# SPDX-License-Identifier: BSD-3-Clause
"""lightcone._core against the command line and its own promises (ctest label `python`): the same
PNG and EXR bytes as `lightcone render`, the same numbers as `lightcone trace` and `lightcone
images`, the reader's file:line:field text in the exceptions, the GIL released while rays are traced,
a progress callback that stops a render by raising, and per-pixel arrays that match the records."""
import importlib.util
import json
import os
import pathlib
import re
import subprocess
import sys
import tempfile
import threading
import time
import unittest

import numpy as np

import lightcone

ROOT = pathlib.Path(__file__).resolve().parents[2]
BINARY = os.environ.get("LIGHTCONE_BINARY", str(ROOT / "build" / "app" / "lightcone"))


def run(*args):
    return subprocess.run([BINARY, *map(str, args)], capture_output=True, text=True, check=True).stdout


class Module(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.tmp = pathlib.Path(self.dir.name)

    def tearDown(self):
        self.dir.cleanup()

    def test_render_saves_the_bytes_the_command_line_writes(self):
        for name, extra in (("default.json", []), ("kerr_disk.json", ["--tolerance", "1e-7"])):
            cli_png, cli_exr = self.tmp / f"cli_{name}.png", self.tmp / f"cli_{name}.exr"
            run("render", ROOT / "data" / name, "-o", cli_png, "--data", cli_exr, "--width", 64, "--height", 36,
                "--quiet", *extra)
            scene = lightcone.read_scene(ROOT / "data" / name)
            image = lightcone.render(scene, width=64, height=36, tolerance=1e-7 if extra else None)
            py_png, py_exr = self.tmp / f"py_{name}.png", self.tmp / f"py_{name}.exr"
            image.save(str(py_png), str(py_exr))
            self.assertEqual(py_png.read_bytes(), cli_png.read_bytes(), name)
            # The EXR header carries its creation time (capDate), to the second: masked.
            stamp = re.compile(rb"\d{4}:\d\d:\d\d \d\d:\d\d:\d\d")
            self.assertEqual(stamp.sub(b"", py_exr.read_bytes()), stamp.sub(b"", cli_exr.read_bytes()), name)

    def test_arrays_hold_the_colour_and_every_record_field(self):
        scene = lightcone.read_scene(ROOT / "data" / "kerr_disk.json")
        image = lightcone.render(scene, width=80, height=45)
        a = image.arrays
        self.assertEqual(a["rgb"].shape, (45, 80, 3))
        self.assertEqual(a["rgb"].dtype, np.float32)
        disk = a["kind"] == 5
        self.assertGreater(disk.sum(), 500)
        # The disk's records: radii between the ISCO (2.3209 M) and the outer edge, g^4 F / F_max >= 0.
        self.assertGreaterEqual(a["disk_radius"][disk].min(), 2.3208)
        self.assertLessEqual(a["disk_radius"][disk].max(), 20.0001)
        self.assertTrue((a["intensity"][disk] >= 0).all())
        self.assertEqual(image.stats["rays"], 80 * 45)
        observed = image.disk()
        self.assertGreater(observed["flux"], 0)
        self.assertEqual(len(observed["frequency_hz"]), 80)
        # Looking away from the hole no disk light arrives: no mean g (None, not NaN).
        away = lightcone.render(scene.edited({"camera.look_at": [200, 0, 12.9]}), width=32, height=18).disk()
        self.assertEqual(away["flux"], 0)
        self.assertIsNone(away["mean_redshift"])

    def test_magnification_arrays_are_the_command_lines_channels(self):
        """render(magnification=True) carries the ray bundles: the arrays gain magnification, shear
        and rotation, and the EXR is the bytes of `lightcone render --magnification`."""
        cli_exr = self.tmp / "cli.exr"
        run("render", ROOT / "data" / "kerr.json", "-o", self.tmp / "cli.png", "--data", cli_exr, "--width", 24,
            "--height", 12, "--quiet", "--magnification")
        scene = lightcone.read_scene(ROOT / "data" / "kerr.json")
        image = lightcone.render(scene, width=24, height=12, magnification=True)
        py_exr = self.tmp / "py.exr"
        image.save(str(self.tmp / "py.png"), str(py_exr))
        stamp = re.compile(rb"\d{4}:\d\d:\d\d \d\d:\d\d:\d\d")
        self.assertEqual(stamp.sub(b"", py_exr.read_bytes()), stamp.sub(b"", cli_exr.read_bytes()))
        a = image.arrays
        sky = a["kind"] == lightcone.PixelKind.sky
        self.assertEqual(a["magnification"].shape, (12, 24))
        self.assertTrue((a["magnification"][sky] != 0).all())
        self.assertTrue((a["magnification"][~sky] == 0).all())  # the horizon has no source
        self.assertNotIn("magnification", lightcone.render(scene, width=4, height=2).arrays)

    def test_pixel_codes_are_named_as_render_prints_them_and_as_the_docs_table(self):
        scene = lightcone.read_scene(ROOT / "data" / "kerr_disk.json")
        image = lightcone.render(scene, width=48, height=27)
        a = image.arrays
        self.assertTrue(set(np.unique(a["kind"])) <= set(lightcone.PixelKind))
        self.assertGreater((a["kind"] == lightcone.PixelKind.disk).sum(), 50)
        self.assertGreater((a["kind"] == lightcone.PixelKind.horizon).sum(), 10)
        # The names are render's stop counts' names, and count the same pixels.
        for name, count in image.stats["stops"].items():
            self.assertEqual((a["stop_reason"] == lightcone.StopReason[name]).sum(), count, name)
        # docs/SCENES.md's tables give every code its name.
        text = (ROOT / "docs" / "SCENES.md").read_text()
        for enum in (lightcone.PixelKind, lightcone.StopReason):
            for member in enum:
                self.assertRegex(text, rf"\n\| {member.value} \| `{member.name}` \|", member)

    @unittest.skipUnless(importlib.util.find_spec("lightcone.filters"), "a build without VTK")
    def test_a_python_without_debians_vtk_is_told_which_python_to_run(self):
        # -S: no site packages, as a pyenv or conda interpreter lacks Debian's python3-vtk9.
        package_folder = str(pathlib.Path(lightcone.__file__).parents[1])
        bare = subprocess.run([sys.executable, "-S", "-c", "import lightcone.filters"], capture_output=True,
                              text=True, env={**os.environ, "PYTHONPATH": package_folder})
        self.assertNotEqual(bare.returncode, 0)
        self.assertIn("python3-vtk9", bare.stderr)
        self.assertIn("/usr/bin/python3", bare.stderr)

    def test_version_is_the_command_lines(self):
        first = run("--version").splitlines()[0]
        self.assertTrue(first.startswith(f"lightcone {lightcone.__version__} (commit "), first)

    def test_results_carry_the_command_lines_names_and_defaults(self):
        args = ["--metric", "kerr", "--param", "a=0.7", "--event", "0,30,0,2", "--direction", "-1,0.2,0"]
        cli = json.loads(run("trace", *args))
        ray = lightcone.trace("kerr", {"a": 0.7}, [0, 30, 0, 2], [-1, 0.2, 0])
        for key in ("reason", "steps", "max_hamiltonian_drift", "stepper"):
            self.assertIn(key, cli)
        self.assertEqual(ray["steps"], cli["steps"])  # the same default stepper and tolerance
        self.assertAlmostEqual(ray["max_hamiltonian_drift"], cli["max_hamiltonian_drift"], delta=1e-15)
        # No made-up ray: the command line needs --event and --direction, Python too.
        with self.assertRaisesRegex(TypeError, "event is needed"):
            lightcone.trace("kerr", {"a": 0.7}, direction=[-1, 0, 0])
        with self.assertRaisesRegex(TypeError, "point is needed"):
            lightcone.godel_images(1.0)

    def test_trace_and_images_give_the_command_lines_numbers(self):
        cli = json.loads(run("trace", "--metric", "kerr", "--param", "a=0.7", "--event", "0,30,0,2",
                             "--direction", "-1,0.2,0", "--tolerance", "1e-10"))
        ray = lightcone.trace("kerr", {"a": 0.7}, [0, 30, 0, 2], [-1, 0.2, 0], tolerance=1e-10)
        self.assertEqual(ray["reason"], cli["reason"])
        np.testing.assert_allclose(ray["x"][0], cli["start"]["x"], rtol=0, atol=1e-12)
        np.testing.assert_allclose(ray["p"][0], cli["start"]["p"], rtol=0, atol=1e-12)
        cli_images = json.loads(run("images", "--a", 1, "--cylindrical", "1.0,0.7,0.3", "--windings", 1))
        py_images = lightcone.godel_images(1.0, [np.cos(0.7), np.sin(0.7), 0.3], windings=1)
        self.assertEqual(len(py_images["images"]), len(cli_images["images"]))
        for p, c in zip(py_images["images"], cli_images["images"]):
            self.assertAlmostEqual(p["emission_time"], c["emission_time"], places=10)
        # A moved observer: both give the direction in the observer's own frame (the camera's).
        cli_moved = json.loads(run("images", "--a", 1, "--observer", "0,-0.3,0.2,0", "--point", "1,0,0.2"))
        py_moved = lightcone.godel_images(1.0, [1, 0, 0.2], observer=[0, -0.3, 0.2, 0])
        self.assertEqual(len(py_moved["images"]), len(cli_moved["images"]))
        for p, c in zip(py_moved["images"], cli_moved["images"]):
            np.testing.assert_allclose(p["direction"], c["direction"], rtol=0, atol=1e-12)
            self.assertAlmostEqual(p["phi0"], c["phi0"], places=12)
            # One naming: the same keys as the command line's images.
            self.assertEqual(set(p), set(c))

    def test_trace_from_a_named_observer_matches_the_command_line(self):
        args = ["--metric", "alcubierre", "--param", "v=2", "--event", "0,0,0,0", "--direction", "1,0,0",
                "--observer", "normal", "--future", "--max-affine", "0.5"]
        cli = json.loads(run("trace", *args))
        ray = lightcone.trace("alcubierre", {"v": 2}, [0, 0, 0, 0], [1, 0, 0], future=True, max_affine=0.5,
                              observer="normal", stepper="dopri87", tolerance=1e-12)
        np.testing.assert_allclose(ray["p"][0], cli["start"]["p"], rtol=0, atol=1e-12)
        with self.assertRaisesRegex(ValueError, "static, zamo, carter, free_fall, normal"):
            lightcone.trace("kerr", {"a": 0.5}, [0, 10, 0, 0], [1, 0, 0], observer="hovering")

    def test_shadow_outline_of_a_falling_observer_matches_the_command_line_and_synge(self):
        # Synge's radius aberrated by the infall speed sqrt(2M/r) (docs/PHYSICS.md section 9b).
        scene = lightcone.read_scene(ROOT / "data" / "schwarzschild_infall.json")
        out = lightcone.shadow_outline(scene, points=12, tolerance=1e-10)
        r, beta = 10.0, np.sqrt(0.2)
        alpha = np.arcsin(3 * np.sqrt(3) * np.sqrt(1 - 2 / r) / r)
        want = np.degrees(np.arccos((np.cos(alpha) + beta) / (1 + beta * np.cos(alpha))))
        self.assertEqual(out["polar_deg"].shape, (12,))
        self.assertEqual(out["directions"].shape, (12, 3))
        np.testing.assert_allclose(out["polar_deg"], want, rtol=1e-7)
        np.testing.assert_allclose(np.linalg.norm(out["directions"], axis=1), 1, rtol=1e-12)
        self.assertAlmostEqual(out["solid_angle_sr"], 2 * np.pi * (1 - np.cos(np.radians(want))), places=6)
        self.assertFalse(out["from_sky"])
        with tempfile.TemporaryDirectory() as d:
            run("sweep", ROOT / "data" / "schwarzschild_infall.json", "--sweep", "metric.M=1:1:1", "--table",
                pathlib.Path(d) / "t.csv", "--outline", pathlib.Path(d) / "o.csv", "--outline-points", 12, "--quiet")
            rows = [line.split(",") for line in (pathlib.Path(d) / "o.csv").read_text().splitlines()[1:]]
            np.testing.assert_allclose([float(row[2]) for row in rows], out["polar_deg"], rtol=1e-9)
        with self.assertRaisesRegex(ValueError, r"\[8, 100000\]"):
            lightcone.shadow_outline(scene, points=3)

    def test_measure_shadow_reports_its_error_and_equals_sweep(self):
        # The same figures and error estimate as lightcone sweep's row (held to the critical curve
        # in tests/validation).
        scene = lightcone.read_scene(ROOT / "data" / "kerr.json")
        out = lightcone.measure_shadow(scene)
        self.assertGreater(out["edge_error_deg"], 0)
        self.assertLess(out["edge_error_deg"], 1e-8)
        with tempfile.TemporaryDirectory() as d:
            run("sweep", ROOT / "data" / "kerr.json", "--sweep", "metric.a=0.9:0.9:1", "--table",
                pathlib.Path(d) / "t.csv", "--quiet")
            header, row = [line.split(",") for line in (pathlib.Path(d) / "t.csv").read_text().splitlines()]
            cells = dict(zip(header, row))
            self.assertAlmostEqual(float(cells["shadow_edge_error_deg"]), out["edge_error_deg"],
                                   delta=1e-9 * out["edge_error_deg"])
            self.assertAlmostEqual(float(cells["shadow_right_deg"]), out["right_deg"], places=9)

    def test_arguments_pass_the_command_lines_ranges(self):
        # threads=100000 once crashed the interpreter; NaN and out-of-range numbers were accepted.
        scene = lightcone.read_scene(ROOT / "data" / "kerr.json")
        for kwargs, text in [({"threads": 100000}, r"threads: expected an integer in \[0, 256\]"),
                             ({"tolerance": float("nan")}, "tolerance"), ({"tolerance": 0.0}, r"\[1e-15, 0.1\]"),
                             ({"width": 0}, "width")]:
            with self.assertRaisesRegex(ValueError, text):
                lightcone.render(scene, **kwargs)
        for kwargs, text in [({"tolerance": float("nan")}, "tolerance"), ({"max_affine": -1.0}, "max_affine"),
                             ({"direction": [0, 0, 0]}, "zero vector")]:
            with self.assertRaisesRegex(ValueError, text):
                lightcone.trace("kerr", {"a": 0.5}, **{"event": [0, 10, 0, 0], "direction": [1, 0, 0], **kwargs})

    def test_every_numeric_argument_takes_its_range_and_refuses_the_rest(self):
        # Each function's numbers, probed with NaN, +-inf, 0, -1 and huge values (ints: 0, -1, 1e9,
        # 10**400): inside the command line's range the call works, outside it raises ValueError (or
        # TypeError/OverflowError for a value no C++ number holds) -- never another error, a crash or a
        # hang (godel_images(windings=10**9) ran out of memory; windings=-1 returned nothing).
        kerr = lightcone.read_scene(ROOT / "data" / "kerr.json")
        kerr_file = (ROOT / "data" / "metrics" / "kerr.json").read_text()
        inf, nan = float("inf"), float("nan")
        floats, ints = [nan, inf, -inf, 0.0, -1.0, 1e308], [0, -1, 10**9, 10**400]
        cases = [  # (name, call, probes, accepted)
            ("render tolerance", lambda v: lightcone.render(kerr, tolerance=v, width=4, height=2), floats,
             lambda v: 1e-15 <= v <= 0.1),
            ("render threads", lambda v: lightcone.render(kerr, threads=v, width=4, height=2), ints,
             lambda v: 0 <= v <= 256),
            ("render width", lambda v: lightcone.render(kerr, width=v, height=2), ints, lambda v: 1 <= v <= 16384),
            ("render height", lambda v: lightcone.render(kerr, width=4, height=v), ints, lambda v: 1 <= v <= 16384),
            ("measure_shadow tolerance", lambda v: lightcone.measure_shadow(kerr, tolerance=v), floats,
             lambda v: 1e-15 <= v <= 0.1),
            ("shadow_outline points", lambda v: lightcone.shadow_outline(kerr, points=v), ints,
             lambda v: 8 <= v <= 100000),
            ("trace tolerance", lambda v: lightcone.trace("kerr", {"a": 0.5}, [0, 10, 0, 0], [1, 0, 0], tolerance=v),
             floats, lambda v: 1e-15 <= v <= 0.1),
            ("trace max_affine",
             lambda v: lightcone.trace("kerr", {"a": 0.5}, [0, 10, 0, 0], [1, 0, 0], max_affine=v), floats,
             lambda v: 1e-6 <= v <= 1e15),
            ("trace spin", lambda v: lightcone.trace("kerr", {"a": v}, [0, 10, 0, 0], [1, 0, 0]), floats,
             lambda v: -1 <= v <= 1),
            ("godel_images a", lambda v: lightcone.godel_images(v, [1, 0, 0]), floats, lambda v: 1e-3 <= v <= 1e6),
            ("godel_images windings", lambda v: lightcone.godel_images(1.0, [1, 0, 0], windings=v), ints,
             lambda v: 0 <= v <= 1000),
            ("godel_images point", lambda v: lightcone.godel_images(1.0, [v, 0, 0]), floats,
             lambda v: abs(v) <= 1e4),
            ("edited metric.a", lambda v: kerr.edited({"metric.a": v}), floats, lambda v: -1 <= v <= 1),
            ("metric_from_formula a", lambda v: lightcone.metric_from_formula(kerr_file, a=v), floats,
             lambda v: -1e6 <= v <= 1e6),
        ]
        for name, call, probes, accepted in cases:
            for v in probes:
                if accepted(v):
                    call(v)  # any exception fails the test
                else:
                    with self.assertRaises((ValueError, TypeError, OverflowError), msg=f"{name} = {v!r}"):
                        call(v)

    def test_bad_scenes_raise_with_the_readers_text(self):
        with self.assertRaises(Exception) as caught:
            lightcone.read_scene(ROOT / "tests" / "data" / "bad_radius.json")
        self.assertIn("bad_radius.json:5: field 'objects[0].radius': expected a number in [1e-06, 1e+06], got -0.5",
                      str(caught.exception))
        scene = lightcone.read_scene({"metric": {"name": "kerr", "a": 0.9}, "observer": {"position": [0, 30, 0, 8]},
                                      "objects": [{"type": "disk"}]})
        with self.assertRaises(Exception) as caught:
            scene.edited({"objects[0].inner_radius": 2})
        self.assertIn("objects[0].inner_radius", str(caught.exception))
        self.assertIn("innermost stable circular orbit", str(caught.exception))
        self.assertEqual(scene.edited({"metric.a": 0.5}).document["metric"]["a"], 0.5)

    def test_the_gil_is_released_while_rays_are_traced(self):
        scene = lightcone.read_scene(ROOT / "data" / "kerr.json")
        ticks = [0]
        done = threading.Event()

        def count():
            while not done.is_set():
                ticks[0] += 1

        counter = threading.Thread(target=count)
        counter.start()
        start = time.perf_counter()
        lightcone.render(scene, width=200, height=100, threads=1)
        seconds = time.perf_counter() - start
        done.set()
        counter.join()
        # A Python loop ticks ~10^6 times a second; held out by the GIL it would barely tick at all.
        self.assertGreater(ticks[0], 1e4 * seconds, f"{ticks[0]} ticks in {seconds:.2f} s")

    def test_progress_may_stop_a_render_by_raising(self):
        scene = lightcone.read_scene(ROOT / "data" / "kerr.json")
        seen = []

        def progress(fraction):
            seen.append(fraction)
            if fraction > 0.2:
                raise KeyboardInterrupt("stop")

        with self.assertRaises(KeyboardInterrupt):
            lightcone.render(scene, width=120, height=60, progress=progress)
        self.assertTrue(seen)


    def test_metrics_lists_every_metric_file_as_metric_list_does(self):
        # The checkout's data/metrics (this build lies in the checkout), each file once, by stem.
        listed = {m["name"]: m for m in lightcone.metrics()}
        on_disk = sorted(p.stem for p in (ROOT / "data" / "metrics").glob("*.json"))
        self.assertEqual(sorted(listed), on_disk)
        kerr = listed["kerr"]
        self.assertEqual(kerr["metric"], "kerr-formula")
        self.assertEqual(kerr["parameters"], {"M": 1.0, "a": 0.9})
        self.assertEqual(pathlib.Path(kerr["file"]).resolve(), (ROOT / "data" / "metrics" / "kerr.json").resolve())
        self.assertEqual(listed["schwarzschild_spherical"]["chart"], "spherical")
        self.assertIn("Ellis", listed["ellis_wormhole"]["summary"])

    def test_metrics_from_formulas_and_sympy_match_the_builtins(self):
        kerr = lightcone.metric_from_formula((ROOT / "data" / "metrics" / "kerr.json").read_text(), a=0.9)
        self.assertEqual(kerr.name, "kerr-formula")
        self.assertEqual(kerr.parameters, {"M": 1.0, "a": 0.9})
        # The same ray through the formula and through the built-in Kerr (C++ with Eigen's autodiff).
        a = lightcone.trace(kerr, event=[0, 30, 2, 3], direction=[-1, 0.3, -0.1], tolerance=1e-11)
        b = lightcone.trace("kerr", {"M": 1.0, "a": 0.9}, event=[0, 30, 2, 3], direction=[-1, 0.3, -0.1],
                            tolerance=1e-11)
        self.assertEqual(a["reason"], b["reason"])
        np.testing.assert_allclose(a["p"][-1], b["p"][-1], rtol=1e-9, atol=1e-12)
        self.assertEqual(kerr.problem([0, 10, 1, 2]), "")
        self.assertEqual(kerr.signature([0, 10, 1, 2]), "(+,-,-,-)")
        self.assertEqual(kerr.derivatives([0, 10, 1, 2]).shape, (4, 4, 4))
        # Metric.from_formula is the same constructor.
        same = lightcone.Metric.from_formula((ROOT / "data" / "metrics" / "kerr.json").read_text(), a=0.9)
        np.testing.assert_array_equal(same.g([0, 10, 1, 2]), kerr.g([0, 10, 1, 2]))
        with self.assertRaisesRegex(ValueError, "field 'ds2': column 14: unknown name 'rr'"):
            lightcone.metric_from_formula({"ds2": "-dt^2 + dx^2*rr + dy^2 + dz^2"})
        # A scene names the metric inline and renders it.
        scene = lightcone.read_scene({"metric": kerr.scene_block(), "observer": {"position": [0, 30, 0, 0]},
                                      "camera": {"width": 24, "height": 12, "fov": [40, 20], "forward": [-1, 0, 0],
                                                 "up": [0, 0, 1]}})
        self.assertEqual(scene.metric, "kerr-formula")
        self.assertGreater(lightcone.render(scene).stats["rays"], 0)

    @unittest.skipUnless(importlib.util.find_spec("sympy"), "sympy is not installed (Debian: python3-sympy)")
    def test_a_sympy_matrix_in_spherical_coordinates_is_the_cartesian_formula(self):
        import sympy
        t, r, th, ph, M = sympy.symbols("t r theta phi M", positive=True)
        # Schwarzschild, outgoing Eddington-Finkelstein: the built-in's time, typed as a physicist would.
        g = sympy.Matrix([[-1 + 2 * M / r, -2 * M / r, 0, 0], [-2 * M / r, 1 + 2 * M / r, 0, 0],
                          [0, 0, r**2, 0], [0, 0, 0, r**2 * sympy.sin(th)**2]])
        spherical = lightcone.metric_from_sympy(g, [t, r, th, ph], parameters={M: (1, (1e-6, 1e6))}, chart="spherical",
                                                far_field={"mass": M}, M=1.5)
        cartesian = lightcone.metric_from_formula((ROOT / "data" / "metrics" / "schwarzschild.json").read_text(), M=1.5)
        for event in ([0, 7, -2, 3], [0, 0, 0, 9], [0, 1e-12, 0, -5], [1, -4, 4, 0.5]):
            np.testing.assert_allclose(spherical.g(event), cartesian.g(event), rtol=0, atol=1e-7)
            np.testing.assert_allclose(spherical.derivatives(event), cartesian.derivatives(event), rtol=0, atol=1e-6)
        with self.assertRaisesRegex(ValueError, "no counterpart"):
            lightcone.metric_from_sympy(sympy.diag(-1, 1, 1, sympy.besselk(0, r)), [t, r, th, ph], chart="spherical")
        with self.assertRaisesRegex(ValueError, "orders 0 and 1"):
            lightcone.metric_from_sympy(sympy.diag(-1, 1, 1, sympy.besselj(sympy.Symbol("nu"), r)), [t, r, th, ph],
                                        chart="spherical")

    @unittest.skipUnless(importlib.util.find_spec("sympy"), "sympy is not installed (Debian: python3-sympy)")
    def test_kramers_bessel_wave_typed_in_sympy_is_the_catalogue_file(self):
        # EinsteinPy's BesselGravitationalWave as it should read (besselj(order, x)), through sympy.
        import sympy
        t, rho, ph, z, C = sympy.symbols("t rho phi z C", real=True)
        J0, J1 = sympy.besselj(0, rho), sympy.besselj(1, rho)
        U = C * J0 * sympy.cos(t)
        K = C**2 * rho / 2 * (rho * (J0**2 + J1**2) - 2 * J0 * J1 * sympy.cos(t)**2)
        g = sympy.diag(-sympy.exp(2 * K - 2 * U), sympy.exp(2 * K - 2 * U), rho**2 * sympy.exp(-2 * U),
                       sympy.exp(2 * U))
        typed = lightcone.metric_from_sympy(g, [t, rho, ph, z], parameters={C: (0.5, (-3, 3))}, chart="cylindrical",
                                            C=0.8)
        shipped = lightcone.metric_from_formula(
            (ROOT / "data" / "metrics" / "bessel_gravitational_wave.json").read_text(), C=0.8)
        for event in ([0.7, 1.3, -1.1, 0.2], [2.0, 0.05, 0.02, 1.0], [-1.0, -5.0, 4.0, 0.5]):
            np.testing.assert_allclose(typed.g(event), shipped.g(event), rtol=1e-12, atol=1e-12)
            np.testing.assert_allclose(typed.derivatives(event), shipped.derivatives(event), rtol=1e-10, atol=1e-10)


if __name__ == "__main__":
    unittest.main(verbosity=2)
