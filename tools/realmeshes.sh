#!/usr/bin/env bash
# `make realmeshes`: every method (fits at degrees 2-4; the degree-free operators once; 2 threads) on the sample meshes Debian's CGAL
# ships (package libcgal-demo, data/meshes/ of /usr/share/doc/libcgal-dev/data.tar.gz), and
# results/REAL_MESHES.md (tools/realmeshes_report.py) with PNGs of H on two meshes in
# results/realmeshes/ (tools/render_ply.py, gnuplot). The package is fetched at run time with
# `apt-get download` (needs the Debian archive; `apt-get update` as root if the package lists are
# missing) into $WORK (default build/realmeshes/, ignored); nothing is committed.
# Usage: tools/realmeshes.sh BUILD_DIR
set -euo pipefail
BUILD=${1:-build}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
WORK=${WORK:-$BUILD/realmeshes}
MESHES=${MESHES:-"bunny00 armadillo refined_elephant fandisk_large ChineseDragon-10kv cheese blade man bear"}
CB="$BUILD/curvbench"
# Every registered method: the fits at degrees 2-4, the degree-free operators once.
METHODS=${METHODS:-$("$CB" methods --labels 2-4 | tr '\n' ' ')}
REF=${REF:-lhf-4}  # the reference of the agreement columns and of the pictures
mkdir -p "$WORK"
DATA="$WORK/data/meshes"
if [ ! -d "$DATA" ]; then
  echo "realmeshes: fetching libcgal-demo (apt-get download) into $WORK" >&2
  ( cd "$WORK" && (apt-get download libcgal-demo >/dev/null 2>&1 ||
      { [ "$(id -u)" = 0 ] && apt-get update >/dev/null && apt-get download libcgal-demo; } ||
      { echo "realmeshes: cannot download libcgal-demo (run 'apt-get update' as root?)" >&2; exit 2; }) )
  deb=$(ls "$WORK"/libcgal-demo_*.deb | head -1)
  dpkg-deb -x "$deb" "$WORK/pkg"
  tar -xzf "$WORK/pkg/usr/share/doc/libcgal-dev/data.tar.gz" -C "$WORK" data/meshes
fi
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
/usr/bin/python3 "$ROOT/tools/realmeshes_report.py" "$WORK" "$ROOT/results/REAL_MESHES.md" \
  --meshes $MESHES --methods $METHODS --reference "$REF"
echo "realmeshes: wrote results/REAL_MESHES.md" >&2
