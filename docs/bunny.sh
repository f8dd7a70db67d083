#!/usr/bin/env bash
# The Stanford bunny (the paper's Fig. 10) covered by developable strips on the automatic path:
# the mesh scaled from metres to mm, thinned, split by k-means into flat strips, each pulled
# towards its points, and the distance report. Build first (bash cmake/setup.sh build).
#
#   bash docs/bunny.sh BUNNY.obj [OUT.devsurf] [STRIPS] [INTERVALS]
#
# Defaults: bunny.devsurf, 94 strips (the paper's count) of 2 spline intervals. Open the result
# with build/bin/devsurf OUT.devsurf; the bunny is stored in it as its reference shape.
set -euo pipefail

if [ $# -lt 1 ]; then
  echo "usage: bash docs/bunny.sh BUNNY.obj [OUT.devsurf] [STRIPS] [INTERVALS]" >&2
  exit 1
fi
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cli="$root/build/bin/devsurf-cli"
if [ ! -x "$cli" ]; then
  echo "$cli is not built yet: run bash cmake/setup.sh build first" >&2
  exit 1
fi
in="$1"
out="${2:-bunny.devsurf}"
strips="${3:-94}"
intervals="${4:-2}"

# The scan is in metres; DevSurf works in mm. The copy keeps the file's name, which the
# project shows as the reference shape's.
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
scaled="$tmp/$(basename "$in")"
awk '$1 == "v" { printf "v %.6f %.6f %.6f\n", $2 * 1000, $3 * 1000, $4 * 1000; next } { print }' \
  "$in" > "$scaled"

# Per-iteration lines left out: one summary line per strip, then the distance report.
"$cli" approximate "$scaled" --strips "$strips" --intervals "$intervals" -o "$out" |
  grep -v '^iteration'
