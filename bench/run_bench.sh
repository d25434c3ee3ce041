#!/usr/bin/env bash
# ./lbdem bench [--peers] [--n N] [--steps S]
# lbdem's particle-steps/s on the settled-bed case of ../shared/bench (N = 20,000 and 100,000, or the
# one --n) on 1 and 2 threads; with --peers, LIGGGHTS and LAMMPS (and STREAM) run the same case in the same invocation
# through ../shared/bench/run_all.sh, and the ratios are printed. Only ratios from one run compare.
set -euo pipefail
BUILD_DIR="$1"; shift
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
PEERS=0 SIZES="20000 100000" STEPS="" REPS=${REPS:-1}
while [[ $# -gt 0 ]]; do
  case "$1" in
    --peers) PEERS=1 ;;
    --n) SIZES="$2"; shift ;;
    --steps) STEPS="$2"; shift ;;
    -h|--help) sed -n '2,5p' "$0"; exit 0 ;;
    *) echo "lbdem bench: unknown option '$1' (known: --peers, --n N, --steps S)" >&2; exit 2 ;;
  esac
  shift
done
WORK="${LBDEM_BENCH_WORK:-${TMPDIR:-/tmp}/lbdem-bench}"
mkdir -p "$WORK"
TABLE="$WORK/lbdem_table_$(date +%Y%m%d_%H%M%S).txt"
echo "# lbdem bench on $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')" | tee "$TABLE"
for n in $SIZES; do
  args=(--n "$n" --cache "$WORK" --threads 1 2)
  [[ -n $STEPS ]] && args+=(--steps "$STEPS")
  "$BUILD_DIR/bin/lbdem-bench-dem" "${args[@]}" | tee -a "$TABLE"
done

if [[ $PEERS == 1 ]]; then
  SHARED="$ROOT/../shared/bench"
  [[ -f $SHARED/run_all.sh ]] || { echo "lbdem bench: $SHARED/run_all.sh not found" >&2; exit 1; }
  need=()
  for p in liggghts lammps openmpi-bin; do dpkg-query -W -f='${db:Status-Abbrev}' "$p" 2>/dev/null | grep -q '^ii' || need+=("$p"); done
  if ((${#need[@]})); then
    sudo=(); [[ $(id -u) -ne 0 ]] && sudo=(sudo)
    "${sudo[@]}" apt-get update -qq && DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${need[@]}" >&2
  fi
  PEERS_WORK="$WORK/peers" REPS="$REPS" RANKS="1 2" DEM_SIZES="$SIZES" bash "$SHARED/run_all.sh" stream liggghts lammps 2>/dev/null | tee -a "$TABLE"
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
fi
echo "# table: $TABLE"
