#!/usr/bin/env bash
# The layer rule (docs/architecture.md), checked on every #include of the library:
#
#   kernel/              kernel/
#   algorithms/imaging/  kernel/, imaging/
#   algorithms/model/    kernel/, imaging/, model/
#   algorithms/methods/  kernel/, imaging/, model/, methods/ -- and no method (ed, gpi, erded,
#                        erdgpi) includes another method's header: what two methods share lives in
#                        a file of its own
#   algorithms/output/   kernel/, imaging/, model/, output/
#   algorithms/codec/    kernel/, imaging/, model/, codec/
#   api/                 kernel/, algorithms/, api/
#   imageio/             kernel/, algorithms/imaging/, imageio/, third_party/stb_glue.h, <zlib.h>, <tiffio.h>
#
# so nothing in kernel/, algorithms/ or api/ includes imageio/, cli/, third_party/ or tests/, and
# their <...> includes are C++ standard headers only (a name without '.' or '/': no <stb/...>,
# <unistd.h>, <malloc.h>); imageio/ (the optional image-I/O library) adds stb through its glue,
# zlib and libtiff, nothing else. No source of the program (those folders and cli/) includes an iostream
# header (<iostream>, <fstream>, <sstream>, <istream>, <ostream>, <iomanip>, <locale>): they link
# libstdc++'s locale machinery into the static binary, 0.8 MB of code and 0.64 MB more memory in
# every run (docs/DECISIONS.md "Memory"). Prints one line per broken include and exits 1 when
# there is one.
# Usage: tools/check_layers.sh [ROOT]   (default: the repository holding this script)
set -u
root=${1:-$(dirname "$0")/..}
cd "$root" || exit 2

allowed() {  # the include prefixes a folder may use
    case $1 in
        kernel) echo "kernel/" ;;
        algorithms/imaging) echo "kernel/ algorithms/imaging/" ;;
        algorithms/model) echo "kernel/ algorithms/imaging/ algorithms/model/" ;;
        algorithms/methods) echo "kernel/ algorithms/imaging/ algorithms/model/ algorithms/methods/" ;;
        algorithms/output) echo "kernel/ algorithms/imaging/ algorithms/model/ algorithms/output/" ;;
        algorithms/codec) echo "kernel/ algorithms/imaging/ algorithms/model/ algorithms/codec/" ;;
        api) echo "kernel/ algorithms/ api/" ;;
        imageio) echo "kernel/ algorithms/imaging/ imageio/ third_party/stb_glue.h" ;;
        *) echo "" ;;  # a folder without a rule: every include of it is reported
    esac
}
methods="ed gpi erded erdgpi"

bad=0
files=0
report() { echo "$1"; bad=$((bad + 1)); }
while IFS= read -r f; do
    files=$((files + 1))
    dir=${f%/*}
    ok=$(allowed "$dir")
    base=${f##*/}
    base=${base%.*}
    while IFS= read -r hit; do
        line=${hit%%:*}
        inc=${hit#*:}
        if [[ $inc =~ ^[[:space:]]*#[[:space:]]*include[[:space:]]*\<([^>]*)\> ]]; then
            name=${BASH_REMATCH[1]}
            [[ $dir == imageio && ( $name == zlib.h || $name == tiffio.h ) ]] && continue
            [[ $name == *.* || $name == */* ]] &&
                report "$f:$line: includes <$name>: the library uses the C++ standard library only"
            continue
        fi
        [[ $inc =~ ^[[:space:]]*#[[:space:]]*include[[:space:]]*\"([^\"]*)\" ]] || continue
        name=${BASH_REMATCH[1]}
        pass=0
        for p in $ok; do [[ $name == "$p"* ]] && pass=1; done
        if [[ $pass -eq 0 ]]; then
            report "$f:$line: includes \"$name\": $dir/ may include only ${ok:-nothing (no rule for $dir/)}"
            continue
        fi
        if [[ $dir == algorithms/methods && " $methods " == *" $base "* ]]; then
            for m in $methods; do
                [[ $m != "$base" && $name == "algorithms/methods/$m.h" ]] &&
                    report "$f:$line: includes \"$name\": a method does not include another method's header"
            done
        fi
    done < <(grep -n '^[[:space:]]*#[[:space:]]*include' "$f")
done < <(find kernel algorithms api imageio -name '*.h' -o -name '*.cpp' | sort)

while IFS= read -r hit; do
    report "${hit%%:*}:$(cut -d: -f2 <<<"$hit"): includes an iostream header: C stdio (<cstdio>) instead"
done < <(find kernel algorithms api imageio cli -name '*.h' -o -name '*.cpp' | sort |
         xargs grep -nE '^[[:space:]]*#[[:space:]]*include[[:space:]]*<(iostream|fstream|sstream|istream|ostream|iomanip|locale)>' /dev/null)

if [[ $files -eq 0 ]]; then echo "check_layers: no sources under $PWD"; exit 2; fi
if [[ $bad -gt 0 ]]; then echo "check_layers: $bad includes break the layer rule ($files files)"; exit 1; fi
echo "check_layers: $files files, every include within its layer"
