#!/usr/bin/env python3
"""The graphics test set of `make eval` (issue 44): anti-aliased drawings of our own as SVG.

usage: tools/graphics_svg.py OUT_DIR [IMAGES_DIR]

Writes OUT_DIR/NAME.svg for every drawing below, deterministically (fixed seeds, no clock): random
gray and colour shapes (the issue's 14-shape 512 x 384 example), a bar, a pie and a line chart,
four flags of our own design, text in DejaVu Sans, Serif and Mono at several sizes (gray, and
colour on coloured bars), a logo, and sheets of icons from Debian's Adwaita icon theme (their path
data inlined, tinted for the colour sheet). With IMAGES_DIR (../shared/images) also the mixed
pictures, which embed a crop of a photo as a PNG data URI: half photo / half chart (gray, peppers)
and text and a logo over a photo (colour, kodim03). rsvg-convert renders them (anti-aliased);
tools/eval_graphics.sh does that and meshes the result. Nothing here is copied into the repository:
the photos and icons are read from where they are installed at run time.

Standard library only. Exit status 1 with one line on stderr when an input is missing.
"""
import base64
import math
import os
import random
import re
import struct
import sys
import zlib

FONTS = ("DejaVu Sans", "DejaVu Serif", "DejaVu Sans Mono")
ICON_DIR = "/usr/share/icons/Adwaita/scalable"
# Adwaita symbolic icons (16 x 16 viewBox, one fill colour #2e3436 or the like).
ICONS = ("places/user-home-symbolic", "places/folder-symbolic", "places/user-trash-symbolic",
         "places/folder-music-symbolic", "places/folder-pictures-symbolic", "places/network-server-symbolic",
         "places/folder-download-symbolic", "places/user-bookmarks-symbolic", "places/folder-documents-symbolic",
         "places/folder-videos-symbolic", "places/start-here-symbolic", "places/network-workgroup-symbolic")
