#!/usr/bin/env python3
"""Independent checks of erd's raster outputs for tests/raster_test.sh (numpy, not erd's code):

  maxerr ORIG REC E      ORIG (.npy or .pfm) and REC (.pfm, erd reconstruct's): the largest
                         |REC - ORIG| over ORIG's valid pixels is at most E, plus the rounding of
                         REC to float32 (half an ulp of the value); REC has no data exactly where
                         ORIG has none (the holes left open). Prints the error.
  levels REC N           REC has at least N distinct values (not collapsed to a few levels).
  same ORIG.json REC.json  `erd info --json` of a raster and of its reconstruction agree on size,
                         type, georeferencing, nodata value and nodata count.
  scale NPY OUT.pfm LO HI  the heights of NPY mapped linearly onto LO..HI, as a PFM (float32).
Exit 0 when the check holds, 1 otherwise (the reason on stdout).
"""
import json
import sys

import numpy as np


def read_pfm(path):
    with open(path, "rb") as f:
        data = f.read()
    parts = data.split(None, 4)  # magic, width, height, scale, rest
    head = data.index(parts[3]) + len(parts[3]) + 1
    w, h, scale = int(parts[1]), int(parts[2]), float(parts[3])
    c = 3 if parts[0] == b"PF" else 1
    a = np.frombuffer(data[head:head + 4 * w * h * c], dtype="<f4" if scale < 0 else ">f4").astype(np.float64)
    return np.flipud(a.reshape(h, w) if c == 1 else a.reshape(h, w, c))


def read(path):
    return np.load(path) if path.endswith(".npy") else read_pfm(path)


def maxerr(orig, rec, bound):
    a, b, e = read(orig), read(rec), float(bound)
    if a.shape != b.shape:
        return f"shapes differ: {a.shape} and {b.shape}"
    valid = ~np.isnan(a)
    if not np.array_equal(valid, ~np.isnan(b)):
        return f"holes differ: {int((np.isnan(b) & valid).sum())} valid pixels without data, {int((~np.isnan(b) & ~valid).sum())} nodata pixels with data"
    err = np.abs(b[valid] - a[valid])
    slack = np.abs(b[valid]) * 2.0 ** -24  # REC is float32
    worst = float(err.max()) if err.size else 0.0
    print(f"max error {worst:.9g} (bound {e:.9g}) over {int(valid.sum())} valid pixels, {int((~valid).sum())} holes")
    return None if np.all(err <= e + slack) else f"max error {worst} above {e}"


def levels(rec, n):
    b = read(rec)
    k = len(np.unique(b[~np.isnan(b)]))
    print(f"{k} distinct values")
    return None if k >= int(n) else f"only {k} distinct values (at least {n} expected)"


def same(orig, rec):
    a, b = json.load(open(orig)), json.load(open(rec))
    keys = ["width", "height", "channels", "type", "nodata", "nodata_pixels", "georeferenced", "epsg", "pixel_to_world"]
    diff = [k for k in keys if a.get(k) != b.get(k)]
    print(", ".join(f"{k} {a.get(k)}" for k in keys))
    return None if not diff else "differ in " + ", ".join(f"{k}: {a.get(k)} / {b.get(k)}" for k in diff)


def scale(npy, out, lo, hi):
    z = np.load(npy)
    zl, zh = np.nanmin(z), np.nanmax(z)
    s = (z - zl) / (zh - zl) * (float(hi) - float(lo)) + float(lo)
    h, w = s.shape
    with open(out, "wb") as f:
        f.write(b"Pf\n%d %d\n-1.0\n" % (w, h))
        f.write(np.flipud(s).astype("<f4").tobytes())
    np.save(out[:-4] + ".npy", s.astype(np.float32).astype(np.float64))
    return None


if __name__ == "__main__":
    cmd, args = sys.argv[1], sys.argv[2:]
    why = {"maxerr": maxerr, "levels": levels, "same": same, "scale": scale}[cmd](*args)
    if why:
        print(why)
        sys.exit(1)
