"""examples/notebook.ipynb executed as CI executes it (nbclient, Debian's python3 kernel), and its
saved output checked: no error, the energy plot, and a <video> whose embedded MP4 decodes to the
render's frames (tumble diff compares it with the PNG frames it was encoded from)."""

import base64
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

import nbclient
import nbformat

SOURCE = pathlib.Path(os.environ.get("TUMBLE_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
EXECUTABLE = os.environ.get("TUMBLE_EXECUTABLE", "tumble")


class Notebook(unittest.TestCase):
    def test_the_example_notebook_runs_and_embeds_its_video(self):
        with tempfile.TemporaryDirectory() as tmp:
            tmp = pathlib.Path(tmp)
            # The notebook's own layout: examples/ beside scenes/, its output in examples/output.
            (tmp / "examples").mkdir()
            shutil.copy(SOURCE / "examples" / "notebook.ipynb", tmp / "examples")
            (tmp / "scenes").symlink_to(SOURCE / "scenes")
            # The kernel is Debian's python3 (the one running this test), whatever else is first
            # on PATH, and it imports the module from where this test does.
            os.environ["PATH"] = os.path.dirname(sys.executable) + os.pathsep + os.environ["PATH"]
            notebook = nbformat.read(tmp / "examples" / "notebook.ipynb", as_version=4)
            client = nbclient.NotebookClient(notebook, timeout=300, kernel_name="python3",
                                             resources={"metadata": {"path": tmp / "examples"}})
            client.execute()  # raises CellExecutionError on the first failing cell
            saved = tmp / "executed.ipynb"
            nbformat.write(notebook, saved)

            outputs = [o for cell in nbformat.read(saved, as_version=4).cells
                       if cell.cell_type == "code" for o in cell.outputs]
            self.assertFalse([o for o in outputs if o.output_type == "error"])
            self.assertTrue(any("image/png" in o.get("data", {}) for o in outputs),
                            "no plot in the notebook's outputs")
            html = [o["data"]["text/html"] for o in outputs if "text/html" in o.get("data", {})]
            videos = [re.search(r'<video[^>]*>\s*<source src="data:video/mp4;base64,([^"]+)"', h)
                      for h in html]
            videos = [v for v in videos if v]
            self.assertEqual(len(videos), 1, "expected one embedded <video>")
            mp4 = tmp / "embedded.mp4"
            mp4.write_bytes(base64.b64decode(videos[0][1]))

            frames = tmp / "examples" / "output" / "dropped_cube" / "frames"
            count = len(list(frames.glob("frame_*.png")))
            self.assertGreater(count, 100)
            # Decoded, the embedded video is the render's frames: as many, and each the frame it
            # was encoded from within H.264's loss: PSNR at least 35 dB.
            done = subprocess.run([EXECUTABLE, "diff", "--metric", "psnr", "--threshold", "35", frames, mp4],
                                  capture_output=True,
                                  text=True)
            self.assertEqual(done.returncode, 0, done.stdout + done.stderr)
            self.assertIn(f"{count} frames", done.stdout + done.stderr)


if __name__ == "__main__":
    unittest.main()
