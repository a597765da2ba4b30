#!/usr/bin/env bash
# Side-by-side speed of granbench's 2D solver and Gerris (the code the seed paper used) on the
# §7 rollwave case at equal cells: Gerris LEVEL L is 10 boxes of 2^L x 2^L cells, i.e.
# (10 2^L) x 2^L; the default L = 4 is 160 x 16 (8 cells per h0), to t = 0.1 s; run one after
# the other on the same machine in one invocation. Prints JSON with the wall and CPU seconds of
# each and the speed-up.
#
#   bench/gerris_side_by_side.sh [build-dir] [t_end seconds] [LEVEL]
# Installs gerris2D (Debian package gerris) when missing; reads the case from shared/ beside the
# repository (or GERRIS_CASE). Each pair runs pinned to one CPU, once per CPU (below); the
# headline figures are the pair with the smaller speed-up, and `per_cpu` lists every pair.
# GRANBENCH_OPTIONS adds options to granbench's run (e.g. "--cfl 0.8"; default none: granbench's
# defaults).
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

# Both codes run on the same CPU, pinned (taskset), once on each CPU this script may use (or
# on those of GERRIS_BENCH_CPUS, e.g. "1"): the host at times runs one of this machine's two
# virtual CPUs 1.3-1.7 times slower than the other, and slows Gerris more than granbench there
# (docs/performance.md), so a pair split across the two CPUs would compare the CPUs, not the
# codes.
allowed=$(python3 -c "import os; print(' '.join(map(str, sorted(os.sched_getaffinity(0)))))")
cpus=${GERRIS_BENCH_CPUS:-$allowed}
for cpu in $cpus; do
  rm -rf "$here/out" && mkdir -p "$here/out/h" "$here/out/full"
  g_start=$(date +%s.%N)
  taskset -c "$cpu" /usr/bin/time -f "%U %S" -o "$here/gtime.$cpu" gerris2D -m -DLEVEL="$level" \
    -DTEND="$tend" -DDTOUT="$tend" -DDTFULL="$tend" -DA0=0.05 -DVMIX=0 -DOUTDIR="$here/out" \
    "$case_file" > /dev/null 2>&1
  g_end=$(date +%s.%N)
  o_start=$(date +%s.%N)
  taskset -c "$cpu" /usr/bin/time -f "%U %S" -o "$here/otime.$cpu" "$build/granbench" run \
    --model twod --nx "$nx" --nz "$nz" --Lx 0.08 --h0 0.004 --a0 2e-4 --angle 28.5 \
    --t-end "$t_end" ${GRANBENCH_OPTIONS:-} --json --quiet > "$here/ours.$cpu.json"
  o_end=$(date +%s.%N)
  echo "$cpu $g_start $g_end $o_start $o_end" >> "$here/times"
done

python3 - "$here" "$t_end" "$nx" "$nz" "${GRANBENCH_OPTIONS:-}" <<'PY'
import json, sys
d, t, nx, nz, options = sys.argv[1], float(sys.argv[2]), sys.argv[3], sys.argv[4], sys.argv[5]
per_cpu = []
for line in open(d + "/times"):
    cpu, gs, ge, os_, oe = line.split()
    gs, ge, os_, oe = map(float, (gs, ge, os_, oe))
    gu, gsys = map(float, open(f"{d}/gtime.{cpu}").read().split()[-2:])
    ou, osys = map(float, open(f"{d}/otime.{cpu}").read().split()[-2:])
    ours = json.load(open(f"{d}/ours.{cpu}.json"))
    per_cpu.append({
        "cpu": int(cpu),
        "gerris": {"wall_seconds": ge - gs, "cpu_seconds": gu + gsys},
        "granbench_twod": {"wall_seconds": oe - os_, "cpu_seconds": ou + osys,
                           "steps": ours["steps"], "mass_error": ours["mass_error"],
                           "options": options},
        "speedup_wall": (ge - gs) / (oe - os_), "speedup_cpu": (gu + gsys) / (ou + osys)})
# The headline is the CPU where granbench gains least (the conservative figure); every CPU's
# pair is listed.
worst = min(per_cpu, key=lambda p: p["speedup_wall"])
print(json.dumps({"cells": f"{nx}x{nz}", "t_end": t, "cpu": worst["cpu"],
                  "gerris": worst["gerris"], "granbench_twod": worst["granbench_twod"],
                  "speedup_wall": worst["speedup_wall"], "speedup_cpu": worst["speedup_cpu"],
                  "per_cpu": per_cpu}, indent=2))
PY
