#!/usr/bin/env python3
"""PSNR of a heightmap mesh written as binary STL by fogleman/hmm against its image.

Usage: bench/stl_psnr.py IMAGE.pgm MESH.stl   -> prints the PSNR in dB

hmm's convention (`hmm -z 1`, no base): a vertex is a pixel (x, y) written as (x, H-1-y, v) with v
the sample over its full range (0..1). The mesh is evaluated at every pixel linearly over the
triangle holding it, rounded to the image's integers, as erd reconstructs its own meshes; the peak
is 2^p - 1 of the image's maxval (erd's rule). Binary PGM (8 or 16 bits) only.
"""
import math
import re
import struct
import sys

import numpy as np


def read_pgm(path):
    with open(path, "rb") as f:
        data = f.read()
    gap = rb"(?:\s|#[^\n]*\n)+"
    m = re.match(rb"P5" + gap + rb"(\d+)" + gap + rb"(\d+)" + gap + rb"(\d+)\s", data)
    if not m:
        raise SystemExit(f"{path}: not a binary PGM")
    w, h, maxval = (int(v) for v in m.groups())
    dtype = ">u2" if maxval > 255 else "u1"
    img = np.frombuffer(data, dtype=dtype, count=w * h, offset=m.end()).reshape(h, w)
    return img.astype(np.float64), maxval


def read_stl(path):
    with open(path, "rb") as f:
        data = f.read()
    (count,) = struct.unpack_from("<I", data, 80)
    rec = np.dtype([("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")])
    return np.frombuffer(data, dtype=rec, count=count, offset=84)["v"].astype(np.float64)


def main():
    img, maxval = read_pgm(sys.argv[1])
    tris = read_stl(sys.argv[2])
    h, w = img.shape
    top = float((1 << max(1, math.ceil(math.log2(maxval + 1)))) - 1)
    rec = np.full((h, w), np.nan)
    for t in tris:
        xs, ys, zs = t[:, 0], (h - 1) - t[:, 1], t[:, 2] * top
        x0, x1 = int(math.floor(xs.min())), int(math.ceil(xs.max()))
        y0, y1 = int(math.floor(ys.min())), int(math.ceil(ys.max()))
        gx, gy = np.meshgrid(np.arange(x0, x1 + 1), np.arange(y0, y1 + 1))
        d = (ys[1] - ys[2]) * (xs[0] - xs[2]) + (xs[2] - xs[1]) * (ys[0] - ys[2])
        if d == 0:
            continue
        a = ((ys[1] - ys[2]) * (gx - xs[2]) + (xs[2] - xs[1]) * (gy - ys[2])) / d
        b = ((ys[2] - ys[0]) * (gx - xs[2]) + (xs[0] - xs[2]) * (gy - ys[2])) / d
        c = 1.0 - a - b
        inside = (a >= -1e-9) & (b >= -1e-9) & (c >= -1e-9)
        rec[gy[inside], gx[inside]] = a[inside] * zs[0] + b[inside] * zs[1] + c[inside] * zs[2]
    if np.isnan(rec).any():
        raise SystemExit(f"{sys.argv[2]}: {int(np.isnan(rec).sum())} pixels outside the mesh")
    mse = float(np.mean((np.clip(np.floor(rec + 0.5), 0, maxval) - img) ** 2))
    print("inf" if mse == 0 else f"{10 * math.log10(top * top / mse):.4f}")


if __name__ == "__main__":
    main()
