#!/usr/bin/env python3
"""Writes the contact-between-bodies scenes that list many bodies: scenes/tower.toml,
scenes/dominoes.toml and scenes/pile.toml (run from the repository root). The numbers come from
a fixed seed, so the files are the same on every run; edit this script, not the files."""
import math
import random

HEADER_PHYSICS = """[physics]
gravity = [0.0, -9.81, 0.0]  # on every moving body
dt = 0.0166666666666666667  # 1/60 s
integrator = "rk4"
contact = "impulse"
"""


def floor(restitution, friction, size):
    return f"""
[[planes]]
name = "floor"
point = [0.0, 0.0, 0.0]
normal = [0.0, 1.0, 0.0]
restitution = {restitution}
friction = {friction}
size = [{size}, {size}]
"""


def body(name, size, mass, position, velocity=None, orientation=None, angular=None,
         restitution=0.0, friction=0.5, color=None):
    lines = ["", "[[bodies]]", f'name = "{name}"']
    if isinstance(size, (int, float)):
        lines += ['shape = "cube"', f"size = {size}"]
    else:
        lines += ['shape = "box"', "size = [%.4f, %.4f, %.4f]" % size]
    lines += [f"mass = {mass:.4f}", "position = [%.4f, %.4f, %.4f]" % position]
    if velocity:
        lines.append("velocity = [%.4f, %.4f, %.4f]" % velocity)
    if orientation:
        lines.append("orientation = [%.6f, %.6f, %.6f, %.6f]" % orientation)
    if angular:
        lines.append("angular_velocity = [%.4f, %.4f, %.4f]" % angular)
    lines += [f"restitution = {restitution}", f"friction = {friction}"]
    if color:
        lines.append('color = "%s"' % color)
    return "\n".join(lines) + "\n"


def tower():
    text = """# A tower of ten unit cubes on a floor, and a small heavy cube lobbed at its foot, landing at 2 s.
#
# What to look for: for two seconds nothing moves (the stack stands still: no creep, no sinking;
# tests/physics/world_step_test.cpp holds a tower for a minute to 3 mm). Then a 40 kg, 0.4 m
# cube at 12 m/s knocks the bottom box out; the column drops a box's height onto the floor,
# leans, and falls over like a tree, the boxes sliding apart as they land.

name = "tower"
duration = 6.0

""" + HEADER_PHYSICS + floor(0.1, 0.5, 60.0)
    for k in range(10):
        text += body(f"box{k}", 1.0, 1.0, (0.0, 0.5 + k, 0.0),
                     color="#%02x%02x%02x" % (200 - 12 * k, 90 + 10 * k, 60))
    # The striker: lobbed from the floor 24 m away so that it arrives at the bottom box's face,
    # at floor level, at t = 2 s (x = x0 + 12 t, y = 0.2 + 9.81 t - g t²/2).
    text += body("striker", 0.4, 40.0, (-24.7, 0.2, 0.0), velocity=(12.0, 9.81, 0.0),
                 color="#3060c0")
    text += """
[camera]
position = [9.0, 6.0, 14.0]
look_at = [0.0, 4.0, 0.0]
"""
    return text


def dominoes():
    text = """# Twenty-four dominoes in a curve on a floor; the first is tipped over.
#
# What to look for: each domino falls onto the next, in order along the curve, the wave running
# at about the same speed from one end to the other; the last one ends lying down.

name = "dominoes"
duration = 7.0

""" + HEADER_PHYSICS + floor(0.0, 0.6, 16.0)
    count = 24
    for k in range(count):
        angle = 0.9 * k / (count - 1)  # the row turns through 0.9 rad
        radius = 8.0
        x = radius * math.sin(angle) - 4.0
        z = radius * (1.0 - math.cos(angle)) - 2.0
        heading = angle
        q = (math.cos(-heading / 2), 0.0, math.sin(-heading / 2), 0.0)  # turn about y
        spin = (0.0, 0.0, -1.6) if k == 0 else None
        if spin:  # the push: the first one starts turning about the row's sideways axis
            spin = (1.6 * math.sin(heading), 0.0, -1.6 * math.cos(heading))
        text += body(f"domino{k}", (0.1, 1.0, 0.5), 2.0, (x, 0.5, z), orientation=q,
                     angular=spin, friction=0.6,
                     color="#%02x%02x%02x" % (230 - 6 * k, 220 - 4 * k, 200))
    text += """
[camera]
position = [-3.0, 6.0, 10.0]
look_at = [0.0, 0.5, 1.0]
"""
    return text


def pile():
    rng = random.Random(12)
    text = """# Six hundred boxes of mixed sizes poured into a walled bin, a few layers at a time.
#
# What to look for: the boxes fall in a column, land, tumble and slide outwards, and heap up
# against the walls; none leaves the bin or sinks into the floor, and by the end (t = 20 s) the
# heap is at rest. tumble's contact_bench runs the same kind of pile beside Bullet.

name = "pile"
duration = 20.0

""" + HEADER_PHYSICS + floor(0.1, 0.5, 8.0)
    half = 3.0
    for name, normal, point in (("wall_east", (-1, 0, 0), (half, 0, 0)),
                                ("wall_west", (1, 0, 0), (-half, 0, 0)),
                                ("wall_north", (0, 0, 1), (0, 0, -half)),
                                ("wall_south", (0, 0, -1), (0, 0, half))):
        text += f"""
[[planes]]
name = "{name}"
point = [{point[0]:.1f}, {point[1]:.1f}, {point[2]:.1f}]
normal = [{normal[0]:.1f}, {normal[1]:.1f}, {normal[2]:.1f}]
restitution = 0.1
friction = 0.5
size = [6.0, 3.0]
"""
    count, pitch, grid = 600, 1.1, 5
    for k in range(count):
        layer, cell = divmod(k, grid * grid)
        row, column = divmod(cell, grid)
        size = tuple(rng.uniform(0.2, 0.6) for _ in range(3))
        mass = 500.0 * size[0] * size[1] * size[2]
        position = ((column - 2) * pitch, 1.0 + layer * pitch, (row - 2) * pitch)
        u1, u2, u3 = rng.random(), rng.random(), rng.random()  # Shoemake's uniform rotation
        q = (math.sqrt(u1) * math.cos(2 * math.pi * u3), math.sqrt(1 - u1) * math.sin(2 * math.pi * u2),
             math.sqrt(1 - u1) * math.cos(2 * math.pi * u2), math.sqrt(u1) * math.sin(2 * math.pi * u3))
        shade = rng.randint(0, 2)
        color = ("#d0603a", "#e0b040", "#4a80c0")[shade]
        text += body(f"b{k}", size, mass, position, orientation=q, restitution=0.1, color=color)
    text += """
[camera]
position = [9.0, 9.0, 12.0]
look_at = [0.0, 1.5, 0.0]
"""
    return text


for name, make in (("tower", tower), ("dominoes", dominoes), ("pile", pile)):
    with open(f"scenes/{name}.toml", "w") as out:
        out.write(make())
