#!/usr/bin/env python3
"""Writes Cook's membrane as a CalculiX deck: the tapered panel with corners (0, 0), (48, 44), (48, 60), (0, 44) [mm],
N x N linear quadrilaterals (CPE4) by the bilinear map of the unit square, with the sets a project names:
  *NSET LEFT      the clamped edge x = 0
  *SURFACE RIGHT  the loaded edge x = 48 (face S2 of the last column of elements)
  *ELSET PANEL    every element

  make-cooks-membrane.py N OUT.inp      (samples/cooks-membrane-2d.inp is N = 16)
"""
import sys

CORNERS = [(0.0, 0.0), (48.0, 44.0), (48.0, 60.0), (0.0, 44.0)]


def point(s, t):
    w = [(1 - s) * (1 - t), s * (1 - t), s * t, (1 - s) * t]
    return tuple(sum(wi * c[k] for wi, c in zip(w, CORNERS)) for k in range(2))


def deck(n):
    node = lambda i, j: j * (n + 1) + i + 1  # noqa: E731
    out = [f"** Cook's membrane, {n} x {n} CPE4: written by scripts/make-cooks-membrane.py", "*NODE"]
    for j in range(n + 1):
        for i in range(n + 1):
            x, y = point(i / n, j / n)
            out.append(f"{node(i, j)}, {x:.12g}, {y:.12g}")
    out.append("*ELEMENT, TYPE=CPE4, ELSET=PANEL")
    for j in range(n):
        for i in range(n):
            e = j * n + i + 1
            out.append(f"{e}, {node(i, j)}, {node(i + 1, j)}, {node(i + 1, j + 1)}, {node(i, j + 1)}")
    out.append("*NSET, NSET=LEFT")
    out += [str(node(0, j)) for j in range(n + 1)]
    out.append("*SURFACE, NAME=RIGHT, TYPE=ELEMENT")
    out += [f"{j * n + n}, S2" for j in range(n)]
    return "\n".join(out) + "\n"


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    with open(sys.argv[2], "w") as f:
        f.write(deck(int(sys.argv[1])))
