#!/usr/bin/env python3
"""Writes terrain.obj in this folder (provenance: generated here, no third-party data).

A gently waving ground for the mesh-ground demo and tests (issue 40): a 12 x 12 m square grid of
24 x 24 cells in x, z, each cut along one diagonal into two triangles wound counter-clockwise
seen from above (normals up), heights y = A sin(2 pi x / L) cos(2 pi z / L). The slope stays
below A 2 pi / L = 0.21 (12 degrees), under the friction angle of the default materials, so a
box can rest anywhere. An open mesh: a static body with "collide_as": "triangles" uses it.
Run: python3 assets/meshes/make_terrain.py
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
HALF = 6.0          # half side [m]
CELLS = 24          # per side
AMPLITUDE = 0.2     # [m]
WAVELENGTH = 6.0    # [m]


def height(x, z):
    k = 2.0 * math.pi / WAVELENGTH
    return AMPLITUDE * math.sin(k * x) * math.cos(k * z)


def main():
    step = 2.0 * HALF / CELLS
    lines = ["# terrain.obj: written by make_terrain.py (a waving grid, 24 x 24 cells, 12 x 12 m)"]
    for i in range(CELLS + 1):
        for j in range(CELLS + 1):
            x, z = -HALF + j * step, -HALF + i * step
            lines.append("v %.6f %.6f %.6f" % (x, height(x, z), z))
    for i in range(CELLS):
        for j in range(CELLS):
            a = i * (CELLS + 1) + j + 1  # OBJ indices start at 1; a at (x_j, z_i)
            b, c, d = a + 1, a + CELLS + 2, a + CELLS + 1  # (x_j+1, z_i), (x_j+1, z_i+1), (x_j, z_i+1)
            lines.append("f %d %d %d" % (a, d, c))  # counter-clockwise seen from +y
            lines.append("f %d %d %d" % (a, c, b))
    with open(os.path.join(HERE, "terrain.obj"), "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
