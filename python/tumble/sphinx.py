"""A Sphinx extension: ``.. tumble:: SCENE`` renders a scene at build time and shows its video.

In conf.py, ``extensions = ["tumble.sphinx"]``; in a page::

    .. tumble:: ../scenes/dropped_cube.toml
       :format: mp4          (mp4, webm, gif or html; default mp4)
       :width: 640           (default the scene's; one of width and height alone keeps its shape)
       :height: 360
       :poster:              (show poster.png until the video plays)
       :caption: A cube lands and comes to rest.

The scene's path is relative to the page, as an image's is (``/`` starts at the source folder).
The render goes into the HTML output's ``_tumble/<scene>-<key>/`` folder, where ``<key>`` hashes
everything that makes the file: the scene's text, the mesh files it reads, the format, the size
and tumble's version. A render whose folder is complete is not done again, so a second build
renders nothing; the page depends on the scene (and its meshes), so an edited scene makes Sphinx
read the page again, and the new text is a new key. Folders no page uses any more are removed at
the end of a build that succeeded.

A scene tumble refuses stops the build (exit 2, with or without -W) with the page's place and
tumble's own message, ``FILE:LINE:COL: KEY: what``; so does a bad option.
"""

import contextlib
import fcntl
import hashlib
import json
import pathlib
import re
import shutil
import time

from docutils import nodes
from sphinx.errors import ExtensionError
from sphinx.util import logging
from sphinx.util.docutils import SphinxDirective
from sphinx.util.osutil import relative_uri

import tumble

logger = logging.getLogger(__name__)

FORMATS = ("mp4", "webm", "gif", "html")
FOLDER = "_tumble"  # under the builder's output folder
_MANIFEST = "tumble-sphinx.json"  # in a render's folder: its files, written last
_KEYED_FOLDER = re.compile(r"^[\w.-]+-[0-9a-f]{16}$")
_VIDEO_TYPES = {"mp4": "video/mp4", "webm": "video/webm"}
_FIT = "max-width: 100%; height: auto"  # the render's size, or narrower on a narrow page
_TUMBLE_ERRORS = (tumble.SceneError, tumble.SimulationError, tumble.RenderError)
# Bumped when what this file asks of a render changes, so that older renders are not reused.
_RENDER_RULES = 1


class tumble_render(nodes.General, nodes.Element):
    """A rendered scene in a page: ``key`` (its folder under _tumble/), ``format``, ``width``
    and ``height`` (px), ``poster`` (whether to show it), ``alt``, and ``request`` (what
    ensure_rendered takes: the writer finds the files through it, and renders them again if the
    output folder lost them while the pages' doctrees were kept)."""


class _Failure(Exception):
    """A directive's error, raised as ExtensionError with the page's place in front."""


def _checked_in_run(value):
    """An option's text as given: run() checks it, so that a bad value stops the build as a bad
    scene does (docutils' own checks only warn, and the build would pass)."""
    return value


def _scene_files(scene_path, text):
    """The mesh files a scene reads (``mesh`` of its bodies, relative to the scene's folder),
    the only files besides itself whose bytes change its render. tumble.load has read the scene
    and every mesh already, so the TOML parses and the files are there."""
    try:
        import tomllib  # Python 3.11, Debian 12's
        bodies = tomllib.loads(text).get("bodies", [])
        meshes = [body.get("mesh") for body in bodies if isinstance(body, dict)]
    except ImportError:
        meshes = re.findall(r"""\bmesh\s*=\s*["']([^"']+)["']""", text)
    folder = pathlib.Path(scene_path).parent
    return sorted({str(folder / mesh) for mesh in meshes if isinstance(mesh, str)})


def render_key(scene, files, fmt, width, height):
    """The name of a render: 16 hex digits of SHA-256 over everything that decides its bytes."""
    digest = hashlib.sha256()
    settings = {"rules": _RENDER_RULES, "tumble": tumble.__version__, "format": fmt,
                "width": width, "height": height, "frames": False}
    digest.update(json.dumps(settings, sort_keys=True).encode() + b"\0")
    digest.update(scene.text.encode() + b"\0")
    for path in files:
        digest.update(pathlib.Path(path).read_bytes() + b"\0")
    name = re.sub(r"[^\w.-]", "_", scene.name) or "scene"
    return f"{name}-{digest.hexdigest()[:16]}"