PALETTE = ("#d62728", "#1f77b4", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf", "#bcbd22")


def fail(msg):
    sys.stderr.write("graphics_svg: " + msg + "\n")
    sys.exit(1)


def svg(w, h, body, background="#ffffff"):
    return ('<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" viewBox="0 0 %d %d">\n'
            '<rect width="%d" height="%d" fill="%s"/>\n%s</svg>\n' % (w, h, w, h, w, h, background, body))


def gray(v):
    return "#%02x%02x%02x" % (v, v, v)


def f(x):
    return ("%.3f" % x).rstrip("0").rstrip(".")


def points(pts):
    return " ".join("%s,%s" % (f(x), f(y)) for x, y in pts)


def star(cx, cy, r, n=5, inner=0.382, rot=-90.0):
    pts = []
    for k in range(2 * n):
        a = math.radians(rot + 180.0 * k / n)
        rr = r if k % 2 == 0 else r * inner
        pts.append((cx + rr * math.cos(a), cy + rr * math.sin(a)))
    return '<polygon points="%s" fill="%%s"/>\n' % points(pts)


def text(x, y, s, size, font="DejaVu Sans", fill="#000000", weight="normal", anchor="start"):
    s = s.replace("&", "&amp;").replace("<", "&lt;")
    return ('<text x="%s" y="%s" font-family="%s" font-size="%s" font-weight="%s" fill="%s" text-anchor="%s">%s</text>\n'
            % (f(x), f(y), font, f(size), weight, fill, anchor, s))


def shapes(w, h, n, seed, colour):
    """n random circles, triangles and rotated rectangles of random flat colours (the issue's case)."""
    rnd = random.Random(seed)
    fill = (lambda: "#%02x%02x%02x" % (rnd.randrange(256), rnd.randrange(256), rnd.randrange(256))) if colour \
        else (lambda: gray(rnd.randrange(256)))
    body = ""
    bg = fill()
    for _ in range(n):
        kind = rnd.randrange(3)
        cx, cy = rnd.uniform(0, w), rnd.uniform(0, h)
        s = rnd.uniform(0.06, 0.25) * min(w, h)
        if kind == 0:
            body += '<circle cx="%s" cy="%s" r="%s" fill="%s"/>\n' % (f(cx), f(cy), f(s), fill())
        elif kind == 1:
            pts = [(cx + s * 1.4 * math.cos(a), cy + s * 1.4 * math.sin(a))
                   for a in (rnd.uniform(0, 2 * math.pi) for _ in range(3))]
            body += '<polygon points="%s" fill="%s"/>\n' % (points(pts), fill())
        else:
            rw, rh, ang = s * rnd.uniform(1, 2.5), s * rnd.uniform(0.5, 1.5), rnd.uniform(0, 180)
            body += ('<rect x="%s" y="%s" width="%s" height="%s" transform="rotate(%s %s %s)" fill="%s"/>\n'
                     % (f(cx - rw / 2), f(cy - rh / 2), f(rw), f(rh), f(ang), f(cx), f(cy), fill()))
    return svg(w, h, body, bg)


def axes(x0, y0, x1, y1, ticks, label_fmt, font_size=11):
    """Grid lines, axes and tick labels of a chart whose plot area is (x0, y0) - (x1, y1)."""
    body = ""
    for k in range(ticks + 1):
        y = y1 - (y1 - y0) * k / ticks
        body += '<line x1="%s" y1="%s" x2="%s" y2="%s" stroke="#c8c8c8" stroke-width="1"/>\n' % (f(x0), f(y), f(x1), f(y))
        body += text(x0 - 6, y + 4, label_fmt(k), font_size, fill="#333333", anchor="end")
    body += '<path d="M%s %s V%s H%s" fill="none" stroke="#222222" stroke-width="1.5"/>\n' % (f(x0), f(y0), f(y1), f(x1))
    return body


def bar_chart(w, h):
    rnd = random.Random(44)
    x0, y0, x1, y1 = 56, 40, w - 20, h - 48
    body = text(w / 2, 26, "Quarterly results", 18, weight="bold", anchor="middle")
    body += axes(x0, y0, x1, y1, 5, lambda k: str(20 * k))
    groups, series = 6, 3
    gw = (x1 - x0) / groups
    for g in range(groups):
        for s in range(series):
            v = rnd.uniform(0.1, 0.95)
            bx = x0 + g * gw + gw * (0.12 + 0.25 * s)
            body += '<rect x="%s" y="%s" width="%s" height="%s" fill="%s"/>\n' % (
                f(bx), f(y1 - v * (y1 - y0)), f(gw * 0.24), f(v * (y1 - y0)), PALETTE[s])
        body += text(x0 + (g + 0.5) * gw, y1 + 18, "Q%d" % (g + 1), 12, anchor="middle")
    return svg(w, h, body)


def pie_chart(w, h):
    rnd = random.Random(7)
    shares = [rnd.uniform(0.5, 3) for _ in range(7)]
    total = sum(shares)
    cx, cy, r = w * 0.36, h * 0.52, min(w, h) * 0.4
    body, a0 = "", -90.0
    for k, s in enumerate(shares):
        a1 = a0 + 360.0 * s / total
        p0 = (cx + r * math.cos(math.radians(a0)), cy + r * math.sin(math.radians(a0)))
        p1 = (cx + r * math.cos(math.radians(a1)), cy + r * math.sin(math.radians(a1)))
        body += '<path d="M%s %s L%s %s A%s %s 0 %d 1 %s %s Z" fill="%s" stroke="#ffffff" stroke-width="2"/>\n' % (
            f(cx), f(cy), f(p0[0]), f(p0[1]), f(r), f(r), 1 if a1 - a0 > 180 else 0, f(p1[0]), f(p1[1]), PALETTE[k], )
        ly = 60 + 36 * k
        body += '<rect x="%s" y="%s" width="18" height="18" fill="%s"/>\n' % (f(w * 0.74), f(ly - 14), PALETTE[k])
        body += text(w * 0.74 + 26, ly, "%.0f%%" % (100 * s / total), 15)
        a0 = a1
    return svg(w, h, body, "#f4f4f4")


def line_chart(w, h):
    rnd = random.Random(3)
    x0, y0, x1, y1 = 56, 30, w - 20, h - 40
    body = axes(x0, y0, x1, y1, 4, lambda k: "%d.0" % k)
    n = 24
    for s, shade in enumerate(("#000000", "#555555", "#999999")):
        v = rnd.uniform(0.3, 0.7)
        pts = []
        for k in range(n):
            v = min(0.98, max(0.02, v + rnd.uniform(-0.12, 0.12)))
            pts.append((x0 + (x1 - x0) * k / (n - 1), y1 - v * (y1 - y0)))
        dash = ' stroke-dasharray="6 4"' if s == 2 else ""
        body += '<polyline points="%s" fill="none" stroke="%s" stroke-width="%s"%s/>\n' % (points(pts), shade, 2.5 - 0.5 * s, dash)
        for p in pts[::6]:
            body += '<circle cx="%s" cy="%s" r="3.5" fill="%s"/>\n' % (f(p[0]), f(p[1]), shade)
    for k in range(0, n, 4):
        body += text(x0 + (x1 - x0) * k / (n - 1), y1 + 18, "%02d" % k, 11, anchor="middle")
    return svg(w, h, body)


def flag_stripes(w, h):
    """Thirteen stripes and a canton of stars in rows (our own drawing)."""
    body = ""
    sh = h / 13
    for k in range(13):
        body += '<rect x="0" y="%s" width="%d" height="%s" fill="%s"/>\n' % (f(k * sh), w, f(sh), "#b22234" if k % 2 == 0 else "#ffffff")
    cw, ch = w * 0.4, sh * 7
    body += '<rect x="0" y="0" width="%s" height="%s" fill="#3c3b6e"/>\n' % (f(cw), f(ch))
    for row in range(9):
        for col in range(11 if row % 2 == 0 else 10):
            if (col + (row % 2)) % 2:
                continue
            body += star(cw * (col + 1) / 12 + (cw / 24 if row % 2 else 0), ch * (row + 1) / 10, sh * 0.42) % "#ffffff"
    return svg(w, h, body)


def flag_disc(w, h):
    """A disc off centre on a field, with a thin border (our own drawing)."""
    body = '<circle cx="%s" cy="%s" r="%s" fill="#f42a41"/>\n' % (f(w * 0.45), f(h / 2), f(h * 0.3))
    body += '<rect x="4" y="4" width="%d" height="%d" fill="none" stroke="#ffce00" stroke-width="3"/>\n' % (w - 8, h - 8)
    return svg(w, h, body, "#006a4e")


def flag_cross(w, h):
    """An off-centre cross with a fimbriation and a small star (our own drawing)."""
    cx, t = w * 0.36, h * 0.16
    body = '<rect x="%s" y="0" width="%s" height="%d" fill="#ffffff"/>\n' % (f(cx - t * 0.8), f(t * 1.6), h)
    body += '<rect x="0" y="%s" width="%d" height="%s" fill="#ffffff"/>\n' % (f(h / 2 - t * 0.8), w, f(t * 1.6))
    body += '<rect x="%s" y="0" width="%s" height="%d" fill="#d21034"/>\n' % (f(cx - t / 2), f(t), h)
    body += '<rect x="0" y="%s" width="%d" height="%s" fill="#d21034"/>\n' % (f(h / 2 - t / 2), w, f(t))
    body += star(w * 0.78, h * 0.22, h * 0.1) % "#ffd700"
    return svg(w, h, body, "#00247d")


def flag_chevron(w, h):
    """Three horizontal bands, a chevron at the hoist with a star, a diagonal sash (our own drawing)."""
    body = '<rect x="0" y="0" width="%d" height="%s" fill="#ffffff"/>\n' % (w, f(h / 3))
    body += '<rect x="0" y="%s" width="%d" height="%s" fill="#009b3a"/>\n' % (f(2 * h / 3), w, f(h / 3 + 1))
    body += '<polygon points="%s" fill="#fedf00" stroke="#000000" stroke-width="4"/>\n' % points([(w, 0), (w * 0.6, h), (w, h)])
    body += '<polygon points="%s" fill="#ce1126"/>\n' % points([(0, 0), (w * 0.42, h / 2), (0, h)])
    body += star(w * 0.13, h / 2, h * 0.13) % "#ffffff"
    return svg(w, h, body, "#000000")


SAMPLE = ("The quick brown fox jumps over the lazy dog 0123456789",
          "Sphinx of black quartz, judge my vow! (ERD, GPI, 3.14%)",
          "Pack my box with five dozen liquor jugs; 42 = 6 x 7")


def text_gray(w, h):
    body, y = "", 14
    for size in (8, 10, 12, 14, 18, 24, 32):
        for k, font in enumerate(FONTS):
            if y > h - 4:
                break
            body += text(6, y, SAMPLE[k], size, font=font, fill=gray((k * 70) % 160))
            y += size * 1.25
        y += 2
    return svg(w, h, body)


def text_colour(w, h):
    body, y = "", 0
    bands = (("#1f3b73", "#ffffff", 30), ("#ffd447", "#202020", 22), ("#c0392b", "#fdfdfd", 16),
             ("#ffffff", "#0b6623", 12), ("#2d2d2d", "#7fdbff", 10), ("#e8f4ea", "#8b0000", 9))
    for k, (bg, fg, size) in enumerate(bands):
        bh = h / len(bands)
        body += '<rect x="0" y="%s" width="%d" height="%s" fill="%s"/>\n' % (f(y), w, f(bh + 0.5), bg)
        body += text(8, y + bh * 0.42, SAMPLE[k % 3], size, font=FONTS[k % 3], fill=fg, weight="bold" if k % 2 == 0 else "normal")
        body += text(8, y + bh * 0.42 + size * 1.2, SAMPLE[(k + 1) % 3], size * 0.8, font=FONTS[(k + 1) % 3], fill=fg)
        y += bh
    return svg(w, h, body)


def logo(w, h):
    """Rings, a gradient disc, a wordmark and a tag line (our own logo)."""
    cx, cy, r = w * 0.28, h / 2, h * 0.32
    body = ('<defs><linearGradient id="g" x1="0" y1="0" x2="1" y2="1">'
            '<stop offset="0" stop-color="#0f4c81"/><stop offset="1" stop-color="#46b3e6"/></linearGradient></defs>\n')
    body += '<circle cx="%s" cy="%s" r="%s" fill="url(#g)"/>\n' % (f(cx), f(cy), f(r))
    for k in range(3):
        body += '<circle cx="%s" cy="%s" r="%s" fill="none" stroke="#ffffff" stroke-width="%s"/>\n' % (
            f(cx), f(cy), f(r * (0.35 + 0.2 * k)), f(3 - k * 0.8))
    body += '<polygon points="%s" fill="#f5a623"/>\n' % points([(cx - r * 0.2, cy + r * 0.25), (cx + r * 0.35, cy - r * 0.3), (cx + r * 0.4, cy + r * 0.3)])
    body += text(w * 0.52, h * 0.52, "erd", h * 0.3, fill="#0f4c81", weight="bold")
    body += text(w * 0.52, h * 0.68, "edges kept, pixels saved", h * 0.06, fill="#555555")
    return svg(w, h, body, "#fafafa")


def icon_body(name):
    path = os.path.join(ICON_DIR, name + ".svg")
    try:
        with open(path, encoding="utf-8") as fh:
            src = fh.read()
    except OSError as e:
        fail("%s: %s (install adwaita-icon-theme)" % (path, e.strerror))
    m = re.search(r"<svg[^>]*>(.*)</svg>", src, re.S)
    if not m:
        fail("%s: no <svg> element" % path)
    return m.group(1)


def icons(w, h, colour):
    """A sheet of Adwaita symbolic icons at 48 px (dark gray on white, or white on coloured tiles)."""
    body, size, cols = "", 48, 6
    gap_x, gap_y = (w - cols * size) / (cols + 1), (h - 2 * size) / 3
    for k, name in enumerate(ICONS[:2 * cols]):
        x, y = gap_x + (k % cols) * (size + gap_x), gap_y + (k // cols) * (size + gap_y)
        inner = icon_body(name)
        if colour:
            body += '<rect x="%s" y="%s" width="%d" height="%d" rx="10" fill="%s"/>\n' % (f(x - 8), f(y - 8), size + 16, size + 16, PALETTE[k % len(PALETTE)])
            inner = re.sub(r'fill="#[0-9a-fA-F]{3,6}"', 'fill="#ffffff"', inner)
        else:
            inner = re.sub(r'fill="#[0-9a-fA-F]{3,6}"', 'fill="#303030"', inner)
        body += '<g transform="translate(%s %s) scale(%s)">%s</g>\n' % (f(x), f(y), f(size / 16.0), inner)
    return svg(w, h, body, "#ffffff" if not colour else "#eeeeee")


def read_pnm(path):
    """A binary PGM (P5) or PPM (P6) with maxval <= 255: (width, height, channels, bytes)."""
    try:
        with open(path, "rb") as fh:
            data = fh.read()
    except OSError as e:
        fail("%s: %s" % (path, e.strerror))
    tokens, pos = [], 0
    while len(tokens) < 4:
        m = re.compile(rb"\s*(#[^\n]*\n\s*)*(\S+)").match(data, pos)
        if not m:
            fail("%s: not a PNM file" % path)
        tokens.append(m.group(2))
        pos = m.end()
    magic, w, h, maxval = tokens[0], int(tokens[1]), int(tokens[2]), int(tokens[3])
    if magic not in (b"P5", b"P6") or maxval > 255:
        fail("%s: only 8-bit P5/P6 is read here" % path)
    c = 1 if magic == b"P5" else 3
    return w, h, c, data[pos + 1:pos + 1 + w * h * c]


def png_data_uri(w, h, c, pixels):
    """pixels (rows of w*c bytes) as a PNG data URI: what rsvg-convert draws 1:1 as <image>."""
    raw = b"".join(b"\0" + pixels[y * w * c:(y + 1) * w * c] for y in range(h))

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xffffffff)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 0 if c == 1 else 2, 0, 0, 0)) + \
        chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    return "data:image/png;base64," + base64.b64encode(png).decode("ascii")


