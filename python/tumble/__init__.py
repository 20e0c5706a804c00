"""tumble from Python: load a scene, run its physics into NumPy arrays, render it, show it.

    import tumble
    scene = tumble.load("scenes/dropped_cube.toml")
    run = scene.simulate()                 # a Trajectory: run.t, run["cube"].position, ...
    render = scene.render(width=640, height=360)
    render                                 # in Jupyter: the video, playable in a saved notebook

The numbers are those of ``tumble simulate``'s CSV bit for bit, and a render writes the bytes
``tumble render`` writes with the same settings: both go through the same C++ functions. Long
work runs with the GIL released, and Ctrl-C stops it as it stops the command line.
"""

import base64
import json
import mimetypes
import os
import pathlib

from . import _tumble
from ._errors import RenderError, SceneError, SimulationError

__version__ = _tumble.__version__
__all__ = ["load", "loads", "Scene", "Trajectory", "Track", "Render", "Video", "SceneError",
           "SimulationError", "RenderError"]

_HERE = pathlib.Path(__file__).resolve().parent


def _shader_directory():
    """The shaders installed beside the module, or "" to let tumble find its source tree's."""
    installed = _HERE / "shaders"
    return str(installed) if (installed / "body.vert").exists() else ""


def _web_directory():
    """The html replay's files installed beside the module, or "" to let tumble find them."""
    installed = _HERE / "web"
    return str(installed) if (installed / "replay.html").exists() else ""


def load(path):
    """The scene in the TOML file at ``path``; raises SceneError as ``tumble check`` reports."""
    return Scene(_tumble.load(os.fspath(path)))


def loads(text, path="<string>"):
    """The scene written in ``text``; ``path`` names it in errors (and relative mesh files are
    read beside it)."""
    return Scene(_tumble.loads(text, os.fspath(path)))


class Scene:
    """A scene as tumble read it. ``name``, ``path``, ``duration`` (s), ``fps``, ``dt`` (s),
    ``steps``, ``width``, ``height`` and ``bodies`` (their names) describe it."""

    def __init__(self, loaded):
        self._scene = loaded

    def __getattr__(self, name):
        if name in ("name", "path", "text", "duration", "fps", "dt", "steps", "width", "height",
                    "bodies"):
            return getattr(self._scene, name)
        raise AttributeError(name)

    def __repr__(self):
        return (f"<tumble.Scene {self.name!r} from {self.path!r}: {len(self.bodies)} bodies, "
                f"{self.duration:g} s>")

    def check(self):
        """The warnings of ``tumble check`` (physics that will be wrong), as a list of strings."""
        return list(self._scene.check())

    def simulate(self, every=1):
        """Runs the physics to the end and returns a Trajectory of the state at step 0, every
        ``every``-th step and the last: the rows of ``tumble simulate --every EVERY``."""
        return Trajectory(self._scene.simulate(every))

    def render(self, output=None, formats=None, width=None, height=None, fps=None, quality=None,
               frames=None):
        """Renders as ``tumble render`` does into ``output`` (default ``output``, beside the
        current folder), in OUTPUT/<the scene's output directory>/, and returns a Render.

        ``formats`` replaces ``[output] formats`` (a list such as ``["mp4", "gif"]``; None keeps
        the scene's, mp4 unless it says otherwise); ``width``, ``height``, ``fps`` and
        ``quality`` (low, medium, high, production, 4k) are ``--width``, ``--height``, ``--fps``
        and ``--quality``; ``frames=False`` is ``--no-frames``."""
        if isinstance(formats, str):
            formats = [formats]
        done = self._scene.render(os.fspath(output) if output is not None else "output",
                                  list(formats) if formats is not None else None, width, height,
                                  fps, quality, frames, _shader_directory(),
                                  _web_directory())
        return Render(done["directory"], done["written"], done["kept"], done["warnings"])


class Track:
    """One body's states over a Trajectory: ``position``, ``velocity``, ``angular_velocity``,
    ``momentum`` and ``angular_momentum`` (n, 3), ``orientation`` (n, 4; w, x, y, z) and
    ``energy`` (n,; kinetic, J)."""

    def __init__(self, name, arrays):
        self.name = name
        for key, value in arrays.items():
            setattr(self, key, value)

    def __repr__(self):
        return f"<tumble.Track {self.name!r}: {len(self.energy)} samples>"


