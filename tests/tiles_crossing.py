#!/usr/bin/env python3
"""Checks the planned crossings of an `erd tiles` ERD run (docs/DECISIONS.md "Tiles"): for every
vcross/hcross offset of DIR/plan.txt, both tiles of that border have a vertex at the crossing,
a discontinuity ending there (an edge of it across which the corner values jump), and the same
two values at the seam: on the side towards the lower offset and towards the higher, different.

    tiles_crossing.py DIR     prints "ok N crossings" or the first problem and exits 1
"""
import sys


def read_erd(path):
    words = []
    with open(path) as f:
        lines = f.read().split("\n")
    if lines and lines[0].strip() == "erd-header 1":
        lines = lines[lines.index("end") + 1:]
    for line in lines:
        words += line.split("#")[0].split()
    at = 1  # maxval
    nv = int(words[at]); at += 1
    verts = []
    for _ in range(nv):
        verts.append((int(words[at]), int(words[at + 1]), float(words[at + 2]))); at += 3
    nf = int(words[at]); at += 1
    faces = []
    for _ in range(nf):
        faces.append((int(words[at]), int(words[at + 1]), int(words[at + 2]))); at += 3
    nw = int(words[at]); at += 1
    wedge = {}
    for _ in range(nw):
        wedge[(int(words[at]), int(words[at + 1]))] = float(words[at + 2]); at += 3
    return verts, faces, wedge


def plan(dirname):
    p = {"vcross": [], "hcross": []}
    for line in open(dirname + "/plan.txt"):
        w = line.split()
        if w[0] in ("size", "tile", "grid"):
            p[w[0]] = [int(x) for x in w[1:]]
        elif w[0] in ("vcross", "hcross"):
            p[w[0]].append((int(w[1]), int(w[2]), [int(x) for x in w[4:]]))
    return p


def seam(dirname, row, col, point, along_x):
    """The values at `point` (tile frame, doubled) of tile (row, col): towards the lower offset and
    towards the higher, or a problem."""
    verts, faces, wedge = read_erd("%s/tile_%d_%d.erd" % (dirname, row, col))
    at = [i for i, v in enumerate(verts) if (v[0], v[1]) == point]
    if not at:
        return "no vertex at %s" % (point,)
    v = at[0]
    value = {f: wedge.get((v, f), verts[v][2]) for f, t in enumerate(faces) if v in t}
    lo = hi = None
    jumps = []
    for f, val in value.items():
        for u in faces[f]:
            if u == v:
                continue
            q = verts[u]
            if (q[1] == point[1]) if along_x else (q[0] == point[0]):  # a side edge of the face
                off, mine = (q[0], point[0]) if along_x else (q[1], point[1])
                if off < mine:
                    lo = val
                else:
                    hi = val
            for g, wal in value.items():  # the face across edge (v, u)
                if g > f and u in faces[g] and wal != val:
                    jumps.append(q)
    if lo is None or hi is None:
        return "no side edge on both sides of %s" % (point,)
    if not jumps:
        return "no discontinuity ends at %s" % (point,)
    return lo, hi


def main(dirname):
    p = plan(dirname)
    W, H = p["size"]
    T = p["tile"][0]
    nx, ny = p["grid"]
    col = lambda i: W - 1 if i >= nx else i * T
    row = lambda j: H - 1 if j >= ny else j * T
    n = 0
    for key in ("vcross", "hcross"):
        for line, cell, offsets in p[key]:
            for o in offsets:
                if key == "vcross":  # vertical line `line`, tile row `cell`: tiles (cell, line-1), (cell, line)
                    left = seam(dirname, cell, line - 1, (2 * (col(line) - col(line - 1)), 2 * o + 1), False)
                    right = seam(dirname, cell, line, (0, 2 * o + 1), False)
                else:
                    left = seam(dirname, line - 1, cell, (2 * o + 1, 2 * (row(line) - row(line - 1))), True)
                    right = seam(dirname, line, cell, (2 * o + 1, 0), True)
                for s in (left, right):
                    if isinstance(s, str):
                        return "%s %d %d offset %d: %s" % (key, line, cell, o, s)
                if left != right or left[0] == left[1]:
                    return "%s %d %d offset %d: seam values %s and %s" % (key, line, cell, o, left, right)
                n += 1
    return "ok %d crossings" % n if n else "the plan has no crossing"


if __name__ == "__main__":
    result = main(sys.argv[1])
    print(result)
    sys.exit(0 if result.startswith("ok") else 1)
