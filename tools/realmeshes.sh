#!/usr/bin/env bash
# `make realmeshes`: every method (fits at degrees 2-4; the degree-free operators once; 2 threads) on the sample meshes Debian's CGAL
# ships (package libcgal-demo, data/meshes/ of /usr/share/doc/libcgal-dev/data.tar.gz), and
# results/REAL_MESHES.md (tools/realmeshes_report.py) with PNGs of H on two meshes in
# results/realmeshes/ (tools/render_ply.py, gnuplot). The package is fetched at run time with
# `apt-get download` (needs the Debian archive; `apt-get update` as root if the package lists are
# missing) into $WORK (default build/realmeshes/, ignored); nothing is committed.
# CORPUS=all (`make realmeshes CORPUS=all`): instead, every method at its default (the names of
# `curvbench methods`; fits at their default degree) with 2 threads on every file of data.tar.gz
# that curvbench reads (.off .obj .ply .xyz .pts .pwn), each run under `timeout $CORPUS_TIMEOUT`
# (default 300 s); a point set (a .xyz/.pts/.pwn file, or one `curvbench info` reports 0 faces
# of) with the point-set methods instead (`curvbench methods --point-sets`, each at its defaults),
# and tools/realmeshes_corpus.py writes the summary (files, refusals, crashes, time-outs, failed
# vertices by method and cause, the point sets' table) as the section between
# `<!-- corpus: begin -->` and `<!-- corpus: end -->` of $CORPUS_REPORT (default
# results/REAL_MESHES.md; the rest of the file is left alone, and the default run keeps that
# section). Other variables: CORPUS_METHODS (default: the first column of `curvbench methods`;
# set it for a binary without that subcommand), CORPUS_POINT_METHODS (default: `curvbench methods
# --point-sets`), CORPUS_RUNS (logs and exit codes; default $WORK/corpus).
# Usage: [CORPUS=all] tools/realmeshes.sh BUILD_DIR
set -euo pipefail
BUILD=${1:-build}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
WORK=${WORK:-$BUILD/realmeshes}
MESHES=${MESHES:-"bunny00 armadillo refined_elephant fandisk_large ChineseDragon-10kv cheese blade man bear"}
CB="$BUILD/curvbench"
CORPUS=${CORPUS:-}
case "$CORPUS" in
  "" | all) ;;
  *) echo "realmeshes: CORPUS must be empty (the sample meshes) or 'all' (every mesh file)" >&2; exit 2 ;;
esac
REF=${REF:-lhf-4}  # the reference of the agreement columns and of the pictures
mkdir -p "$WORK"
DATA="$WORK/data/meshes"
TARBALL="$WORK/pkg/usr/share/doc/libcgal-dev/data.tar.gz"
# fetch MEMBER: extracts MEMBER (data/meshes, or data: everything) of the package's data.tar.gz
# into $WORK, downloading and unpacking the package first unless that was done.
fetch() {
  if [ ! -f "$TARBALL" ]; then
    if ! ls "$WORK"/libcgal-demo_*.deb >/dev/null 2>&1; then
      echo "realmeshes: fetching libcgal-demo (apt-get download) into $WORK" >&2
      ( cd "$WORK" && (apt-get download libcgal-demo >/dev/null 2>&1 ||
          { [ "$(id -u)" = 0 ] && apt-get update >/dev/null && apt-get download libcgal-demo; } ||
          { echo "realmeshes: cannot download libcgal-demo (run 'apt-get update' as root?)" >&2; exit 2; }) )
    fi
    deb=$(ls "$WORK"/libcgal-demo_*.deb | head -1)
    dpkg-deb -x "$deb" "$WORK/pkg"
  fi
  tar -xzf "$TARBALL" -C "$WORK" "$1"
}

