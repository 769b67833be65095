#!/usr/bin/env python3
"""Writes the small seed corpora of fuzz_pgm, fuzz_png and fuzz_tiff (committed; rerun to regenerate).
The TIFF seeds are also the hostile TIFFs of tools/hostile_table.sh and tests/test_rasters.cpp.

Usage: python3 fuzz/make_image_seeds.py   (from the repository root)
"""
import os
import struct
import sys
import zlib

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")


def put(target, name, data):
    d = os.path.join(ROOT, target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb") as f:
        f.write(data)


def pgm_seeds():
    raster = bytes((x * 37 + 11) % 256 for x in range(12))
    put("fuzz_pgm", "p5_8bit", b"P5\n4 3\n255\n" + raster)
    put("fuzz_pgm", "p5_16bit", b"P5\n2 2\n1000\n" + struct.pack(">4H", 0, 999, 1000, 512))
    put("fuzz_pgm", "p2_8bit", b"P2\n# a comment\n3 2\n15\n0 5 10\n15 1 2\n")
    put("fuzz_pgm", "p2_16bit", b"P2 2 1 65535 65535 0\n")
    put("fuzz_pgm", "comment_after_magic", b"P5#c\n2 1 255\n\x05\x06")
    put("fuzz_pgm", "crlf", b"P5\r\n2 1\r\n255\r\n\x05\x06")
    put("fuzz_pgm", "vt_ff_zeros", b"P5\x0b002\x0c01 0255\n\x05\x06")
    put("fuzz_pgm", "two_images", b"P5 1 1 255\n\x07P5 1 1 255\n\x08")
    put("fuzz_pgm", "truncated", b"P5\n4 4 255\nabc")
    put("fuzz_pgm", "maxval_small", b"P5 2 2 3\n\x00\x01\x02\x03")
    put("fuzz_pgm", "ppm", b"P6\n1 1 255\nabc")
    put("fuzz_pgm", "p6_8bit", b"P6\n2 2 255\n" + bytes(range(10, 22)))
    put("fuzz_pgm", "p6_16bit", b"P6\n1 2 1000\n" + struct.pack(">6H", 0, 999, 1000, 5, 6, 7))
    put("fuzz_pgm", "p3_8bit", b"P3\n# plain\n2 1\n255\n1 2 3 4 5 6\n")
    put("fuzz_pgm", "p6_gray_equal", b"P6 2 1 255\n\x05\x05\x05\x09\x09\x09")
    put("fuzz_pgm", "p7_rgba", b"P7\nWIDTH 2\nHEIGHT 1\nDEPTH 4\nMAXVAL 255\nTUPLTYPE RGB_ALPHA\nENDHDR\n" + bytes(range(8)))
    put("fuzz_pgm", "p6_16bit_odd", b"P6\n1 1 65535\n\x00\x01\x00\x02\x00")


def png(w, h, depth, ctype, rows, plte=b"", trns=b"", interlace=0):
    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xFFFFFFFF)

    raw = b"".join(b"\x00" + r for r in rows)
    out = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, depth, ctype, 0, 0, interlace))
    if plte:
        out += chunk(b"PLTE", plte)
    if trns:
        out += chunk(b"tRNS", trns)
    return out + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")


