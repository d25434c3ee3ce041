#!/usr/bin/env bash
# ./lbdem bench [--peers] [--n N] [--steps S] [--lbm-n "64 128"] [--no-dem] [--no-lbm]
# ./lbdem bench scaling [--threads 1,2] [--case NAME]... [--out DIR]   (bench/scaling.py)
# ./lbdem bench size [--dem-n N,...] [--lbm-n N,...] [--threads T] [--out DIR]   (bench/size.py)
# lbdem's particle-steps/s on the settled-bed case of bench/peers (N = 20,000 and 100,000, or the
# one --n) and its MLUPS on the periodic Taylor-Green box (64^3 and 128^3), on 1 and 2 threads; with
# --peers, STREAM, Palabos, LIGGGHTS and LAMMPS run the same cases in the same invocation through
# bench/peers/run_all.sh, and the ratios are printed. Only ratios from one run compare.
set -euo pipefail
BUILD_DIR="$1"; shift
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# ./lbdem bench scaling ...: the thread-scaling study (bench/scaling.py, Debian's python3 with
# numpy, h5py and matplotlib).
if [[ ${1:-} == scaling ]]; then
  shift
  exec /usr/bin/python3 "$ROOT/bench/scaling.py" "$BUILD_DIR" "$@"
fi
# ./lbdem bench size ...: cost and memory against problem size (bench/size.py).
if [[ ${1:-} == size ]]; then
  shift
  exec /usr/bin/python3 "$ROOT/bench/size.py" "$BUILD_DIR" "$@"
fi
PEERS=0 PEERS_MISSING=0 SIZES="20000 100000" STEPS="" REPS=${REPS:-1} LBM_SIZES="64 128" DEM=1 LBM=1
while [[ $# -gt 0 ]]; do
  case "$1" in
    --peers) PEERS=1 ;;
    --n) SIZES="$2"; shift ;;
    --steps) STEPS="$2"; shift ;;
    --lbm-n) LBM_SIZES="$2"; shift ;;
    --no-dem) DEM=0 ;;
    --no-lbm) LBM=0 ;;
    -h|--help) sed -n '2,8p' "$0"; exit 0 ;;
    *) echo "lbdem bench: unknown option '$1' (known: --peers, --n N, --steps S, --lbm-n \"N...\", --no-dem, --no-lbm)" >&2; exit 2 ;;
  esac
  shift
done
WORK="${LBDEM_BENCH_WORK:-${TMPDIR:-/tmp}/lbdem-bench}"
mkdir -p "$WORK"
TABLE="$WORK/lbdem_table_$(date +%Y%m%d_%H%M%S).txt"
echo "# lbdem bench on $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')" | tee "$TABLE"
if [[ $DEM == 1 ]]; then
  for n in $SIZES; do
    args=(--n "$n" --cache "$WORK" --threads 1 2)
    [[ -n $STEPS ]] && args+=(--steps "$STEPS")
    "$BUILD_DIR/bin/lbdem-bench-dem" "${args[@]}" | tee -a "$TABLE"
  done
fi
if [[ $LBM == 1 ]]; then
  # shellcheck disable=SC2086
  "$BUILD_DIR/bin/lbdem-bench-lbm" --n $LBM_SIZES --threads 1 2 --precision double single | tee -a "$TABLE"
fi