class Trajectory:
    """A simulation's samples: ``t`` (n,) and one Track per body, by name (``run["cube"]``) or in
    order (``run.tracks``); ``names`` lists the bodies."""

    def __init__(self, run):
        self.t = run["t"]
        self.names = list(run["bodies"])
        self.tracks = [Track(name, arrays) for name, arrays in zip(self.names, run["states"])]
        self._by_name = {track.name: track for track in self.tracks}

    def __getitem__(self, name):
        try:
            return self._by_name[name]
        except KeyError:
            raise KeyError(f"no body {name!r} (bodies: {', '.join(self.names)})") from None

    def __iter__(self):
        return iter(self.tracks)

    def __len__(self):
        return len(self.t)

    def __repr__(self):
        return f"<tumble.Trajectory: {len(self.t)} samples of {len(self.names)} bodies>"


def _data_uri(path):
    kind = mimetypes.guess_type(str(path))[0] or "application/octet-stream"
    return f"data:{kind};base64," + base64.b64encode(pathlib.Path(path).read_bytes()).decode()


def _video_html(path, poster=None, width=None):
    """HTML that shows the file at ``path`` with its bytes inside: a <video> for MP4 and WebM,
    an <img> for a GIF or a PNG, so that a saved or converted notebook still plays it."""
    path = pathlib.Path(path)
    size = f' width="{int(width)}"' if width else ""
    if path.suffix.lower() in (".gif", ".png"):
        return f'<img src="{_data_uri(path)}"{size} alt="{path.name}">'
    kind = "video/webm" if path.suffix.lower() == ".webm" else "video/mp4"
    data = base64.b64encode(path.read_bytes()).decode()
    shown = f' poster="{_data_uri(poster)}"' if poster else ""
    return (f'<video controls loop{size}{shown}><source src="data:{kind};base64,{data}" '
            f'type="{kind}"></video>')


class Video:
    """A video or image file to show in Jupyter: ``tumble.Video("output/x/x.mp4")`` as a cell's
    last line plays it. The file's bytes go into the notebook, so a saved notebook plays it."""

    def __init__(self, path, poster=None, width=None):
        self.path = pathlib.Path(path)
        if not self.path.is_file():
            raise FileNotFoundError(f"{self.path}: no such file")
        self.poster = pathlib.Path(poster) if poster else None
        self.width = width

    def _repr_html_(self):
        return _video_html(self.path, self.poster, self.width)

    def __repr__(self):
        return f"<tumble.Video {str(self.path)!r}>"


class Render:
    """What a render wrote: ``directory``, ``files`` (name -> path of each file written, plus
    ``frames`` for the PNG folder), ``kept`` (names kept of an earlier render of the scene),
    ``warnings``, ``report`` (report.json as a dict), ``video`` (the first video's path, or
    None), ``gltf`` and ``html`` (the .glb's and the replay page's paths, or None). In Jupyter
    it shows its video (or GIF, or poster)."""

    def __init__(self, directory, written, kept, warnings):
        self.directory = pathlib.Path(directory)
        self.files = {name: self.directory / name for name in written}
        self.kept = list(kept)
        self.warnings = list(warnings)
        self.report = json.loads((self.directory / "report.json").read_text())
        videos = self.report.get("videos") or {}
        self.videos = {kind: self.directory / pathlib.Path(path).name for kind, path in videos.items()}
        self.video = next(iter(self.videos.values()), None)
        gltf = self.report.get("gltf")
        self.gltf = self.directory / pathlib.Path(gltf).name if gltf else None
        html = self.report.get("html")
        self.html = self.directory / pathlib.Path(html).name if html else None
        poster = self.directory / "poster.png"
        self.poster = poster if poster.exists() else None

    def _repr_html_(self):
        shown = next((p for p in self.videos.values() if p.suffix in (".mp4", ".webm")), None)
        shown = shown or next(iter(self.videos.values()), None) or self.poster
        if shown is None:
            return f"<p>tumble: rendered to {self.directory} (no video, no poster)</p>"
        return _video_html(shown, self.poster if shown != self.poster else None,
                           min(self.report.get("width", 640), 800))

    def __repr__(self):
        return f"<tumble.Render {str(self.directory)!r}: {', '.join(self.files)}>"
