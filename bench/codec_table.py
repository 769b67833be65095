#!/usr/bin/env python3
# The codec table of docs/RESULTS.md from bench/codec.sh's rd.tsv and rows.tsv: per erd row its
# PSNR, bpp and bpp per section, and each other codec's bpp at the same PSNR, interpolated
# linearly in (PSNR, log bpp) between the sweep points around it.
import json
import sys

from codec_curve import at_psnr

rd_path, rows_path = sys.argv[1], sys.argv[2]
curves = {}
settings = {}  # (img, codec) -> [(bpp, psnr, setting)]
for line in open(rd_path).read().splitlines()[1:]:
    img, codec, setting, bpp, psnr = line.split('\t')
    curves.setdefault((img, codec), []).append((float(bpp), float(psnr)))
    settings.setdefault((img, codec), []).append((float(bpp), float(psnr), setting))


summary = []  # (img, d, method, psnr, erd's best bpp, {codec: bpp or None})
print('| image | density | method | step | PSNR (dB) | erd bpp | positions / edges / flips / values | erd\'s search at that PSNR | erd envelope | cheapest erd point at that PSNR | JPEG | JPEG 2000 | WebP |')
print('| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |')
for line in open(rows_path).read().splitlines():
    img, d, method, psnr, js, chosen = (line.split('\t') + ['-'])[:6]
    j = json.load(open(js))
    px = j['width'] * j['height']
    psnr = float(psnr)
    erd_bpp = j['bpp']
    cells = []
    others = {}
    for codec in ('jpeg', 'jpeg2000', 'webp'):
        text, b = at_psnr(curves.get((img, codec), [(1, 0)]), psnr)
        # '<x': the codec's cheapest setting already beats the PSNR, at x bpp (erd must beat x);
        # '>x': its best does not reach it (no comparison).
        others[codec] = b if text[0] not in '<>' else (float(text[1:]) if text[0] == '<' else None)
        # Percent only where interpolated; '<x' / '>x' are bounds.
        mark = ' (erd %+.0f%%)' % (100.0 * (erd_bpp - b) / b) if b is not None and text[0] not in '<>' else ''
        cells.append(text + mark)
    sections = '%.4f / %.4f / %.4f / %.4f' % (j['position_bits'] / px, j['edge_bits'] / px, j.get('flip_bits', 0) / px,
                                              j['value_bits'] / px)
    # The cheapest erd point at this PSNR over every method, density and step (the point count
    # traded against the step).
    every = [p for (i, c), pts in curves.items() if i == img and c.startswith('erd') for p in pts]
    envelope, envelope_bpp = at_psnr(every, psnr)
    best = min(erd_bpp, envelope_bpp) if envelope_bpp is not None and envelope[0] not in '<>' else erd_bpp
    # erd's own search at this PSNR (--step-psnr P --choose-density): its file, measured; it
    # reaches P up to the last digit erd psnr prints.
    search = '-'
    if chosen != '-':
        setting, cbpp, cpsnr = chosen.split(':')
        search = '%.4f (%s, %.2f dB)' % (float(cbpp), setting, float(cpsnr))
        if float(cpsnr) >= psnr - 1e-9:
            best = min(best, float(cbpp))
    summary.append((img, d, method, psnr, best, others))
    # The point count traded against the step: the cheapest measured erd point (method, density,
    # step) that reaches this PSNR, not interpolated.
    reach = sorted((b, c, s) for (i, c), pts in settings.items() if i == img and c.startswith('erd')
                   for b, p, s in pts if p >= psnr - 1e-9)
    name = lambda c: 'ERDGPI search' if c == 'erd-choose' else c[4:].upper()
    cheapest = '%.4f (%s %s)' % (reach[0][0], name(reach[0][1]), reach[0][2]) if reach else '-'
    print('| %s | %s%% | %s | %g | %.2f | %.4f | %s | %s | %s | %s | %s |' % (img, d, method.upper(), j['step'], psnr, erd_bpp, sections,
                                                                           search, envelope, cheapest, ' | '.join(cells)))

# The targets, on erd's best bpp at each row's PSNR (the row's file, erd's search or the
# envelope, whichever is cheapest): below JPEG up to 30 dB on the photos and up to 40 dB on bull, below
# JPEG 2000 on bull at every PSNR. Where a codec's cheapest setting already beats the PSNR ("<x")
# erd must be below that setting's x bpp.
def verdict(name, rows, codec):
    missed = ['%s %s%% %s %.2f dB: %.4f against %s' % (i, d, m.upper(), p, b, '%.4f' % o[codec])
              for i, d, m, p, b, o in rows if o[codec] is not None and b >= o[codec]]
    print('- %s: %d of %d rows met%s' % (name, len(rows) - len(missed), len(rows), ('; missed: ' + '; '.join(missed)) if missed else ''))


print()
print('Targets (erd\'s best bpp at the row\'s PSNR: the row, erd\'s search or the envelope):')
verdict('smaller than JPEG up to 30 dB (photos) and 40 dB (bull)',
        [r for r in summary if r[3] <= (40.0 if r[0] == 'bull' else 30.0)], 'jpeg')
verdict('smaller than JPEG 2000 on bull', [r for r in summary if r[0] == 'bull'], 'jpeg2000')