if [[ $PEERS == 1 ]]; then
  PEERS_DIR="$ROOT/bench/peers"
  [[ -f $PEERS_DIR/run_all.sh ]] || { echo "lbdem bench: $PEERS_DIR/run_all.sh not found" >&2; exit 1; }
  need=()
  pkgs=(openmpi-bin libopenmpi-dev make)
  [[ $DEM == 1 ]] && pkgs+=(liggghts lammps)
  [[ $LBM == 1 ]] && pkgs+=(libplb-dev libeigen3-dev libtinyxml-dev)
  for p in "${pkgs[@]}"; do dpkg-query -W -f='${db:Status-Abbrev}' "$p" 2>/dev/null | grep -q '^ii' || need+=("$p"); done
  if ((${#need[@]})); then
    echo "lbdem bench: installing the peers' Debian packages: ${need[*]}" >&2
    sudo=()
    if [[ $(id -u) -ne 0 ]]; then
      command -v sudo >/dev/null || { echo "lbdem bench: need root or sudo to install: ${need[*]}" >&2; exit 1; }
      sudo=(sudo)
    fi
    "${sudo[@]}" apt-get update -qq && DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${need[@]}" >&2
  fi
  sections=(stream)
  [[ $LBM == 1 ]] && sections+=(palabos)
  [[ $DEM == 1 ]] && sections+=(liggghts lammps)
  # run_all.sh's progress and failures ("liggghts not found", "palabos build failed") go to its
  # stderr: shown as they come and kept in $PEERS_LOG, so that a missing row has its reason.
  PEERS_LOG="$WORK/peers.log"
  echo "# peers: progress on stderr and in $PEERS_LOG (settling a bed of 100,000 takes minutes per code)" | tee -a "$TABLE"
  PEERS_WORK="$WORK/peers" REPS="$REPS" RANKS="1 2" DEM_SIZES="$SIZES" PLB_SIZES="$LBM_SIZES" \
    bash "$PEERS_DIR/run_all.sh" "${sections[@]}" 2> >(tee "$PEERS_LOG" >&2) | tee -a "$TABLE" || true
  wait  # for the tee on stderr
  for s in "${sections[@]}"; do
    if ! grep -q "^$s " "$TABLE"; then
      PEERS_MISSING=1
      why=$(grep -iE "not found|failed" "$PEERS_LOG" | grep -i "$s" | tail -n 2 | tr '\n' ' ')
      [[ -n $why ]] || why="the last lines of $PEERS_LOG: $(tail -n 2 "$PEERS_LOG" | tr '\n' ' ')"
      echo "lbdem bench: no $s row; $why" | tee -a "$TABLE" >&2
    fi
  done
  # Ratios: lbdem per thread against the best peer per rank, and lbdem's 1 -> 2 thread speed-up.
  awk '
    { for (i = 3; i <= NF; i++) if ($i == "particle-steps/s") { v = $(i-1) + 0; t = $(i-2); break }
      if (i > NF) next
      n = $0; sub(/.*N=/, "", n); sub(/,.*/, "", n); k = "N=" n " at " t " thread(s)/rank(s)"
      if ($1 == "lbdem") { l[k] = v; one[n] = (t == 1 ? v : one[n]); two[n] = (t == 2 ? v : two[n]) }
      else if (v > best[k]) best[k] = v }
    END {
      for (k in l) if (best[k] > 0) printf "ratio lbdem / best peer, %s: %.2f\n", k, l[k] / best[k]
      for (n in one) if (one[n] > 0 && two[n] > 0) printf "lbdem speed-up 1 -> 2 threads, N=%s: %.2f\n", n, two[n] / one[n]
    }' "$TABLE" | tee -a "$TABLE"
  # LBM: lbdem against Palabos per size and thread/rank count, and against the double-precision
  # roofline (304 B/cell) of the same run's STREAM triad.
  awk '
    /^lbdem LBM TGV/ { n = $0; sub(/.*N=/, "", n); sub(/,.*/, "", n)
      t = $0; sub(/.*N=[0-9]+, /, "", t); sub(/ thread.*/, "", t)
      m = $0; sub(/ MLUPS.*/, "", m); sub(/.*: /, "", m); l[n " " t] = m + 0 }
    /^palabos / { n = substr($0, 12, 44); sub(/.*TGV /, "", n); sub(/\^3.*/, "", n)
      p[n " " (substr($0, 57, 5) + 0)] = substr($0, 63, 14) + 0 }
    /^lbdem-single LBM TGV/ { n = $0; sub(/.*N=/, "", n); sub(/,.*/, "", n)
      t = $0; sub(/.*N=[0-9]+, /, "", t); sub(/ thread.*/, "", t)
      m = $0; sub(/ MLUPS.*/, "", m); sub(/.*: /, "", m); lf[n " " t] = m + 0 }
    /^roofline +D3Q19 double/ { r[substr($0, 57, 5) + 0] = substr($0, 63, 14) + 0 }
    /^roofline +D3Q19 single/ { rf[substr($0, 57, 5) + 0] = substr($0, 63, 14) + 0 }
    END {
      for (k in l) { split(k, a, " ")
        if (p[k] > 0) printf "ratio lbdem / Palabos, TGV %s^3 at %s thread(s)/rank(s): %.2f\n", a[1], a[2], l[k] / p[k]
        if (r[a[2]] > 0) printf "lbdem share of the double roofline, TGV %s^3 at %s thread(s): %.0f %%\n", a[1], a[2], 100 * l[k] / r[a[2]]
        if (lf[k] > 0) printf "lbdem single / double precision, TGV %s^3 at %s thread(s): %.2f\n", a[1], a[2], lf[k] / l[k]
        if (lf[k] > 0 && rf[a[2]] > 0) printf "lbdem single share of the single roofline, TGV %s^3 at %s thread(s): %.0f %%\n", a[1], a[2], 100 * lf[k] / rf[a[2]] }
    }' "$TABLE" | tee -a "$TABLE"
fi
echo "# table: $TABLE"
# A peer that gave no row fails the command (after the rows and ratios the others gave).
[[ $PEERS_MISSING == 0 ]] || exit 1
