#!/usr/bin/env bash
# Side-by-side speed of granbench's 2D solver and Gerris (the code the seed paper used) on the
# §7 rollwave case at equal cells: Gerris LEVEL L is 10 boxes of 2^L x 2^L cells, i.e.
# (10 2^L) x 2^L; the default L = 4 is 160 x 16 (8 cells per h0), to t = 0.1 s; run one after
# the other on the same machine in one invocation. Prints JSON with the wall and CPU seconds of
# each and the speed-up.
#
#   bench/gerris_side_by_side.sh [build-dir] [t_end seconds] [LEVEL]
# Installs gerris2D (Debian package gerris) when missing; reads the case from shared/ beside the
# repository (or GERRIS_CASE). GRANBENCH_OPTIONS adds options to granbench's run (e.g.
# "--cfl 0.8"; default none: granbench's defaults).
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-build}
t_end=${2:-0.1}
level=${3:-4}
nz=$((1 << level))
nx=$((10 * nz))
case_file=${GERRIS_CASE:-$repo/../shared/gerris/rollwave.gfs}
if ! command -v gerris2D >/dev/null; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq gerris >&2
fi
here=$(mktemp -d)
trap 'rm -rf "$here"' EXIT
T0=0.02019275109  # sqrt(h0/g) in seconds: Gerris' time unit
tend=$(python3 -c "print($t_end/$T0)")

mkdir -p "$here/out/h" "$here/out/full"
g_start=$(date +%s.%N)
/usr/bin/time -f "%U %S" -o "$here/gtime" gerris2D -m -DLEVEL="$level" -DTEND="$tend" -DDTOUT="$tend" \
  -DDTFULL="$tend" -DA0=0.05 -DVMIX=0 -DOUTDIR="$here/out" "$case_file" > /dev/null 2>&1
g_end=$(date +%s.%N)

o_start=$(date +%s.%N)
/usr/bin/time -f "%U %S" -o "$here/otime" "$build/granbench" run --model twod --nx "$nx" --nz "$nz" \
  --Lx 0.08 --h0 0.004 --a0 2e-4 --angle 28.5 --t-end "$t_end" ${GRANBENCH_OPTIONS:-} --json --quiet \
  > "$here/ours.json"
o_end=$(date +%s.%N)

python3 - "$here" "$g_start" "$g_end" "$o_start" "$o_end" "$t_end" "$nx" "$nz" "${GRANBENCH_OPTIONS:-}" <<'PY'
import json, sys
d, gs, ge, os_, oe, t = sys.argv[1], *map(float, sys.argv[2:7])
nx, nz = sys.argv[7], sys.argv[8]
gu, gsys = map(float, open(d + "/gtime").read().split()[-2:])
ou, osys = map(float, open(d + "/otime").read().split()[-2:])
ours = json.load(open(d + "/ours.json"))
print(json.dumps({
    "cells": f"{nx}x{nz}", "t_end": t,
    "gerris": {"wall_seconds": ge - gs, "cpu_seconds": gu + gsys},
    "granbench_twod": {"wall_seconds": oe - os_, "cpu_seconds": ou + osys, "steps": ours["steps"],
                       "mass_error": ours["mass_error"], "options": sys.argv[9]},
    "speedup_wall": (ge - gs) / (oe - os_), "speedup_cpu": (gu + gsys) / (ou + osys)}, indent=2))
PY