@contextlib.contextmanager
def _locked(folder):
    """The render folder, held against another process building the same render (parallel
    reads or writes, or a second sphinx-build on the same output)."""
    folder.mkdir(parents=True, exist_ok=True)
    with open(folder / ".lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        try:
            yield folder
        finally:
            fcntl.flock(lock, fcntl.LOCK_UN)


def _rendered(folder):
    """The manifest of a complete render in ``folder``, or None."""
    try:
        manifest = json.loads((folder / _MANIFEST).read_text())
    except (OSError, ValueError):
        return None
    files = [manifest.get("file")] + ([manifest["poster"]] if manifest.get("poster") else [])
    if all(name and (folder / name).is_file() for name in files):
        return manifest
    return None


def _output_file(render, fmt):
    if fmt in render.videos:
        return render.videos[fmt]
    pages = sorted(render.directory.glob("*.html"))  # the replay page, <scene>.html
    if fmt == "html" and len(pages) == 1:
        return pages[0]
    raise tumble.RenderError(f"the render wrote no {fmt} file in {render.directory}")


def ensure_rendered(outdir, request):
    """The manifest of the render ``request`` asks for, rendered into outdir/_tumble/<key>/ unless
    it is there already. Raises tumble's errors."""
    folder = pathlib.Path(outdir) / FOLDER / request["key"]
    done = _rendered(folder)
    if done:
        return done
    with _locked(folder):
        done = _rendered(folder)  # another process may have rendered it while this one waited
        if done:
            return done
        started = time.monotonic()
        scene = tumble.load(request["scene"])
        render = scene.render(output=folder, formats=[request["format"]], width=request["width"],
                              height=request["height"], frames=False)
        logger.info("tumble: rendered %s (%s, %dx%d) into %s/%s in %.1f s", request["scene"],
                    request["format"], request["width"], request["height"], FOLDER,
                    request["key"], time.monotonic() - started)
        try:
            file = _output_file(render, request["format"]).relative_to(folder)
            poster = render.poster.relative_to(folder) if render.poster else None
        except ValueError:
            raise tumble.RenderError(f"the render went to {render.directory}, outside {folder}")
        manifest = {"file": str(file), "poster": str(poster) if poster else None,
                    "scene": request["scene"]}
        written = folder / (_MANIFEST + ".part")
        written.write_text(json.dumps(manifest, indent=1) + "\n")
        written.replace(folder / _MANIFEST)  # last, so that a manifest means a whole render
        return manifest


class TumbleDirective(SphinxDirective):
    """``.. tumble:: SCENE``: see the module's docstring."""

    required_arguments = 1
    optional_arguments = 0
    final_argument_whitespace = True
    has_content = False
    option_spec = {name: _checked_in_run for name in ("format", "width", "height", "poster",
                                                      "caption")}

    def run(self):
        try:
            return self._run()
        except _Failure as failure:
            raise ExtensionError(f"{self.get_location()}: tumble: {failure}",
                                 modname=__name__) from None
        except _TUMBLE_ERRORS as error:
            raise ExtensionError(f"{self.get_location()}: tumble: {error}",
                                 modname=__name__) from None

    def _run(self):
        fmt = (self.options.get("format") or "mp4").strip()
        if fmt not in FORMATS:
            raise _Failure(f":format: {fmt!r} is not a format of the tumble directive "
                           f"(expected one of {', '.join(FORMATS)})")
        if (self.options.get("poster") or "").strip():
            raise _Failure(f":poster: is a flag and takes no value, got {self.options['poster']!r}")
        poster = "poster" in self.options
        if poster and fmt not in _VIDEO_TYPES:
            raise _Failure(f":poster: is for a video (mp4 or webm), not {fmt}")
        _, scene_path = self.env.relfn2path(self.arguments[0], self.env.docname)
        self.env.note_dependency(scene_path)
        scene = tumble.load(scene_path)
        for warning in scene.check():  # as `tumble render` prints them: physics that will be wrong
            logger.warning("tumble: %s", warning, location=self.get_location(), type="tumble")
        width, height = self._size(scene)
        files = _scene_files(scene_path, scene.text)
        for path in files:
            self.env.note_dependency(path)
        key = render_key(scene, files, fmt, width, height)
        request = {"key": key, "scene": scene_path, "format": fmt, "width": width,
                   "height": height}
        if self.env.app.builder.format == "html":  # other builders show nothing of it
            ensure_rendered(self.env.app.outdir, request)  # here, to fail at the page's line
        _renders(self.env).setdefault(self.env.docname, set()).add(key)
        caption = (self.options.get("caption") or "").strip()
        node = tumble_render(key=key, format=fmt, width=width, height=height, poster=poster,
                             alt=f"tumble: {scene.name}", request=request)
        self.set_source_info(node)
        if not caption:
            return [node]
        parsed, messages = self.state.inline_text(caption, self.lineno)
        shown = nodes.caption(caption, "", *parsed)
        node["alt"] = shown.astext()
        figure = nodes.figure("", node, shown, classes=["tumble-figure"])
        self.set_source_info(shown)
        self.set_source_info(figure)
        return [figure] + messages

    def _size(self, scene):
        """The render's width and height in pixels: the options', the scene's, or one option
        and the other from the scene's shape (rounded to even, as MP4 and WebM need)."""
        given = {}
        for name in ("width", "height"):
            value = self.options.get(name)
            if value is None:
                continue
            if not re.fullmatch(r"\s*\d+\s*", value) or int(value) < 1:
                raise _Failure(f":{name}: expected a whole number of pixels >= 1, got {value!r}")
            given[name] = int(value)
        if "width" in given and "height" in given:
            return given["width"], given["height"]
        if "width" in given:
            return given["width"], max(2, 2 * round(given["width"] * scene.height
                                                    / scene.width / 2))
        if "height" in given:
            return max(2, 2 * round(given["height"] * scene.width / scene.height / 2)), \
                given["height"]
        return scene.width, scene.height


def _uri(translator, node, name):
    here = translator.builder.get_target_uri(translator.builder.current_docname)
    return relative_uri(here, f"{FOLDER}/{node['key']}/{name}")


def _escape(text):
    return (str(text).replace("&", "&amp;").replace('"', "&quot;").replace("<", "&lt;")
            .replace(">", "&gt;"))


def visit_html(translator, node):
    try:  # rendered when the page was read, unless the output folder has lost it since
        manifest = ensure_rendered(translator.builder.outdir, node["request"])
    except _TUMBLE_ERRORS as error:
        raise ExtensionError(f"{node.source}:{node.line}: tumble: {error}",
                             modname=__name__) from None
    poster = manifest["poster"] if node["poster"] else None
    src = _escape(_uri(translator, node, manifest["file"]))
    size = f'width="{node["width"]}" height="{node["height"]}"'
    alt = _escape(node["alt"])
    fmt = node["format"]
    if fmt == "gif":
        html = f'<img class="tumble" src="{src}" {size} alt="{alt}" style="{_FIT}">'
    elif fmt == "html":
        html = (f'<iframe class="tumble" src="{src}" {size} title="{alt}" '
                f'style="border: 0; max-width: 100%"></iframe>')
    else:
        shown = f' poster="{_escape(_uri(translator, node, poster))}"' if poster else ""
        html = (f'<video class="tumble" controls {size}{shown} style="{_FIT}" '
                f'aria-label="{alt}"><source src="{src}" type="{_VIDEO_TYPES[fmt]}">'
                f'<a href="{src}">{alt}</a></video>')
    if not isinstance(node.parent, nodes.figure):
        html = f'<div class="tumble">{html}</div>'  # a block of its own, as a figure is
    translator.body.append(html + "\n")
    raise nodes.SkipNode



def skip(translator, node):
    raise nodes.SkipNode


def _renders(env):
    """{docname: the keys of its renders}, kept in the environment between builds."""
    if not hasattr(env, "tumble_renders"):
        env.tumble_renders = {}
    return env.tumble_renders


def _purge(app, env, docname):
    _renders(env).pop(docname, None)


def _merge(app, env, docnames, other):
    for docname in docnames:
        if docname in _renders(other):
            _renders(env)[docname] = _renders(other)[docname]


def _remove_unused(app, exception):
    """Removes the render folders no page uses any more, after a build that succeeded."""
    if exception is not None or app.builder.format != "html":
        return
    folder = pathlib.Path(app.outdir) / FOLDER
    if not folder.is_dir():
        return
    used = set().union(*_renders(app.env).values())
    for entry in folder.iterdir():
        if entry.is_dir() and _KEYED_FOLDER.match(entry.name) and entry.name not in used:
            shutil.rmtree(entry)
            logger.info("tumble: removed %s/%s (no page uses it)", FOLDER, entry.name)


def setup(app):
    app.add_node(tumble_render, html=(visit_html, None), latex=(skip, None), text=(skip, None),
                 man=(skip, None), texinfo=(skip, None))
    app.add_directive("tumble", TumbleDirective)
    app.connect("env-purge-doc", _purge)
    app.connect("env-merge-info", _merge)
    app.connect("build-finished", _remove_unused)
    # Reads are safe in parallel: each render is locked by its folder, and env-merge-info
    # gathers the keys; writes only read the manifests (or render a lost folder, locked too).
    return {"version": tumble.__version__, "parallel_read_safe": True,
            "parallel_write_safe": True, "env_version": 1}
