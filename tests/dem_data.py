#!/usr/bin/env python3
"""The real elevation models of the tests and the terrain bench, written from Debian's
python-matplotlib-data (nothing of them is committed):

  jacksboro.tif  jacksboro_fault_dem.npz (Jacksboro fault, Tennessee, 3 arc-second cells), float32
                 GeoTIFF in EPSG:4326 degrees; jacksboro16.tif the same as int16 (its own type) with
                 GDAL_NODATA -32768 and a block of nodata; jacksboro.pfm float32
  topobathy.tif  topobathy.npz (coast and sea floor off Vancouver Island, negative heights), float32
                 GeoTIFF in degrees; topobathy.pfm
  NAME.png       the 16-bit PNG hmm reads: (h - lo) / (hi - lo) * 65535, rounded
  NAME.npy       the heights as float64, NaN for nodata: the independent measurements read these

Usage: tests/dem_data.py OUT_DIR   (prints one line per model: name, width, height, lo, hi)
"""
import os
import struct
import sys
import zlib

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
from tiff_bytes import geo_tags, tiff  # noqa: E402

DATA = "/usr/share/matplotlib/mpl-data/sample_data"


def pfm(path, z):
    h, w = z.shape
    with open(path, "wb") as f:
        f.write(b"Pf\n%d %d\n-1.0\n" % (w, h))
        f.write(np.flipud(z).astype("<f4").tobytes())


def png16(path, q):
    h, w = q.shape
    raw = b"".join(b"\x00" + q[y].astype(">u2").tobytes() for y in range(h))

    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xFFFFFFFF)

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 16, 0, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def geotiff(path, z, dtype, origin, pixel, nodata=None):
    h, w = z.shape
    a = np.ascontiguousarray(z.astype(dtype))
    rows = 16
    strips = [a[y:y + rows].astype(a.dtype.newbyteorder("<")).tobytes() for y in range(0, h, rows)]
    fmt = 3 if a.dtype.kind == "f" else 2
    extra = geo_tags(origin[0], origin[1], pixel[0], pixel[1], 4326, projected=False, nodata=nodata)
    with open(path, "wb") as f:
        f.write(tiff(w, h, strips, bits=8 * a.dtype.itemsize, fmt=fmt, rows_per_strip=rows, extra=extra))


def main(out):
    os.makedirs(out, exist_ok=True)
    d = np.load(os.path.join(DATA, "jacksboro_fault_dem.npz"))
    jb = d["elevation"]
    # The npz's corners: x from xmin to xmax, y from ymax (north, row 0) down to ymin.
    jb_origin = (float(d["xmin"]), float(d["ymin"]))
    jb_pixel = (float(d["dx"]), float(d["dy"]))
    t = np.load(os.path.join(DATA, "topobathy.npz"))
    tb = t["topo"]
    lon, lat = t["longitude"].astype(np.float64), t["latitude"].astype(np.float64)
    # Rows north first: the npz's latitudes ascend, so its rows are flipped.
    if lat[0] < lat[-1]:
        tb = tb[::-1]
        lat = lat[::-1]
    tb_origin = (lon[0] - 360.0 if lon[0] > 180 else lon[0], lat[0])
    tb_pixel = ((lon[-1] - lon[0]) / (len(lon) - 1), (lat[0] - lat[-1]) / (len(lat) - 1))
    for name, z, origin, pixel in (("jacksboro", jb.astype(np.float32), jb_origin, jb_pixel),
                                   ("topobathy", tb.astype(np.float32), tb_origin, tb_pixel)):
        geotiff(os.path.join(out, name + ".tif"), z, np.float32, origin, pixel)
        pfm(os.path.join(out, name + ".pfm"), z)
        lo, hi = float(z.min()), float(z.max())
        png16(os.path.join(out, name + ".png"), np.round((z.astype(np.float64) - lo) / (hi - lo) * 65535).astype(np.uint16))
        np.save(os.path.join(out, name + ".npy"), z.astype(np.float64))
        print(name, z.shape[1], z.shape[0], repr(lo), repr(hi))
    # int16 with nodata: a block in the middle and the first rows' western half.
    j16 = jb.astype(np.int16).copy()
    h, w = j16.shape
    j16[h // 3:h // 3 + 40, w // 2:w // 2 + 60] = -32768
    j16[:12, :w // 2] = -32768
    geotiff(os.path.join(out, "jacksboro16.tif"), j16, np.int16, jb_origin, jb_pixel, nodata=-32768)
    z = j16.astype(np.float64)
    z[j16 == -32768] = np.nan
    np.save(os.path.join(out, "jacksboro16.npy"), z)
    print("jacksboro16", w, h, repr(float(np.nanmin(z))), repr(float(np.nanmax(z))))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
