#!/usr/bin/env bash
# `make run`: mesh one image with the best method this build has, reconstruct it, print the PSNR.
# Usage: tools/run.sh ERD_BINARY IMAGES_DIR      (files are left under out/)
#
# The image is IMAGES_DIR/peppers.pgm when it exists, else a hard-edged cartoon made by `erd synth`
# (where explicit edges matter most); an ERD method's PSNR is shown beside GPI's. Methods are
# tried best first (erdgpi, erded, gpi, ed); the first that succeeds is used. DENSITY (percent of
# the pixels that become vertices, default 2) and METHODS (space separated) override the defaults.
set -u
ERD=${1:-build/erd}
IMAGES=${2:-../shared/images}
DENSITY=${DENSITY:-2}
METHODS=${METHODS:-erdgpi erded gpi ed}
OUT=out
# Paths given relative to the caller's folder stay valid after the cd to the repository.
[[ $ERD == */* && $ERD != /* ]] && ERD=$PWD/$ERD
[[ $IMAGES != /* ]] && IMAGES=$PWD/$IMAGES
cd "$(dirname "$0")/.."
mkdir -p "$OUT"

say() { printf '%s\n' "$*"; }

if [[ ! -x $ERD ]]; then say "run: $ERD is not built (try: make)"; exit 1; fi

if [[ -f $IMAGES/peppers.pgm ]]; then
    img=$IMAGES/peppers.pgm
    name=peppers
    say "image:   $img ($("$ERD" info --json "$img" | sed -n 's/.*"width":\([0-9]*\),"height":\([0-9]*\),"maxval":\([0-9]*\).*/\1 x \2, maxval \3/p'))"
else
    # A hard-edged picture: flat regions whose edges are steps between two pixels, where ERD's
    # explicit discontinuities matter most (docs/manual.md "Which method when").
    img=$OUT/cartoon.pgm
    name=cartoon
    say "image:   $IMAGES/peppers.pgm not found; synthesising one: $ERD synth --kind cartoon -W 256 -H 256 -o $img"
    "$ERD" synth -q --kind cartoon -W 256 -H 256 -o "$img" || { say "run: erd synth failed"; exit 1; }
fi

used=""
for m in $METHODS; do
    case $m in erded|erdgpi) ext=erd ;; *) ext=model ;; esac
    mesh=$OUT/$name.$m.$ext
    say "mesh:    $ERD generate --method $m -i $img -d $DENSITY -o $mesh"
    start=$(date +%s.%N)
    "$ERD" generate --method "$m" -i "$img" -d "$DENSITY" -o "$mesh" 2>"$OUT/generate.$m.log"
    rc=$?
    end=$(date +%s.%N)
    if [[ $rc -eq 0 || ( $rc -eq 3 && -s $mesh ) ]]; then
        [[ $rc -eq 3 ]] && say "         (exit 3: the exact point count was not reached; see $OUT/generate.$m.log)"
        say "         done in $(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }') s"
        used=$m
        break
    fi
    say "         method $m failed (exit $rc): $(head -1 "$OUT/generate.$m.log")"
done
if [[ -z $used ]]; then
    say "run: no mesh method worked in this build (tried: $METHODS)"
    exit 1
fi

approx=$OUT/$name.$used.pgm
say "rebuild: $ERD reconstruct $mesh -o $approx"
if ! "$ERD" reconstruct "$mesh" -o "$approx" 2>"$OUT/reconstruct.log"; then
    say "run: reconstruct failed: $(head -1 "$OUT/reconstruct.log")"
    exit 1
fi
psnr=$("$ERD" psnr "$img" "$approx") || { say "run: psnr failed"; exit 1; }
say "psnr:    $ERD psnr $img $approx"
# The same N with GPI (no edges), so the run shows what the edges are worth.
versus=""
if [[ $used == erdgpi || $used == erded ]] &&
    "$ERD" generate -q -m gpi -i "$img" -d "$DENSITY" -o "$OUT/$name.gpi.model" --psnr-report 2>"$OUT/generate.gpi.log"; then
    versus=$(sed -n 's/^erd generate: psnr: //p' "$OUT/generate.gpi.log")
fi
say ""
say "$name, method $used, density $DENSITY%: PSNR $psnr dB"
if [[ -n $versus ]]; then
    say "         gpi at the same density (no edges): $versus"
    if [[ $name == cartoon ]]; then
        say "         why: the cartoon's edges are steps between two pixels; $used keeps each as a"
        say "         discontinuity (two values on its sides), gpi must pile vertices along both sides."
    else
        say "         why: $used places vertices on the image's edges and keeps a discontinuity there."
    fi
fi
files="$mesh $approx"
[[ $name == cartoon ]] && files="$img $files"
say "files:   $files (logs: $OUT/generate.$used.log, $OUT/reconstruct.log)"
