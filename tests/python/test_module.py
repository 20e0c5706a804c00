"""The Python module against the command line: the same numbers, the same bytes, the same errors.

Run by ctest (tests/CMakeLists.txt) with Debian's python3, PYTHONPATH at build/python and
TUMBLE_EXECUTABLE naming the CLI built beside it; TUMBLE_SCENE picks the scene of
SimulateMatchesCsv (one ctest case a shipped scene)."""

import base64
import csv
import os
import pathlib
import re
import subprocess
import sys
import tempfile
import threading
import unittest

import numpy as np

import tumble

SOURCE = pathlib.Path(os.environ.get("TUMBLE_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
EXECUTABLE = os.environ.get("TUMBLE_EXECUTABLE", "tumble")
SCENES = SOURCE / "scenes"


def cli(*args, cwd=None):
    return subprocess.run([EXECUTABLE, *map(str, args)], capture_output=True, text=True, cwd=cwd)


def bits(array):
    """The float64s' bit patterns: equal only when every number is the same bit for bit."""
    return np.ascontiguousarray(array, dtype=np.float64).view(np.int64)


def csv_rows(path):
    """{body: [[t, x, y, ..., energy], ...]} of a `tumble simulate` CSV, parsed exactly."""
    rows = {}
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        assert header[:2] == ["t", "body"], header
        for row in reader:
            rows.setdefault(row[1], []).append([float(row[0])] + [float(v) for v in row[2:]])
    return rows


class SimulateMatchesCsv(unittest.TestCase):
    """scene.simulate(every) holds the CSV's numbers bit for bit, for a shipped scene."""

    def test_the_arrays_are_the_csvs_numbers(self):
        scene_path = SCENES / os.environ.get("TUMBLE_SCENE", "dropped_cube.toml")
        every = 60
        with tempfile.TemporaryDirectory() as tmp:
            out = pathlib.Path(tmp) / "states.csv"
            done = cli("simulate", scene_path, "--every", every, "--out", out)
            self.assertEqual(done.returncode, 0, done.stderr)
            expected = csv_rows(out)
        run = tumble.load(scene_path).simulate(every=every)
        self.assertEqual(run.names, list(expected))
        for track in run:
            table = np.array(expected[track.name])
            self.assertEqual(len(run.t), len(table))
            self.assertTrue(np.array_equal(bits(run.t), bits(table[:, 0])))
            columns = np.column_stack([track.position, track.velocity, track.orientation,
                                       track.angular_velocity, track.momentum,
                                       track.angular_momentum, track.energy])
            self.assertEqual(columns.shape, (len(table), 20))
            self.assertTrue(np.array_equal(bits(columns), bits(table[:, 1:])),
                            f"{track.name}: arrays differ from the CSV")


class Errors(unittest.TestCase):
    def test_a_bad_scene_raises_scene_error_with_the_clis_message(self):
        text = 'duration = 1.0\n[[bodies]]\nname = "a"\nshape = "ball"\n'
        with tempfile.TemporaryDirectory() as tmp:
            path = pathlib.Path(tmp) / "bad.toml"
            path.write_text(text)
            done = cli("check", path)
            self.assertEqual(done.returncode, 2)
            with self.assertRaises(tumble.SceneError) as raised:
                tumble.load(path)
        error = raised.exception
        self.assertEqual("tumble: " + str(error), done.stderr.strip())
        self.assertEqual((error.file, error.line, error.column, error.key),
                         (str(path), 4, 9, "bodies[0].shape"))
        self.assertIsInstance(error, ValueError)

    def test_loads_names_the_given_path_and_a_syntax_error_has_no_key(self):
        with self.assertRaises(tumble.SceneError) as raised:
            tumble.loads("duration = \n", path="inline.toml")
        error = raised.exception
        self.assertEqual((error.file, error.line, error.key), ("inline.toml", 1, None))
        self.assertIn("TOML syntax error", error.message)

    def test_a_missing_file_names_it(self):
        with self.assertRaises(tumble.SceneError) as raised:
            tumble.load("/no/such/scene.toml")
        self.assertEqual(raised.exception.file, "/no/such/scene.toml")
        self.assertIsNone(raised.exception.line)

    def test_an_impossible_override_is_a_scene_error(self):
        scene = tumble.load(SCENES / "dropped_cube.toml")
        with tempfile.TemporaryDirectory() as tmp:
            with self.assertRaises(tumble.SceneError) as raised:
                scene.render(output=tmp, width=321, height=180)  # odd: no 4:2:0 MP4
            self.assertIn("width", str(raised.exception))
            with self.assertRaises(ValueError):
                scene.simulate(every=0)

    def test_check_returns_the_clis_warnings(self):
        path = SCENES / "spinning_top.toml"
        done = cli("check", path)
        expected = [line[len("tumble: warning: "):] for line in done.stdout.splitlines()
                    if line.startswith("tumble: warning: ")]
        self.assertEqual(tumble.load(path).check(), expected)
        # a scene with a step too coarse for its spring: at least one warning, told the same way
        text = (SCENES / "cube_on_spring.toml").read_text()
        text = re.sub(r"(?m)^dt\s*=.*$", "dt = 0.5", text)
        with tempfile.TemporaryDirectory() as tmp:
            coarse = pathlib.Path(tmp) / "coarse.toml"
            coarse.write_text(text)
            done = cli("check", coarse)
            expected = [line[len("tumble: warning: "):] for line in done.stdout.splitlines()
                        if line.startswith("tumble: warning: ")]
            self.assertTrue(expected, done.stdout)
            self.assertEqual(tumble.load(coarse).check(), expected)


def folder_bytes(folder):
    """{relative path: bytes} of every file a render wrote but report.json (its timings)."""
    folder = pathlib.Path(folder)
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*"))
            if p.is_file() and p.name != "report.json"}


class Render(unittest.TestCase):
    def test_render_writes_the_clis_bytes(self):
        scene_path = SCENES / "dropped_cube.toml"
        with tempfile.TemporaryDirectory() as tmp:
            a, b = pathlib.Path(tmp) / "cli", pathlib.Path(tmp) / "python"
            done = cli("render", scene_path, "-o", a, "--width", 320, "--height", 180,
                       "--format", "mp4,gif,gltf", "-q")
            self.assertEqual(done.returncode, 0, done.stderr)
            render = tumble.load(scene_path).render(output=b, width=320, height=180,
                                                    formats=["mp4", "gif", "gltf"])
            (cli_folder,) = a.iterdir()
            expected, got = folder_bytes(cli_folder), folder_bytes(render.directory)
            self.assertEqual(sorted(expected), sorted(got))
            self.assertGreater(len(expected), 10)
            for name in expected:
                self.assertEqual(expected[name], got[name], name)
            self.assertEqual(render.report["width"], 320)
            self.assertEqual(render.report["frames"]["count"],
                             len(list((render.directory / "frames").iterdir())))
            self.assertEqual(set(render.videos), {"mp4", "gif"})
            self.assertTrue(render.video.is_file())
            self.assertIn("frames", render.files)
            self.assertEqual(render.gltf, render.directory / "dropped_cube.glb")
            self.assertIsNone(render.html)
            self.assertIn("dropped_cube.glb", expected)

            # In Jupyter: the MP4's own bytes in a data URI, the poster beside it.
            html = render._repr_html_()
            data = re.search(r'src="data:video/mp4;base64,([^"]+)"', html)
            self.assertIsNotNone(data, html[:200])
            self.assertEqual(base64.b64decode(data[1]), render.videos["mp4"].read_bytes())
            self.assertIn('poster="data:image/png;base64,', html)
            gif = tumble.Video(render.videos["gif"])._repr_html_()
            data = re.search(r'<img src="data:image/gif;base64,([^"]+)"', gif)
            self.assertEqual(base64.b64decode(data[1]), render.videos["gif"].read_bytes())
            with self.assertRaises(FileNotFoundError):
                tumble.Video(pathlib.Path(tmp) / "none.mp4")

    def test_the_gil_is_released_while_rendering(self):
        scene = tumble.load(SCENES / "dropped_cube.toml")
        with tempfile.TemporaryDirectory() as tmp:
            finished = threading.Event()
            failure = []

            def work():
                try:
                    scene.render(output=tmp, width=320, height=180, frames=False)
                except Exception as error:  # noqa: BLE001 - reported below
                    failure.append(error)
                finally:
                    finished.set()

            counts_during = 0
            thread = threading.Thread(target=work)
            thread.start()
            while not finished.is_set():
                counts_during += 1
            thread.join()
            self.assertEqual(failure, [])
            # Held by the render, the GIL would let this loop run only between Python's bytecodes
            # of the render thread: a handful of times. Released, it spins all along.
            self.assertGreater(counts_during, 100000)


STOPPED_BY_CTRL_C = r"""
import os, pathlib, signal, sys, threading
import tumble
out = pathlib.Path(sys.argv[2])
threading.Timer(1.0, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
try:
    tumble.load(sys.argv[1]).render(output=out, width=320, height=180)
except KeyboardInterrupt:
    left = sorted(p.name for p in out.iterdir()) if out.exists() else []
    print("interrupted", left)
    sys.exit(0)
print("not interrupted")
sys.exit(1)
"""


class CtrlC(unittest.TestCase):
    def test_ctrl_c_stops_a_render_and_leaves_no_folder(self):
        with tempfile.TemporaryDirectory() as tmp:
            scene = pathlib.Path(tmp) / "long.toml"
            text = (SCENES / "dropped_cube.toml").read_text()
            scene.write_text(re.sub(r"(?m)^duration\s*=.*$", "duration = 60.0", text))
            done = subprocess.run([sys.executable, "-c", STOPPED_BY_CTRL_C, scene,
                                   pathlib.Path(tmp) / "out"], capture_output=True, text=True,
                                  timeout=120)
            self.assertEqual(done.returncode, 0, done.stdout + done.stderr)
            # Nothing of the stopped render is left: not its folder, not its staging folder.
            self.assertEqual(done.stdout.strip(), "interrupted []")


class Installed(unittest.TestCase):
    def test_cmake_install_makes_import_tumble_work_from_the_user_site(self):
        build = pathlib.Path(tumble.__file__).parents[2]
        with tempfile.TemporaryDirectory() as prefix:
            done = subprocess.run(["cmake", "--install", build, "--prefix", prefix],
                                  capture_output=True, text=True)
            self.assertEqual(done.returncode, 0, done.stderr)
            env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
            env["PYTHONUSERBASE"] = prefix
            probe = ("import tumble; print(tumble.__file__); print(tumble._shader_directory()); "
                     "print(len(tumble.load(%r).simulate(every=600).t)); "
                     "print(tumble._web_directory())"
                     % str(SCENES / "dropped_cube.toml"))
            done = subprocess.run(["/usr/bin/python3", "-c", probe], capture_output=True,
                                  text=True, env=env, cwd=prefix)
            self.assertEqual(done.returncode, 0, done.stderr)
            module, shaders, samples, web = done.stdout.split("\n")[:4]
            self.assertTrue(module.startswith(prefix), module)
            self.assertTrue(shaders.startswith(prefix), shaders)
            self.assertGreater(int(samples), 1)
            # The replay's page, player and three.js inside the package too.
            self.assertTrue(web.startswith(prefix), web)
            self.assertTrue((pathlib.Path(web) / "dist" / "three.bundle.js").is_file())


if __name__ == "__main__":
    unittest.main()
