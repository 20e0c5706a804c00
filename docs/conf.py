# The Sphinx site of docs/ (Debian's python3-sphinx 5.3): index.rst, videos.rst (scenes rendered
# at build time by the tumble directive) and python.rst. The reference pages stay Markdown
# (*.md, which Sphinx without a Markdown parser does not read) and are linked as downloads.
#
# Built into the build folder, never into docs/:  cmake --build build --target docs
# (or by hand: PYTHONPATH=build/python python3 -m sphinx -b html docs build/docs/html)
import pathlib
import sys

try:
    import tumble
except ImportError:  # a build folder beside the sources, as the README's quick start makes
    sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "build" / "python"))
    import tumble

project = "tumble"
author = "the tumble authors"
release = version = tumble.__version__
extensions = ["sphinx.ext.autodoc", "tumble.sphinx"]
exclude_patterns = ["_build"]
html_theme = "alabaster"
html_theme_options = {"description": "physics videos from scene files, off-screen",
                      "page_width": "1000px"}
autodoc_member_order = "bysource"
