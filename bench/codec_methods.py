#!/usr/bin/env python3
"""Two erd methods as codecs, file size at equal PSNR (issue 45: better meshes should be smaller
.erdz files). Reads bench/codec.sh's rd.tsv and rows.tsv, run with METHODS="A B": for each row of
method A (its coarsest step within 0.25 dB of step 1), the bpp of A and of B at that row's PSNR,
each read off its own envelope over every density and step of the image (the cheapest point that
reaches a PSNR; between two envelope points, linear in (PSNR, log bpp)). Prints a Markdown table.
Usage: codec_methods.py RD_TSV ROWS_TSV A B"""
import collections
import csv
import sys

from codec_curve import at_psnr


def main():
    rd_path, rows_path, a, b = sys.argv[1:5]
    points = collections.defaultdict(list)
    for r in csv.DictReader(open(rd_path), delimiter='\t'):
        if r['codec'] in ('erd-' + a, 'erd-' + b):
            points[(r['image'], r['codec'][4:])].append((float(r['bpp']), float(r['psnr'])))
    print(f'| image | density | {a} row PSNR (dB) | {a} bpp | {b} bpp at that PSNR | {b} - {a} |')
    print('| --- | ---: | ---: | ---: | ---: | ---: |')
    changes = []
    for line in open(rows_path):
        img, density, method, psnr = line.split('\t')[:4]
        if method != a:
            continue
        target = float(psnr)
        ba = at_psnr(points[(img, a)], target)[1]
        bb = at_psnr(points[(img, b)], target)[1]
        if ba is None or bb is None:
            print(f'| {img} | {density}% | {target:.2f} | - | - | (not reached) |')
            continue
        changes.append(bb / ba - 1)
        print(f'| {img} | {density}% | {target:.2f} | {ba:.4f} | {bb:.4f} | {100 * (bb / ba - 1):+.1f}% |')
    if changes:
        changes.sort()
        print(f'\n{b} against {a}: median {100 * changes[len(changes) // 2]:+.1f}% bpp, '
              f'{100 * changes[0]:+.1f}% .. {100 * changes[-1]:+.1f}%, smaller in {sum(c < 0 for c in changes)} of {len(changes)} cases.')


main()