def png_seeds():
    put("fuzz_png", "gray8", png(4, 3, 8, 0, [bytes([x * 60 + y for x in range(4)]) for y in range(3)]))
    put("fuzz_png", "gray16", png(2, 2, 16, 0, [struct.pack(">2H", 0, 65535), struct.pack(">2H", 1000, 7)]))
    put("fuzz_png", "gray1", png(8, 2, 1, 0, [b"\xa5", b"\x5a"]))
    put("fuzz_png", "gray4", png(4, 1, 4, 0, [b"\x0f\x84"]))
    put("fuzz_png", "rgb8", png(2, 2, 8, 2, [b"\xff\x00\x00\x00\xff\x00", b"\x00\x00\xff\x10\x20\x30"]))
    put("fuzz_png", "rgb16", png(1, 1, 16, 2, [struct.pack(">3H", 65535, 1, 300)]))
    put("fuzz_png", "ga8", png(2, 1, 8, 4, [b"\x10\x00\x20\xff"]))
    put("fuzz_png", "rgba8", png(1, 2, 8, 6, [b"\x01\x02\x03\x04", b"\xff\xff\xff\x00"]))
    put("fuzz_png", "palette", png(3, 1, 8, 3, [b"\x00\x01\x02"], plte=b"\x00\x00\x00\x40\x40\x40\xff\x00\x00", trns=b"\x00\xff"))
    put("fuzz_png", "palette2", png(4, 1, 2, 3, [b"\x1b"], plte=b"\x00\x00\x00\x55\x55\x55\xaa\xaa\xaa\xff\xff\xff"))
    # Adam7 with a 1x1 image: only pass 1 holds a pixel, so the raster is one filtered row.
    put("fuzz_png", "interlaced", png(1, 1, 8, 0, [b"\x80"], interlace=1))
    rows = [b"\x05\x01\x01", b"\x01\x01\x01"]
    raw = b"\x01" + rows[0] + b"\x02" + rows[1]  # Sub and Up filters
    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xFFFFFFFF)
    put("fuzz_png", "filters", b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 3, 2, 8, 0, 0, 0, 0))
        + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def tiff_seeds():
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
    from tiff_bytes import DOUBLE, SHORT, geo_tags, tiff

    def le(fmt, values):
        return struct.pack("<" + fmt * len(values), *values)

    f32 = le("f", [x * 0.5 - 1.0 for x in range(12)])
    put("fuzz_tiff", "f32_strips", tiff(4, 3, [f32[:16], f32[16:32], f32[32:]], rows_per_strip=1))
    put("fuzz_tiff", "f64_geo_nodata", tiff(3, 2, [le("d", [1.5, -2.0, -9999.0, 4.0, 5.25, 6.0])], bits=64,
                                            extra=geo_tags(500000.0, 5200000.0, 10.0, 10.0, 32633, nodata=-9999.0)))
    put("fuzz_tiff", "f32_nan", tiff(2, 2, [le("f", [1.0, float("nan"), 3.0, 4.0])]))
    put("fuzz_tiff", "i16", tiff(3, 2, [le("h", [-5, 0, 7, 300, -32768, 12])], bits=16, fmt=2,
                                 extra=[(42113, 2, "-32768")]))
    put("fuzz_tiff", "i32_be", tiff(2, 2, [struct.pack(">4i", -70000, 1, 2, 70000)], bits=32, fmt=2, big_endian=True))
    put("fuzz_tiff", "u32", tiff(2, 1, [le("I", [4000000000, 3])], bits=32, fmt=1))
    put("fuzz_tiff", "u16_rgb", tiff(2, 2, [le("H", [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12])], spp=3, bits=16, fmt=1, photometric=2))
    put("fuzz_tiff", "u8_planar_rgb", tiff(2, 2, [bytes([1, 2, 3, 4]), bytes([5, 6, 7, 8]), bytes([9, 10, 11, 12])], spp=3, bits=8,
                                           fmt=1, photometric=2, planar=2))
    put("fuzz_tiff", "u8_minwhite", tiff(2, 2, [bytes([0, 50, 200, 255])], bits=8, fmt=1, photometric=0))
    put("fuzz_tiff", "f32_tiles", tiff(20, 18, [le("f", [float(i) for i in range(256)])] * 4, tile=(16, 16)))
    put("fuzz_tiff", "f32_deflate_pred3", tiff(2, 1, [zlib.compress(bytes([0x3f, 0x80, 0x00, 0x00, 0x00, 0x40, 0x00, 0x00][::1]))],
                                               compression=8, predictor=3))
    put("fuzz_tiff", "u8_palette", tiff(2, 1, [bytes([0, 1])], bits=8, fmt=1, photometric=3,
                                        colormap=[i * 256 for i in range(256)] * 3))
    put("fuzz_tiff", "u8_gray_alpha", tiff(2, 1, [bytes([10, 255, 20, 128])], spp=2, bits=8, fmt=1))
    # Hostile: each gets one clear line (docs/HOSTILE.md).
    whole = tiff(4, 3, [f32[:16], f32[16:32], f32[32:]], rows_per_strip=1)
    put("fuzz_tiff", "truncated", whole[:40])
    put("fuzz_tiff", "lying_offsets", tiff(4, 3, [f32], offsets=[1 << 30], counts=[48]))
    put("fuzz_tiff", "lying_counts", tiff(4, 3, [f32], counts=[1 << 30]))
    put("fuzz_tiff", "huge_30000", tiff(30000, 30000, [f32]))
    put("fuzz_tiff", "huge_side", tiff(100000, 2, [f32]))
    put("fuzz_tiff", "planar_5_samples", tiff(2, 2, [bytes(16)] * 5, spp=5, bits=32, fmt=3, planar=2))
    put("fuzz_tiff", "palette_1bit_float", tiff(8, 1, [bytes([0x5a])], bits=1, fmt=3, photometric=3,
                                                colormap=[0, 65535] * 3))
    put("fuzz_tiff", "i8", tiff(2, 1, [bytes([0x80, 0x7f])], bits=8, fmt=2))
    put("fuzz_tiff", "cmyk", tiff(1, 1, [bytes(4)], spp=4, bits=8, fmt=1, photometric=5))
    put("fuzz_tiff", "unknown_compression", tiff(2, 1, [bytes(8)], compression=50123))
    put("fuzz_tiff", "all_nodata", tiff(2, 1, [le("f", [-1.0, -1.0])], extra=[(42113, 2, "-1")]))
    put("fuzz_tiff", "infinity", tiff(2, 1, [le("f", [1.0, float("inf")])]))
    put("fuzz_tiff", "nodata_text", tiff(2, 1, [le("f", [1.0, 2.0])], extra=[(42113, 2, "none")]))
    put("fuzz_tiff", "no_width", b"II*\x00" + struct.pack("<IH", 8, 1) + struct.pack("<HHII", 257, 4, 1, 1) + struct.pack("<I", 0))


if __name__ == "__main__":
    pgm_seeds()
    png_seeds()
    tiff_seeds()
