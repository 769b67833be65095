#!/usr/bin/env python3
"""The seam picture of docs/img (issue 48): a window of a merged mesh (`erd tiles --merge x.ply`)
around a corner shared by four tiles (or any point), drawn as SVG: faces shaded by height, their
edges in black, each tile's faces in its own tint, the tiles' border lines dashed red, and the
ERD discontinuities (edges whose two faces take different copies of an end: a step) in blue.

    tiles_seam_svg.py MESH.ply W H TILE CX CY HALF OUT.svg    (window: CX +- HALF, CY +- HALF pixels)
"""
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 2)[0] + "/tests")
from tiles_check import read_mesh  # noqa: E402


def main():
    path, w, h, tile, cx, cy, half, out = sys.argv[1:9]
    w, h, tile, cx, cy, half = int(w), int(h), int(tile), int(cx), int(cy), int(half)
    v, f = read_mesh(path)
    x, y, z = v[:, 0], (h - 1) - v[:, 1], v[:, 2]  # back to image rows (y down)
    x0, x1, y0, y1 = cx - half, cx + half, cy - half, cy + half
    scale = 900.0 / (2 * half)
    zlo, zhi = z.min(), z.max()
    tints = [(255, 235, 205), (205, 230, 255), (215, 250, 215), (245, 215, 245)]
    parts = ['<svg xmlns="http://www.w3.org/2000/svg" width="900" height="900" viewBox="0 0 900 900">',
             '<rect width="900" height="900" fill="white"/>']
    for a, b, c in f:
        xs, ys = x[[a, b, c]], y[[a, b, c]]
        if xs.max() < x0 or xs.min() > x1 or ys.max() < y0 or ys.min() > y1:
            continue
        cxf, cyf = xs.mean(), ys.mean()
        t = tints[(int(cxf // tile) % 2) + 2 * (int(cyf // tile) % 2)]
        g = 0.55 + 0.45 * (z[[a, b, c]].mean() - zlo) / max(zhi - zlo, 1e-12)
        fill = "rgb(%d,%d,%d)" % tuple(int(k * g) for k in t)
        pts = " ".join("%.2f,%.2f" % ((px - x0) * scale, (py - y0) * scale) for px, py in zip(xs, ys))
        parts.append('<polygon points="%s" fill="%s" stroke="black" stroke-width="0.6"/>' % (pts, fill))
    for k in range(0, max(w, h), tile):
        if x0 <= k <= x1:
            parts.append('<line x1="%.1f" y1="0" x2="%.1f" y2="900" stroke="red" stroke-width="2" stroke-dasharray="8,6" '
                         'opacity="0.7"/>' % ((k - x0) * scale, (k - x0) * scale))
        if y0 <= k <= y1:
            parts.append('<line x1="0" y1="%.1f" x2="900" y2="%.1f" stroke="red" stroke-width="2" stroke-dasharray="8,6" '
                         'opacity="0.7"/>' % ((k - y0) * scale, (k - y0) * scale))
    # Discontinuities: the faces on either side of an edge (by position) use different copies.
    key = np.round(v[:, 0] * 2).astype(np.int64) * (4 * h + 8) + np.round(v[:, 1] * 2).astype(np.int64)
    sides = {}
    for a, b, c in f:
        for p, q in ((a, b), (b, c), (c, a)):
            sides.setdefault(frozenset((key[p], key[q])), []).append({key[p]: p, key[q]: q})
    for e, fs in sides.items():
        if len(fs) != 2 or fs[0] == fs[1]:
            continue
        p, q = fs[0].values()
        xs, ys = x[[p, q]], y[[p, q]]
        if xs.max() < x0 or xs.min() > x1 or ys.max() < y0 or ys.min() > y1:
            continue
        parts.append('<line x1="%.2f" y1="%.2f" x2="%.2f" y2="%.2f" stroke="rgb(20,60,230)" stroke-width="3"/>' %
                     ((xs[0] - x0) * scale, (ys[0] - y0) * scale, (xs[1] - x0) * scale, (ys[1] - y0) * scale))
    parts.append("</svg>")
    with open(out, "w") as fo:
        fo.write("\n".join(parts) + "\n")


if __name__ == "__main__":
    main()
