#!/usr/bin/env python3
"""Writes scenes/galton_board.toml (run from the repository root): 200 balls fed through a funnel
onto 12 rows of static pegs, into 13 bins; tests/scene/galton_board_test.cpp runs that file. The
options make other boards of the same shape, for trying a change; the layout has no randomness:
the file is the same on every run. Edit this script, not the file.

How the board was found (each tried with 100 or 200 balls; the counts are chaotic in every
setting, so a change anywhere moves balls between bins):
- rows 0.17 m apart left straight diagonal channels 0.113 m wide between the pegs, wider than a
  ball: balls ran down them without meeting a peg and piled into the outer bins. At 0.15 m with
  pegs of 0.04 m the channels are 0.097 m, and the gaps a ball must pass 0.106 m;
- restitution 0 lets a ball slide round a peg keeping its sideways speed (the same outer bins);
  0.5 jams the funnel; 0.6 spreads the balls as the binomial does; 0.7 and 0.8 spread them less
  evenly;
- a funnel throat of 0.24 m holds an arch of 18 balls for good; 0.32 m lets balls pass beside
  the top peg, and the outer bins get too many (1 in bin 0, against 0.05 expected)."""
import argparse
import math

ROWS = 12
PEG_SPACING = 0.22       # m, across a row
ROW_SPACING = 0.15       # m, between rows
PEG_RADIUS = 0.04        # m
BALL_RADIUS = 0.05       # m
GAP = 0.005              # m, between a ball and each pane of glass
BIN_DEPTH = 2.6          # m: room for the 45 of 200 expected in the middle bin
FUNNEL_OPENING = 0.28    # m, the funnel's throat, 2.8 ball diameters: at 2.4 an arch of balls jams it


def block(lines):
    return "\n".join(lines) + "\n"


