#!/usr/bin/env python3
"""Checks that a mesh (`erd tiles --merge` .ply or .obj) is a valid triangulation of the W x H
rectangle: every face counter-clockwise with positive area, the areas summing to (W-1)(H-1),
every edge used by one face (then on the rectangle's boundary) or by two faces in opposite
directions (no crack, no T-junction, no overlap), and Euler's relation V - E + F = 1 over the
vertices identified by position (an ERD mesh's wedge copies share one).

    tiles_check.py MESH W H        prints "ok V E F" or the first problem and exits 1
"""
import sys

import numpy as np


def read_mesh(path):
    with open(path, "rb") as f:
        data = f.read()
    if path.endswith(".ply"):
        head, body = data.split(b"end_header\n", 1)
        nv = int(head.split(b"element vertex ")[1].split(b"\n")[0])
        nf = int(head.split(b"element face ")[1].split(b"\n")[0])
        rows = body.split(b"\n")
        v = np.array([r.split() for r in rows[:nv]], dtype=np.float64)
        f = np.array([r.split()[1:] for r in rows[nv:nv + nf]], dtype=np.int64)
        return v, f
    vs, fs = [], []
    for line in data.split(b"\n"):
        if line.startswith(b"v "):
            vs.append(line.split()[1:4])
        elif line.startswith(b"f "):
            fs.append([int(t.split(b"/")[0]) - 1 for t in line.split()[1:4]])
    return np.array(vs, dtype=np.float64), np.array(fs, dtype=np.int64)


def check(path, w, h):
    v, f = read_mesh(path)
    if len(f) == 0:
        return "no faces"
    # Vertices by position (x, y): wedge copies of an ERD vertex are one point of the triangulation.
    key = np.round(v[:, 0] * 2).astype(np.int64) * (4 * h + 8) + np.round(v[:, 1] * 2).astype(np.int64)
    uniq, pos = np.unique(key, return_inverse=True)
    f = pos[f]
    p = v[:, :2]
    xy = np.zeros((len(uniq), 2))
    xy[pos] = p
    a, b, c = xy[f[:, 0]], xy[f[:, 1]], xy[f[:, 2]]
    area2 = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (c[:, 0] - a[:, 0]) * (b[:, 1] - a[:, 1])
    if (area2 <= 0).any():
        return "%d faces not counter-clockwise or degenerate" % int((area2 <= 0).sum())
    total = area2.sum() / 2
    if abs(total - (w - 1) * (h - 1)) > 1e-6 * w * h:
        return "areas sum to %r, not %d (overlap or hole)" % (total, (w - 1) * (h - 1))
    n = len(uniq)
    directed = np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]])
    d = directed[:, 0] * n + directed[:, 1]
    if len(np.unique(d)) != len(d):
        return "a directed edge used twice (overlap)"
    und = np.minimum(directed[:, 0], directed[:, 1]) * n + np.maximum(directed[:, 0], directed[:, 1])
    ue, counts = np.unique(und, return_counts=True)
    if (counts > 2).any():
        return "an edge with more than two faces"
    single = ue[counts == 1]
    i, j = single // n, single % n
    xi, xj = xy[i], xy[j]
    on = ((xi[:, 0] == xj[:, 0]) & ((xi[:, 0] == 0) | (xi[:, 0] == w - 1))) | \
         ((xi[:, 1] == xj[:, 1]) & ((xi[:, 1] == 0) | (xi[:, 1] == h - 1)))
    if not on.all():
        k = int(np.argmin(on))
        return "a crack: edge %s-%s has one face and is not on the boundary" % (xi[k].tolist(), xj[k].tolist())
    used = np.unique(f)
    if len(used) != n:
        return "%d vertices in no face" % (n - len(used))
    euler = n - len(ue) + len(f)
    if euler != 1:
        return "Euler: V - E + F = %d, not 1" % euler
    return "ok %d %d %d" % (n, len(ue), len(f))


if __name__ == "__main__":
    result = check(sys.argv[1], int(sys.argv[2]), int(sys.argv[3]))
    print(result)
    sys.exit(0 if result.startswith("ok") else 1)