def crop(path, x, y, w, h):
    iw, ih, c, px = read_pnm(path)
    if x + w > iw or y + h > ih:
        fail("%s: %d x %d is smaller than the crop" % (path, iw, ih))
    rows = b"".join(px[((y + r) * iw + x) * c:((y + r) * iw + x + w) * c] for r in range(h))
    return png_data_uri(w, h, c, rows)


def mixed_half(w, h, images):
    """Left half a photo (peppers), right half a bar chart: gray."""
    uri = crop(os.path.join(images, "peppers.pgm"), 128, 64, w // 2, h)
    chart = bar_chart(w // 2, h)
    inner = re.search(r"<svg[^>]*>(.*)</svg>", chart, re.S).group(1)
    inner = "\n".join(re.sub(r'fill="(#[0-9a-f]{6})"', lambda m: 'fill="%s"' % to_gray(m.group(1)), l) for l in inner.split("\n"))
    body = '<image x="0" y="0" width="%d" height="%d" href="%s"/>\n' % (w // 2, h, uri)
    body += '<g transform="translate(%d 0)">%s</g>\n' % (w // 2, inner)
    return svg(w, h, body)


def to_gray(hexcolour):
    r, g, b = (int(hexcolour[k:k + 2], 16) for k in (1, 3, 5))
    return gray(int(0.299 * r + 0.587 * g + 0.114 * b + 0.5))


def mixed_text(w, h, images):
    """A caption bar, a title and a small logo over a colour photo (kodim03)."""
    uri = crop(os.path.join(images, "color", "kodim03.ppm"), 128, 64, w, h)
    body = '<image x="0" y="0" width="%d" height="%d" href="%s"/>\n' % (w, h, uri)
    body += text(200, 40, "Summer hats", 34, weight="bold", fill="#ffffff")
    body += text(200, 64, "A photo with text and a logo over it", 15, fill="#ffff66")
    body += '<rect x="0" y="%d" width="%d" height="44" fill="#000000" fill-opacity="0.6"/>\n' % (h - 44, w)
    body += text(12, h - 16, "erd mesh test: photo 60%, graphics 40% - DejaVu Sans 16 px", 16, fill="#ffffff")
    body += '<circle cx="%d" cy="50" r="30" fill="#d62728" stroke="#ffffff" stroke-width="3"/>\n' % (w - 50)
    body += text(w - 50, 58, "erd", 22, weight="bold", fill="#ffffff", anchor="middle")
    return svg(w, h, body)


DRAWINGS = {
    "shapes-gray": lambda: shapes(512, 384, 14, 1, False),
    "shapes-colour": lambda: shapes(512, 384, 14, 2, True),
    "bar-chart": lambda: bar_chart(512, 384),
    "pie-chart": lambda: pie_chart(512, 384),
    "line-chart": lambda: line_chart(512, 384),
    "flag-stripes": lambda: flag_stripes(494, 260),
    "flag-disc": lambda: flag_disc(480, 288),
    "flag-cross": lambda: flag_cross(480, 320),
    "flag-chevron": lambda: flag_chevron(480, 320),
    "text-gray": lambda: text_gray(512, 384),
    "text-colour": lambda: text_colour(512, 384),
    "logo": lambda: logo(512, 256),
    "icons-gray": lambda: icons(448, 160, False),
    "icons-colour": lambda: icons(448, 160, True),
}
MIXED = {
    "mixed-half": mixed_half,
    "mixed-text": mixed_text,
}


def main(argv):
    if len(argv) < 2:
        fail("usage: graphics_svg.py OUT_DIR [IMAGES_DIR]")
    out = argv[1]
    os.makedirs(out, exist_ok=True)
    items = [(name, make) for name, make in DRAWINGS.items()]
    if len(argv) > 2:
        items += [(name, (lambda m: lambda: m(512, 384, argv[2]))(make)) for name, make in MIXED.items()]
    for name, make in items:
        with open(os.path.join(out, name + ".svg"), "w", encoding="utf-8") as fh:
            fh.write(make())
        print(name)


if __name__ == "__main__":
    main(sys.argv)
