#!/usr/bin/env python3
# Writes tests/data/thousand_boxes.toml (run from the repository root): 10 x 10 x 10 separated
# boxes, spinning slowly. Seeded, so the file is the same every time.
import random
random.seed(12)
out = []
out.append("""# 1000 boxes of mixed sizes (edges 0.2 to 0.6 m) on a 10 x 10 x 10 grid 1 m apart, each
# spinning slowly about its own axis, none touching: the render benchmark of issue 12 item 5
# (`tumble render tests/data/thousand_boxes.toml --no-video`, render stage in report.json) and
# the input of the instanced-drawing tests. Written by scripts/thousand_boxes.py (seed 12).

name = "thousand_boxes"
duration = 2.0

[physics]
dt = 0.0166666666666666667  # 1/60 s
integrator = "rk4"
""")
for i in range(10):
    for j in range(10):
        for k in range(10):
            size = [round(random.uniform(0.2, 0.6), 2) for _ in range(3)]
            w = [round(random.uniform(-0.8, 0.8), 2) for _ in range(3)]
            out.append(f"""[[bodies]]
name = "box_{i}{j}{k}"
shape = "box"
size = [{size[0]}, {size[1]}, {size[2]}]
mass = 1.0
position = [{i - 4.5:.1f}, {j - 4.5:.1f}, {k - 4.5:.1f}]
angular_velocity = [{w[0]}, {w[1]}, {w[2]}]
""")
open("tests/data/thousand_boxes.toml", "w").write("\n".join(out))
