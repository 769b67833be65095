#!/usr/bin/env bash
# The map of record (docs/architecture.md, "Layers and rooms"): every source file under the
# repository's source folders (kernel/ algorithms/ api/ imageio/ cli/ python/ web/ tests/ fuzz/
# bench/ tools/ third_party/) lies in a room of the room table (the longest room path that holds
# it) and is named in that room's row: by its name (cdt_locate.cpp), its stem (canny_pass, for a
# .h/.cpp pair), its path inside the room (src/arrays) or a pattern with * (test_*.cpp). Source
# files: .h .cpp .py .pyi .sh .js .mjs .html; build output, node_modules, caches and seed corpora
# are not sources. Prints one line per file the table does not name, and exits 1 when there is one.
# Usage: tools/check_map.sh [ROOT] [MAP]   (default: the repository holding this script, its map)
set -u
root=${1:-$(dirname "$0")/..}
cd "$root" || exit 2
map=${2:-docs/architecture.md}
[[ -f $map ]] || { echo "check_map: no $map"; exit 2; }
folders="kernel algorithms api imageio cli python web tests fuzz bench tools third_party docs"

# The room table's rows: "| room/ | holds | may include |".
declare -A holds
while IFS= read -r line; do
    [[ $line =~ ^\|\ +([a-z_]+(/[a-z_]+)*/)\ +\|(.*)$ ]] || continue
    holds[${BASH_REMATCH[1]}]=${BASH_REMATCH[3]}
done < "$map"
if [[ ${#holds[@]} -eq 0 ]]; then echo "check_map: no room table in $map"; exit 2; fi

# The words of a row: names, stems, paths and patterns, without the punctuation around them.
declare -A words
for room in "${!holds[@]}"; do
    w=$(tr -c 'A-Za-z0-9_.*/\n-' ' ' <<<"${holds[$room]}")
    words[$room]=" $(for t in $w; do t=${t%.}; printf '%s ' "$t"; done)"
done

named() {  # named ROOM REL: is the file ROOM/REL named in ROOM's row?
    local room=$1 rel=$2 base stem t
    base=${rel##*/}
    stem=${base%.*}
    for t in ${words[$room]}; do
        [[ $t == "$base" || $t == "$stem" || $t == "$rel" || $t == "${rel%.*}" ]] && return 0
        if [[ $t == *'*'* ]]; then
            # shellcheck disable=SC2053  # the row's pattern is meant as a glob
            [[ $base == $t || $rel == $t ]] && return 0
        fi
    done
    return 1
}

bad=0
files=0
while IFS= read -r f; do
    files=$((files + 1))
    room=""
    for r in "${!holds[@]}"; do
        [[ $f == "$r"* && ${#r} -gt ${#room} ]] && room=$r
    done
    if [[ -z $room ]]; then
        echo "$f: in no room of $map (add a row for ${f%/*}/)"; bad=$((bad + 1)); continue
    fi
    named "$room" "${f#"$room"}" || { echo "$f: not named in the $room row of $map"; bad=$((bad + 1)); }
done < <(find $folders -type d \( -name node_modules -o -name build -o -name __pycache__ -o -name corpus \
             -o -name '*.egg-info' -o -name .pytest_cache \) -prune -o -type f \
             \( -name '*.h' -o -name '*.cpp' -o -name '*.py' -o -name '*.pyi' -o -name '*.sh' -o -name '*.js' \
             -o -name '*.mjs' -o -name '*.html' \) -print 2>/dev/null | sort)

if [[ $files -eq 0 ]]; then echo "check_map: no sources under $PWD"; exit 2; fi
if [[ $bad -gt 0 ]]; then echo "check_map: $bad of $files files missing from the room table of $map"; exit 1; fi
echo "check_map: $files files, each named in its room's row of $map"