if [ "$CORPUS" = all ]; then
  # Every file of data.tar.gz (meshes/, points_3/, images/); the stamp marks a complete extraction.
  [ -f "$WORK/.data-all" ] || { fetch data && touch "$WORK/.data-all"; }
  TIMEOUT=${CORPUS_TIMEOUT:-300}
  RUNS=${CORPUS_RUNS:-$WORK/corpus}
  REPORT=${CORPUS_REPORT:-$ROOT/results/REAL_MESHES.md}
  # The method names: the lines of `curvbench methods` whose second column is a degree range or -.
  CMETHODS=${CORPUS_METHODS:-$("$CB" methods | awk '$2 ~ /^([0-9]+\.\.[0-9]+|-)$/ { print $1 }' | tr '\n' ' ')}
  [ -n "${CMETHODS// /}" ] || { echo "realmeshes: no methods (set CORPUS_METHODS)" >&2; exit 2; }
  PMETHODS=${CORPUS_POINT_METHODS:-$("$CB" methods --point-sets | tr '\n' ' ')}
  [ -n "${PMETHODS// /}" ] || { echo "realmeshes: no point-set methods (set CORPUS_POINT_METHODS)" >&2; exit 2; }
  CBABS="$(cd "$(dirname "$CB")" && pwd)/$(basename "$CB")"
  DATAALL="$(cd "$WORK/data" && pwd)"
  mkdir -p "$RUNS"
  RUNS="$(cd "$RUNS" && pwd)"
  rm -rf -- "$RUNS/runs"
  # run OUT CMD...: CMD in data/ (so messages name files as data/-relative paths) under the time
  # limit; stdout to OUT.txt, stderr to OUT.log, "exit-code seconds" to OUT.rc (124: timed out;
  # 128+n: signal n; seconds to the millisecond).
  run() {
    local out=$1 t0 rc=0
    shift
    t0=$(date +%s%N)
    ( cd "$DATAALL" && exec timeout -k 10 "$TIMEOUT" "$@" ) > "$out.txt" 2> "$out.log" || rc=$?
    local ms=$(( ($(date +%s%N) - t0) / 1000000 ))
    printf '%d %d.%03d\n' "$rc" $(( ms / 1000 )) $(( ms % 1000 )) > "$out.rc"
    [ -s "$out.txt" ] || rm -f "$out.txt"
  }
  mapfile -t FILES < <(cd "$DATAALL" && find . -type f \( -iname '*.off' -o -iname '*.obj' -o -iname '*.ply' \
    -o -iname '*.xyz' -o -iname '*.pts' -o -iname '*.pwn' \) | sed 's|^\./||' | LC_ALL=C sort)
  start=$(date +%s)
  i=0
  for f in "${FILES[@]}"; do
    i=$(( i + 1 ))
    echo "realmeshes: corpus $i/${#FILES[@]} $f" >&2
    d="$RUNS/runs/$f"
    mkdir -p "$d"
    run "$d/info" "$CBABS" info "$f"
    # A point set (the rule of realmeshes_corpus.py's is_point_set): a point file, or 0 faces.
    methods=$CMETHODS
    case "${f,,}" in
      *.xyz | *.pts | *.pwn) methods=$PMETHODS ;;
      *) ! grep -Eq '^faces: +0$' "$d/info.txt" 2>/dev/null || methods=$PMETHODS ;;
    esac
    for method in $methods; do
      run "$d/$method" "$CBABS" estimate "$f" --method "$method" --threads 2 --output "$RUNS/out.csv"
      rm -f "$RUNS/out.csv"
    done
  done
  echo "realmeshes: corpus of ${#FILES[@]} files run in $(( $(date +%s) - start )) s" >&2
  # shellcheck disable=SC2086
  /usr/bin/python3 "$ROOT/tools/realmeshes_corpus.py" "$DATAALL" "$RUNS/runs" "$REPORT" \
    --methods $CMETHODS --point-methods $PMETHODS --timeout "$TIMEOUT" --binary "$("$CB" --version 2>/dev/null || echo "$CB")"
  echo "realmeshes: wrote the corpus section of $REPORT" >&2
  exit 0
fi

# Every registered method: the fits at degrees 2-4, the degree-free operators once.
METHODS=${METHODS:-$("$CB" methods --labels 2-4 | tr '\n' ' ')}
[ -d "$DATA" ] || fetch data/meshes
start=$(date +%s)
for m in $MESHES; do
  mesh="$DATA/$m.off"
  [ -f "$mesh" ] || { echo "realmeshes: $mesh missing" >&2; exit 2; }
  "$CB" info "$mesh" > "$WORK/$m.info"
  for method in $METHODS; do
    echo "realmeshes: $m $method" >&2
    "$CB" estimate "$mesh" --method "$method" --threads 2 --output "$WORK/$m.$method.csv" \
      2> "$WORK/$m.$method.log"
  done
done
echo "realmeshes: estimates done in $(( $(date +%s) - start )) s" >&2
mkdir -p "$ROOT/results/realmeshes"
# Pictures: H of the reference method as a coloured PLY (kept in $WORK: several MB) and a PNG of
# it in results/realmeshes/ (tools/render_ply.py, gnuplot's pngcairo; headless).
# Each entry: mesh:up axis:azimuth:elevation.
RENDER=${RENDER:-"bunny00:y:180:10 fandisk_large:z:215:-30"}
for r in $RENDER; do
  IFS=: read -r m up az el <<< "$r"
  case " $MESHES " in *" $m "*) ;; *) continue ;; esac
  echo "realmeshes: picture of $m" >&2
  "$CB" estimate "$DATA/$m.off" --method "$REF" --color H --threads 2 --output "$WORK/$m.H.ply" \
    2> "$WORK/$m.H.ply.log"
  /usr/bin/python3 "$ROOT/tools/render_ply.py" "$WORK/$m.H.ply" \
    "$ROOT/results/realmeshes/$m.H.png" \
    --up "$up" --azimuth "$az" --elevation "$el" --title "$m: mean curvature H (${REF^^})"
done
# The section of CORPUS=all (between its marker lines) survives the rewrite of the report.
keep=$(mktemp)
[ ! -f "$ROOT/results/REAL_MESHES.md" ] ||
  sed -n '/^<!-- corpus: begin -->$/,/^<!-- corpus: end -->$/p' "$ROOT/results/REAL_MESHES.md" > "$keep"
/usr/bin/python3 "$ROOT/tools/realmeshes_report.py" "$WORK" "$ROOT/results/REAL_MESHES.md" \
  --meshes $MESHES --methods $METHODS --reference "$REF"
[ ! -s "$keep" ] || { echo; cat "$keep"; } >> "$ROOT/results/REAL_MESHES.md"
rm -f "$keep"
echo "realmeshes: wrote results/REAL_MESHES.md" >&2