def static_box(name, size, position, angle_z=0.0, color="#6b6f78"):
    q = [math.cos(angle_z / 2), 0.0, 0.0, math.sin(angle_z / 2)]
    return block(["", "[[bodies]]", f'name = "{name}"', 'shape = "box"',
                  f"size = [{size[0]!r}, {size[1]!r}, {size[2]!r}]", "static = true",
                  f"position = [{position[0]!r}, {position[1]!r}, 0.0]",
                  f"orientation = [{q[0]!r}, 0.0, 0.0, {q[3]!r}]", "friction = 0.0",
                  f'color = "{color}"'])


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--balls", type=int, default=200)
    parser.add_argument("--out", default="scenes/galton_board.toml")
    parser.add_argument("--throat", type=float, default=0.16)
    parser.add_argument("--drag", type=float, default=0.0)
    parser.add_argument("--restitution", type=float, default=0.6)
    parser.add_argument("--friction", type=float, default=0.0)
    parser.add_argument("--duration", type=float, default=32.0)
    parser.add_argument("--bin-depth", type=float, default=BIN_DEPTH)
    args = parser.parse_args()
    depth = 2.0 * (BALL_RADIUS + GAP)  # between the panes (z)
    bottom = -(ROWS - 1) * ROW_SPACING - 0.12  # the bins' tops
    floor = bottom - args.bin_depth
    out = [f"""# A Galton board: {args.balls} balls fed through a funnel fall through {ROWS} rows
# of static pegs into {ROWS + 1} bins, between two panes of glass. At each peg a ball goes left or
# right about evenly, so the bin it ends in counts its rights out of {ROWS}: the counts follow the
# binomial distribution, C({ROWS}, k) / 2^{ROWS} of the balls in bin k.
#
# What to look for: the stream splits at the top peg and spreads row by row; the bins fill into a
# bell, tallest in the middle ({args.balls} × 924/4096 ≈ {args.balls * 924 / 4096:.0f} balls expected in the middle bin,
# {args.balls} / 4096 ≈ {args.balls / 4096:.2f} in each outer one). Pegs are static cylinders, the bins' walls and the
# funnel static boxes: shapes that never move, met as the planes are. By 30 s every ball lies in a
# bin. Written by scripts/galton_board.py (which says how the board was found);
# tests/scene/galton_board_test.cpp runs this file and holds each bin's count to the binomial's
# 3-sigma band.

name = "galton_board"
duration = {args.duration}

[physics]
gravity = [0.0, -9.81, 0.0]  # on every moving body
dt = 0.0166666666666666667  # 1/60 s
integrator = "rk4"

[[planes]]
name = "floor"
point = [0.0, {floor!r}, 0.0]
normal = [0.0, 1.0, 0.0]
size = [3.2, 0.4]

[[planes]]
name = "back"
point = [0.0, {{PANE_CENTRE!r}}, {-depth / 2!r}]
normal = [0.0, 0.0, 1.0]
friction = 0.0
size = [3.2, {{PANE_HEIGHT!r}}]

[[planes]]
name = "glass"
point = [0.0, {{PANE_CENTRE!r}}, {depth / 2!r}]
normal = [0.0, 0.0, -1.0]
friction = 0.0
size = [3.2, {{PANE_HEIGHT!r}}]
"""]
    # Pegs: staggered rows across the whole board, one under the funnel at the top; a row has a
    # peg under each gap of the row above, as far out as the outer bins reach.
    half_width = (ROWS + 1) / 2.0 * PEG_SPACING
    for k in range(ROWS):
        offset = 0.0 if k % 2 == 0 else PEG_SPACING / 2
        j = 0
        x = -math.floor((half_width - offset) / PEG_SPACING) * PEG_SPACING + offset
        while x <= half_width - PEG_SPACING / 2 + 1e-9:
            y = -k * ROW_SPACING
            out.append(block(["", "[[bodies]]", f'name = "peg_{k}_{j}"', 'shape = "cylinder"',
                              f"radius = {PEG_RADIUS}", f"length = {depth!r}", "static = true",
                              f"position = [{x!r}, {y!r}, 0.0]",
                              # the axis (body y) along z
                              "orientation = [0.7071067811865476, 0.7071067811865476, 0.0, 0.0]",
                              f"friction = {args.friction}", 'color = "#c9ccd2"']))
            x += PEG_SPACING
            j += 1
    # The sides: two walls from the top row down to the bins.
    for side in (-1, 1):
        out.append(static_box("side_left" if side < 0 else "side_right",
                              (0.02, (ROWS - 1) * ROW_SPACING + 0.6, depth),
                              (side * half_width, -(ROWS - 1) * ROW_SPACING / 2 + 0.1)))
    # Bins: walls between and either side of the 13 bins, each centred under a gap of the last row.
    for j in range(ROWS + 2):
        x = (j - (ROWS + 1) / 2.0) * PEG_SPACING
        out.append(static_box(f"wall_{j}", (0.02, args.bin_depth, depth),
                              (x, bottom - args.bin_depth / 2)))
    # The funnel: two slabs at 50° meeting just above the top peg, their lower ends FUNNEL_OPENING
    # apart, so that balls leave it slowly and fall a few centimetres onto the top peg.
    angle = math.radians(50.0)
    length = 2.0
    throat_y = args.throat
    for side in (-1, 1):
        edge_x = side * (FUNNEL_OPENING / 2 + 0.01)
        cx = edge_x + side * (length / 2) * math.cos(angle)
        cy = throat_y + (length / 2) * math.sin(angle)
        out.append(static_box("funnel_left" if side < 0 else "funnel_right", (length, 0.02, depth),
                              (cx, cy), side * angle))
    # Balls: in rows inside the funnel, 0.11 apart, each row as wide as the funnel lets it be.
    placed = 0
    row = 0
    top = throat_y
    while placed < args.balls:
        y = throat_y + 0.1 + row * 0.11
        half = FUNNEL_OPENING / 2 + (y - throat_y) / math.tan(angle) - 0.09
        count = max(1, int(2 * half / 0.11) + 1)
        for col in range(count):
            if placed == args.balls:
                break
            x = (col - (count - 1) / 2.0) * 0.11 + (0.01 if row % 2 else -0.01)
            out.append(block(["", "[[bodies]]", f'name = "ball_{placed}"', 'shape = "sphere"',
                              f"radius = {BALL_RADIUS}", "mass = 0.05",
                              f"position = [{x!r}, {y!r}, 0.0]", f"restitution = {args.restitution}",
                              f"friction = {args.friction}", 'color = "#e3662e"']))
            if args.drag > 0.0:
                out.append(block(["", "[[bodies.forces]]", 'kind = "linear_damping"',
                                  f"coefficient = {args.drag}"]))
            placed += 1
        top = y
        row += 1
    top += 0.3
    # Everything in the picture's height (the vertical field of view is 40°), with a margin.
    middle = (top + floor) / 2
    distance = 0.5 * (top - floor) / math.tan(math.radians(20.0)) + 1.0
    out.append(f"""
[camera]
position = [0.0, {middle!r}, {distance!r}]
look_at = [0.0, {middle!r}, 0.0]
""")
    text = "".join(out)
    text = text.replace("{PANE_CENTRE!r}", repr(middle)).replace("{PANE_HEIGHT!r}",
                                                                  repr(top - floor + 0.4))
    with open(args.out, "w") as f:
        f.write(text)


if __name__ == "__main__":
    main()
