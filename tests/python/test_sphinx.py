"""The Sphinx extension tumble.sphinx: its directive renders a scene while a site builds, the page
plays the video in headless Chromium, a second build renders nothing, an edited scene renders
again, a bad scene stops the build with tumble's message; and the repository's docs/ site builds.

Run by ctest (tests/CMakeLists.txt) with Debian's python3 (python3-sphinx 5.3) and PYTHONPATH at
build/python; TUMBLE_DOCS_OUTPUT is where DocsSite builds docs/ (build/docs)."""

import json
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import textwrap
import unittest

import tumble

import headless_chromium

SOURCE = pathlib.Path(os.environ.get("TUMBLE_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
SCENES = SOURCE / "scenes"
RENDERED = re.compile(r"^tumble: rendered (\S+) \((\w+), (\d+)x(\d+)\) into (_tumble/\S+) in ",
                      re.M)


def sphinx_build(source, out, *options):
    """python3 -m sphinx -b html SOURCE OUT: the finished process, stdout and stderr together."""
    return subprocess.run([sys.executable, "-m", "sphinx", "-b", "html", *options, str(source),
                           str(out)], capture_output=True, text=True)


def output_of(done):
    return done.stdout + done.stderr


def make_project(root, pages, scenes=("dropped_cube.toml",)):
    """A Sphinx project in root/src: conf.py, the pages ({name: reST}) and copies of the shipped
    scenes in src/scenes/. Returns the source folder."""
    source = pathlib.Path(root) / "src"
    (source / "scenes").mkdir(parents=True)
    (source / "conf.py").write_text('project = "t"\nextensions = ["tumble.sphinx"]\n')
    for name in scenes:
        (source / "scenes" / name).write_bytes((SCENES / name).read_bytes())
    for name, text in pages.items():
        (source / name).parent.mkdir(parents=True, exist_ok=True)
        (source / name).write_text(textwrap.dedent(text))
    return source


def stamps(folder):
    """{path: (mtime in ns, bytes)} of every file under folder."""
    return {str(p.relative_to(folder)): (p.stat().st_mtime_ns, p.read_bytes())
            for p in sorted(pathlib.Path(folder).rglob("*")) if p.is_file()}


# Plays every <video> of the page muted and reports, once it has played (currentTime > 0) or
# failed, its duration, readyState, currentTime and error; loads its poster, if it has one, as an
# Image; and reports each <img class="tumble">'s natural size. A video that neither plays nor fails
# within 20 s is reported as it stands then (a bound against a hang, not a figure under test).
PLAY_EVERY_VIDEO = r"""
(async () => {
  const played = v => new Promise(done => {
    const report = () => done({src: v.currentSrc, duration: v.duration, readyState: v.readyState,
                               currentTime: v.currentTime, error: v.error && v.error.code});
    v.addEventListener('timeupdate', () => { if (v.currentTime > 0) report(); });
    v.addEventListener('error', report, true);
    setTimeout(report, 20000);
    v.muted = true;
    v.play().catch(e => done({playError: String(e), readyState: v.readyState}));
  });
  const image = url => new Promise(done => {
    const i = new Image();
    i.onload = () => done(i.naturalWidth);
    i.onerror = () => done(-1);
    i.src = url;
  });
  const videos = [];
  for (const v of document.querySelectorAll('video')) {
    const poster = v.getAttribute('poster') ? await image(v.poster) : null;
    videos.push(Object.assign(await played(v), {poster: poster, posterUrl: v.poster}));
  }
  const images = [];
  for (const i of document.querySelectorAll('img.tumble')) {
    await (i.complete ? Promise.resolve() : new Promise(r => { i.onload = i.onerror = r; }));
    images.push({src: i.currentSrc, naturalWidth: i.naturalWidth, naturalHeight: i.naturalHeight});
  }
  return {videos: videos, images: images};
})()
"""


class Directive(unittest.TestCase):
    """One site, built once: an MP4 with a poster and a caption and a GIF on the index, a WebM on
    a page in a subfolder whose scene path goes up a level."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.source = make_project(cls.tmp.name, {
            "index.rst": """
                Index
                =====

                .. toctree::

                   sub/page

                .. tumble:: scenes/dropped_cube.toml
                   :width: 320
                   :height: 180
                   :poster:
                   :caption: A cube *lands* and comes to rest.

                .. tumble:: /scenes/dropped_cube.toml
                   :format: gif
                   :width: 160
                """,
            "sub/page.rst": """
                Page
                ====

                .. tumble:: ../scenes/dropped_cube.toml
                   :format: webm
                   :width: 320
                   :height: 180
                """})
        cls.out = pathlib.Path(cls.tmp.name) / "html"
        cls.first = sphinx_build(cls.source, cls.out)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_the_build_renders_each_directive_once_in_its_format_and_size(self):
        self.assertEqual(self.first.returncode, 0, output_of(self.first))
        rendered = sorted((fmt, int(w), int(h)) for _, fmt, w, h, _ in
                          RENDERED.findall(self.first.stdout))
        self.assertEqual(rendered, [("gif", 160, 90), ("mp4", 320, 180), ("webm", 320, 180)])
        for scene, fmt, width, height, folder in RENDERED.findall(self.first.stdout):
            self.assertEqual(scene, str(self.source / "scenes" / "dropped_cube.toml"))
            report = json.loads((self.out / folder / "dropped_cube" / "report.json").read_text())
            self.assertEqual((report["width"], report["height"]), (int(width), int(height)))
            self.assertEqual(list(report["videos"]), [fmt])  # the one format asked for
            self.assertIsNone(report["frames_directory"])  # and no PNG frames
            self.assertFalse((self.out / folder / "dropped_cube" / "frames").exists())

    def test_the_html_is_a_video_with_a_poster_a_figure_an_img_and_a_video_up_a_folder(self):
        index = (self.out / "index.html").read_text()
        video = re.search(r'<figure class="tumble-figure[^"]*"[^>]*>\s*(<video [^>]*>)'
                          r'<source src="(_tumble/dropped_cube-[0-9a-f]{16}/dropped_cube/'
                          r'dropped_cube\.mp4)" type="video/mp4">', index)
        self.assertIsNotNone(video, index)
        self.assertIn('controls width="320" height="180"', video[1])
        poster = re.search(r'poster="([^"]+)"', video[1])
        self.assertRegex(poster[1], r"^_tumble/dropped_cube-[0-9a-f]{16}/dropped_cube/poster\.png$")
        self.assertTrue((self.out / poster[1]).is_file())
        self.assertTrue((self.out / video[2]).is_file())
        self.assertRegex(index, r'<figcaption>\s*<p><span class="caption-text">A cube <em>lands'
                                r'</em> and comes to rest\.</span>')
        gif = re.search(r'<div class="tumble"><img class="tumble" src="([^"]+\.gif)" width="160" '
                        r'height="90"', index)
        self.assertIsNotNone(gif, index)
        self.assertTrue((self.out / gif[1]).is_file())
        page = (self.out / "sub" / "page.html").read_text()
        webm = re.search(r'(<video [^>]*>)<source src="(\.\./_tumble/[^"]+\.webm)" '
                         r'type="video/webm">', page)
        self.assertIsNotNone(webm, page)
        self.assertNotIn("poster=", webm[1])  # only with :poster:
        self.assertTrue((self.out / "sub" / webm[2]).resolve().is_file())

    @unittest.skipUnless(headless_chromium.available(), "needs chromium (scripts/install-deps)")
    def test_chromium_plays_each_video_and_shows_the_poster(self):
        self.assertEqual(self.first.returncode, 0, output_of(self.first))
        duration = tumble.load(self.source / "scenes" / "dropped_cube.toml").duration
        with headless_chromium.Page((self.out / "index.html").as_uri()) as page:
            index = page.evaluate(PLAY_EVERY_VIDEO)
        with headless_chromium.Page((self.out / "sub" / "page.html").as_uri()) as page:
            sub = page.evaluate(PLAY_EVERY_VIDEO)
        print(json.dumps({"index": index, "sub/page": sub}), file=sys.stderr)
        (mp4,), (webm,) = index["videos"], sub["videos"]
        for video, kind in ((mp4, ".mp4"), (webm, ".webm")):
            self.assertTrue(video["src"].endswith(kind), video)
            self.assertIsNone(video["error"], video)
            self.assertAlmostEqual(video["duration"], duration, delta=0.05)
            self.assertGreaterEqual(video["readyState"], 2)  # HAVE_CURRENT_DATA: a frame decoded
            self.assertGreater(video["currentTime"], 0)      # and it played
        self.assertEqual(mp4["poster"], 320)  # the poster image loaded, at the render's width
        self.assertIsNone(webm["poster"])
        self.assertEqual(index["images"], [{"src": index["images"][0]["src"], "naturalWidth": 160,
                                            "naturalHeight": 90}])

    def test_a_second_build_renders_nothing_and_leaves_the_files_as_they_were(self):
        self.assertEqual(self.first.returncode, 0, output_of(self.first))
        before = stamps(self.out / "_tumble")
        self.assertEqual(len([p for p in before if p.endswith("report.json")]), 3)
        again = sphinx_build(self.source, self.out)
        self.assertEqual(again.returncode, 0, output_of(again))
        self.assertEqual(RENDERED.findall(again.stdout), [])
        self.assertEqual(stamps(self.out / "_tumble"), before)
        # -E reads every page again, so each directive runs: its render is found, not made.
        fresh = sphinx_build(self.source, self.out, "-E")
        self.assertEqual(fresh.returncode, 0, output_of(fresh))
        self.assertIn("reading sources... [100%] sub/page", fresh.stdout)
        self.assertEqual(RENDERED.findall(fresh.stdout), [])
        self.assertEqual(stamps(self.out / "_tumble"), before)


class Rebuilds(unittest.TestCase):
    def test_an_edited_scene_is_rendered_again_and_its_old_render_removed(self):
        with tempfile.TemporaryDirectory() as tmp:
            source = make_project(tmp, {"index.rst": """
                Index
                =====

                .. tumble:: scenes/dropped_cube.toml
                   :format: gif
                   :width: 96
                   :height: 54
                """})
            out = pathlib.Path(tmp) / "html"
            first = sphinx_build(source, out)
            self.assertEqual(first.returncode, 0, output_of(first))
            (old,) = [folder for *_, folder in RENDERED.findall(first.stdout)]
            scene = source / "scenes" / "dropped_cube.toml"
            scene.write_text(scene.read_text().replace("duration = 4.0", "duration = 2.0"))
            second = sphinx_build(source, out)  # no -E: the page is read again for its scene
            self.assertEqual(second.returncode, 0, output_of(second))
            (new,) = [folder for *_, folder in RENDERED.findall(second.stdout)]
            self.assertNotEqual(new, old)
            report = json.loads((out / new / "dropped_cube" / "report.json").read_text())
            self.assertEqual(report["frames"]["count"], 120)  # 2 s at 60 fps
            self.assertIn(f'src="{new}/dropped_cube/dropped_cube.gif"',
                          (out / "index.html").read_text())
            self.assertFalse((out / old).exists())  # no page uses it any more
            self.assertEqual(sorted(p.name for p in (out / "_tumble").iterdir()),
                             [pathlib.Path(new).name])


    def test_a_new_output_folder_with_the_doctrees_kept_gets_its_renders_when_written(self):
        with tempfile.TemporaryDirectory() as tmp:
            source = make_project(tmp, {"index.rst": """
                Index
                =====

                .. tumble:: scenes/dropped_cube.toml
                   :format: gif
                   :width: 96
                """})
            doctrees, out = pathlib.Path(tmp) / "doctrees", pathlib.Path(tmp) / "html"
            first = sphinx_build(source, out, "-d", str(doctrees))
            self.assertEqual(first.returncode, 0, output_of(first))
            shutil.rmtree(out)
            second = sphinx_build(source, out, "-d", str(doctrees))
            self.assertEqual(second.returncode, 0, output_of(second))
            self.assertNotIn("reading sources", second.stdout)  # the page was not read again
            (folder,) = [folder for *_, folder in RENDERED.findall(second.stdout)]
            self.assertIn(f'src="{folder}/dropped_cube/dropped_cube.gif"',
                          (out / "index.html").read_text())
            self.assertTrue((out / folder / "dropped_cube" / "dropped_cube.gif").is_file())


class Parallel(unittest.TestCase):
    def test_a_parallel_build_renders_each_render_once_and_keeps_every_pages_files(self):
        # Eight pages, read by two processes (Sphinx reads in parallel past five pages): four
        # pairs of pages ask for the same render, so two processes may ask for one at once.
        pages = {"index.rst": "Index\n=====\n\n.. toctree::\n\n" +
                 "".join(f"   p{i}\n" for i in range(8))}
        for i in range(8):
            pages[f"p{i}.rst"] = (f"P{i}\n==\n\n.. tumble:: scenes/dropped_cube.toml\n"
                                  f"   :format: gif\n   :width: {64 + 16 * (i // 2)}\n")
        with tempfile.TemporaryDirectory() as tmp:
            source = make_project(tmp, pages)
            out = pathlib.Path(tmp) / "html"
            done = sphinx_build(source, out, "-j", "2")
            self.assertEqual(done.returncode, 0, output_of(done))
            # "reading sources... [ 33%] index .. p2": a chunk of pages read in another process
            self.assertRegex(done.stdout, r"reading sources\.\.\. \[ *\d+%\] \S+ \.\. \S+")
            widths = sorted(int(w) for _, _, w, _, _ in RENDERED.findall(done.stdout))
            self.assertEqual(widths, [64, 80, 96, 112])
            for i in range(8):
                page = (out / f"p{i}.html").read_text()
                (src,) = re.findall(r'<img class="tumble" src="([^"]+)"', page)
                self.assertTrue((out / src).is_file(), src)  # not removed as unused
            self.assertEqual(len(list((out / "_tumble").iterdir())), 4)


class Errors(unittest.TestCase):
    def build_one(self, directive, scene_text=None):
        """Builds a page holding ``directive`` (its scene scenes/x.toml, ``scene_text`` or the
        dropped cube) and returns (the finished build, the scene's path, the page's path)."""
        tmp = self._tmp()
        source = make_project(tmp, {"index.rst": "Index\n=====\n\n" + directive})
        scene = source / "scenes" / "x.toml"
        scene.write_text(scene_text or (SCENES / "dropped_cube.toml").read_text())
        return sphinx_build(source, pathlib.Path(tmp) / "html"), scene, source / "index.rst"

    def _tmp(self):
        tmp = tempfile.TemporaryDirectory()
        self.addCleanup(tmp.cleanup)
        return tmp.name

    def test_a_bad_scene_stops_the_build_with_its_file_line_column_and_key(self):
        bad = 'duration = 1.0\n[[bodies]]\nname = "a"\nshape = "ball"\n'
        done, scene, page = self.build_one(".. tumble:: scenes/x.toml\n   :poster:\n", bad)
        self.assertNotEqual(done.returncode, 0, output_of(done))
        with self.assertRaises(tumble.SceneError) as raised:
            tumble.load(scene)
        self.assertEqual((raised.exception.line, raised.exception.column, raised.exception.key),
                         (4, 9, "bodies[0].shape"))
        self.assertIn(f"{page}:4: tumble: {raised.exception.message}", done.stderr)
        self.assertIn(f"{scene}:4:9: bodies[0].shape: ", done.stderr)

    def test_it_stops_a_parallel_build_too(self):
        bad = 'duration = 1.0\n[[bodies]]\nname = "a"\nshape = "ball"\n'
        tmp = self._tmp()
        pages = {f"p{i}.rst": f"P{i}\n==\n\nText.\n" for i in range(6)}
        pages["index.rst"] = ("Index\n=====\n\n.. toctree::\n\n" +
                              "".join(f"   p{i}\n" for i in range(6)) +
                              "\n.. tumble:: scenes/x.toml\n")
        source = make_project(tmp, pages)
        (source / "scenes" / "x.toml").write_text(bad)
        done = sphinx_build(source, pathlib.Path(tmp) / "html", "-j", "2")
        self.assertNotEqual(done.returncode, 0, output_of(done))
        self.assertIn(f"{source / 'scenes' / 'x.toml'}:4:9: bodies[0].shape: ", done.stderr)

    def test_a_size_the_render_refuses_stops_the_build(self):
        done, _, page = self.build_one(".. tumble:: scenes/x.toml\n   :width: 321\n"
                                       "   :height: 180\n")
        self.assertNotEqual(done.returncode, 0, output_of(done))
        self.assertIn(f"{page}:4: tumble: ", done.stderr)
        self.assertIn("width", done.stderr)
        self.assertRegex(done.stderr, r"\b321\b")

    def test_an_unknown_format_is_named_with_the_formats_there_are(self):
        done, _, page = self.build_one(".. tumble:: scenes/x.toml\n   :format: avi\n")
        self.assertNotEqual(done.returncode, 0, output_of(done))
        self.assertIn(f"{page}:4: tumble: :format: 'avi' is not a format of the tumble directive "
                      "(expected one of mp4, webm, gif, html)", done.stderr)

    def test_bad_options_stop_the_build(self):
        for options, message in (("   :width: wide\n", ":width: expected a whole number of "
                                  "pixels >= 1, got 'wide'"),
                                 ("   :height: 0\n", ":height: expected a whole number of "
                                  "pixels >= 1, got '0'"),
                                 ("   :format: gif\n   :poster:\n",
                                  ":poster: is for a video (mp4 or webm), not gif"),
                                 ("   :poster: yes\n",
                                  ":poster: is a flag and takes no value, got 'yes'")):
            with self.subTest(options=options):
                done, _, _ = self.build_one(".. tumble:: scenes/x.toml\n" + options)
                self.assertNotEqual(done.returncode, 0, output_of(done))
                self.assertIn(message, done.stderr)
                self.assertNotIn("tumble: rendered", done.stdout)

    def test_a_stability_warning_is_a_sphinx_warning(self):
        coarse = re.sub(r"(?m)^dt\s*=.*$", "dt = 0.5", (SCENES / "cube_on_spring.toml").read_text())
        (expected,) = tumble.loads(coarse, "x.toml").check()
        tmp = self._tmp()
        source = make_project(tmp, {"index.rst": "Index\n=====\n\n.. tumble:: scenes/x.toml\n"})
        (source / "scenes" / "x.toml").write_text(coarse)
        done = sphinx_build(source, pathlib.Path(tmp) / "html", "-W")
        self.assertNotEqual(done.returncode, 0, output_of(done))
        # "FILE:4: WARNING: tumble: ...", which -W prints as "FILE:4:tumble: ..."
        self.assertRegex(done.stderr, re.escape(f"{source / 'index.rst'}:4:") +
                         r"( WARNING: )?" + re.escape(f"tumble: {expected}"))
        self.assertNotIn("tumble: rendered", done.stdout)  # -W stops at the warning

    def test_a_missing_scene_names_the_file(self):
        done, _, page = self.build_one(".. tumble:: scenes/absent.toml\n")
        self.assertNotEqual(done.returncode, 0, output_of(done))
        self.assertIn(f"{page}:4: tumble: {page.parent / 'scenes' / 'absent.toml'}: ",
                      done.stderr)


class HtmlFormat(unittest.TestCase):
    """:format: html renders tumble's interactive replay page (<scene>.html) and embeds it in an
    iframe. Skipped only while this build's tumble refuses the html format."""

    def setUp(self):
        scene = tumble.load(SCENES / "dropped_cube.toml")
        with tempfile.TemporaryDirectory() as tmp:
            try:
                scene.render(output=tmp, formats=["html"], width=320, height=180, frames=False)
            except tumble.SceneError as refused:
                if "html" in str(refused):
                    self.skipTest(f"this tumble has no html format yet: {refused}")
                raise

    def test_the_replay_page_is_embedded_in_an_iframe_of_the_size_asked(self):
        with tempfile.TemporaryDirectory() as tmp:
            source = make_project(tmp, {"index.rst": """
                Index
                =====

                .. tumble:: scenes/dropped_cube.toml
                   :format: html
                   :width: 320
                   :height: 180
                   :caption: Turn it with the mouse.
                """})
            out = pathlib.Path(tmp) / "html"
            done = sphinx_build(source, out)
            self.assertEqual(done.returncode, 0, output_of(done))
            self.assertEqual([fmt for _, fmt, *_ in RENDERED.findall(done.stdout)], ["html"])
            index = (out / "index.html").read_text()
            frame = re.search(r'<iframe class="tumble" src="(_tumble/dropped_cube-[0-9a-f]{16}/'
                              r'dropped_cube/dropped_cube\.html)" width="320" height="180"',
                              index)
            self.assertIsNotNone(frame, index)
            replay = (out / frame[1]).read_text()
            self.assertIn("<html", replay.lower())
            self.assertIn("Turn it with the mouse.", index)


class DocsSite(unittest.TestCase):
    """The repository's docs/ builds with its directives (warnings are errors), into
    TUMBLE_DOCS_OUTPUT, the command of the CMake target `docs`."""

    def test_docs_build_with_their_videos_and_a_second_build_renders_nothing(self):
        out = pathlib.Path(os.environ.get("TUMBLE_DOCS_OUTPUT", SOURCE / "build" / "docs"))
        options = ("-W", "--keep-going", "-d", str(out / "doctrees"))
        first = sphinx_build(SOURCE / "docs", out / "html", *options)
        self.assertEqual(first.returncode, 0, output_of(first))
        page = (out / "html" / "videos.html").read_text()
        videos = re.findall(r'<video class="tumble" controls width="480" height="270"[^>]*>'
                            r'<source src="(_tumble/[^"]+\.mp4)"', page)
        self.assertEqual([pathlib.Path(v).name for v in videos],
                         ["die_on_table.mp4", "spinning_cube.mp4"])
        for video in videos:
            self.assertGreater((out / "html" / video).stat().st_size, 10_000)
        self.assertEqual(len(re.findall(r'<video [^>]*poster="_tumble/die_on_table-', page)), 1)
        self.assertIn("tumble.load", (out / "html" / "python.html").read_text())
        before = stamps(out / "html" / "_tumble")
        again = sphinx_build(SOURCE / "docs", out / "html", *options)
        self.assertEqual(again.returncode, 0, output_of(again))
        self.assertEqual(RENDERED.findall(again.stdout), [])
        self.assertEqual(stamps(out / "html" / "_tumble"), before)


if __name__ == "__main__":
    unittest.main()
