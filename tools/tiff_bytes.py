"""TIFF files written byte by byte, independently of libtiff and of erd's writer: the seeds of
fuzz_tiff and the hostile cases (fuzz/make_image_seeds.py) and the elevation models of the tests
(tests/dem_data.py).

    tiff(width, height, blocks, spp=1, bits=32, fmt=3, ...) -> bytes

blocks: the encoded strips (or tiles) in order, planes after planes for planar data. Tags are
written sorted, one IFD, classic little-endian TIFF unless big_endian. GeoTIFF keys and GDAL's
nodata go in through `extra` as (tag, type, values) triples; geo_tags() makes them.
"""
import struct

SHORT, LONG, ASCII, DOUBLE = 3, 4, 2, 12
SIZES = {1: 1, 2: 1, 3: 2, 4: 4, 5: 8, 7: 1, 11: 4, 12: 8, 16: 8}
PACK = {1: "B", 3: "H", 4: "I", 11: "f", 12: "d", 7: "B"}


def tiff(width, height, blocks, spp=1, bits=32, fmt=3, photometric=1, planar=1, rows_per_strip=None, tile=None,
         compression=1, predictor=None, extra=(), big_endian=False, colormap=None, offsets=None, counts=None):
    e = ">" if big_endian else "<"
    out = bytearray(b"MM\x00*" if big_endian else b"II*\x00")
    out += struct.pack(e + "I", 0)  # the IFD offset, patched below
    positions = []
    for b in blocks:
        positions.append(len(out))
        out += b
        if len(out) % 2:
            out += b"\x00"
    entries = [(256, LONG, [width]), (257, LONG, [height]), (258, SHORT, [bits] * spp), (259, SHORT, [compression]),
               (262, SHORT, [photometric]), (277, SHORT, [spp]), (284, SHORT, [planar]), (339, SHORT, [fmt] * spp)]
    if tile:
        entries += [(322, LONG, [tile[0]]), (323, LONG, [tile[1]]), (324, LONG, offsets or positions),
                    (325, LONG, counts or [len(b) for b in blocks])]
    else:
        entries += [(273, LONG, offsets or positions), (278, LONG, [rows_per_strip or height]),
                    (279, LONG, counts or [len(b) for b in blocks])]
    if predictor:
        entries.append((317, SHORT, [predictor]))
    if colormap:
        entries.append((320, SHORT, colormap))
    if spp in (2, 4) and photometric != 3:
        entries.append((338, SHORT, [2]))  # unassociated alpha
    entries += list(extra)
    entries.sort(key=lambda t: t[0])
    # Values that do not fit in the entry go before the IFD.
    data = {}
    for tag, typ, vals in entries:
        raw = vals.encode() + b"\x00" if typ == ASCII else b"".join(struct.pack(e + PACK[typ], v) for v in vals)
        if len(raw) > 4:
            if len(out) % 2:
                out += b"\x00"
            data[tag] = len(out)
            out += raw
    if len(out) % 2:
        out += b"\x00"
    ifd = len(out)
    struct.pack_into(e + "I", out, 4, ifd)
    out += struct.pack(e + "H", len(entries))
    for tag, typ, vals in entries:
        count = len(vals) + 1 if typ == ASCII else len(vals)
        raw = vals.encode() + b"\x00" if typ == ASCII else b"".join(struct.pack(e + PACK[typ], v) for v in vals)
        out += struct.pack(e + "HHI", tag, typ, count)
        out += struct.pack(e + "I", data[tag]) if tag in data else raw.ljust(4, b"\x00")
    out += struct.pack(e + "I", 0)
    return bytes(out)


def geo_tags(origin_x, origin_y, pixel_x, pixel_y, epsg, projected=True, nodata=None):
    """ModelPixelScale, ModelTiepoint (raster (0, 0) at the origin), GeoKeyDirectory naming the CRS
    by its EPSG code (pixels are areas), and GDAL_NODATA when given."""
    keys = [1, 1, 0, 3, 1024, 0, 1, 1 if projected else 2, 1025, 0, 1, 1, 3072 if projected else 2048, 0, 1, epsg]
    tags = [(33550, DOUBLE, [pixel_x, pixel_y, 0.0]), (33922, DOUBLE, [0.0, 0.0, 0.0, origin_x, origin_y, 0.0]),
            (34735, SHORT, keys)]
    if nodata is not None:
        tags.append((42113, ASCII, repr(float(nodata)) if isinstance(nodata, float) else str(nodata)))
    return tags
