#!/usr/bin/env bash
# Writes the seed corpus of fuzz_jpeg (committed; rerun to regenerate). Needs ImageMagick's
# convert (JPEG encoding is not erd's); the hostile seeds are cut or patched from the good ones.
# Usage: bash fuzz/make_jpeg_seeds.sh   (from the repository root)
set -eu
D=fuzz/corpus/fuzz_jpeg
mkdir -p "$D"
strip=(-strip -define jpeg:optimize-coding=false)
convert -size 8x8 gradient:black-white -colorspace Gray "${strip[@]}" "$D/gray_8x8.jpg"
convert -size 16x8 gradient:red-blue "${strip[@]}" -sampling-factor 2x2 "$D/rgb_16x8_420.jpg"
convert -size 12x10 plasma:fractal -seed 1 "${strip[@]}" -sampling-factor 1x1 "$D/rgb_12x10_444.jpg" 2>/dev/null ||
    convert -size 12x10 gradient:green-yellow "${strip[@]}" -sampling-factor 1x1 "$D/rgb_12x10_444.jpg"
convert -size 1x7 gradient:red-blue "${strip[@]}" -interlace JPEG "$D/progressive_1x7.jpg"
convert -size 9x1 gradient:black-white "${strip[@]}" "$D/gray_9x1.jpg"
convert -size 8x8 xc:gray50 "${strip[@]}" -type TrueColor "$D/rgb_equal_8x8.jpg"
convert -size 8x8 xc:red -colorspace CMYK "${strip[@]}" "$D/cmyk_8x8.jpg"
# Hostile: cut in the middle of the image data; progressive with a 16000 x 16000 frame header.
f=$D/rgb_16x8_420.jpg
head -c $(($(stat -c %s "$f") - 20)) "$f" > "$D/truncated.jpg"
python3 - "$D/progressive_1x7.jpg" "$D/progressive_huge.jpg" <<'PY'
import sys
b = bytearray(open(sys.argv[1], "rb").read())
i = b.find(b"\xff\xc2")
b[i + 5:i + 9] = (16000).to_bytes(2, "big") + (16000).to_bytes(2, "big")
open(sys.argv[2], "wb").write(b)
PY
