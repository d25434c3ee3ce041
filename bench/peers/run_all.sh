#!/usr/bin/env bash
# The peer codes on lbdem's benchmark cases (bench/peers/README.md): STREAM triad (memory
# bandwidth and the D3Q19 roofline), Palabos on the periodic Taylor-Green box, LIGGGHTS and LAMMPS
# on the settled Hertz-Mindlin bed. Prints one table of medians. `./lbdem bench --peers` calls it
# (bench/run_bench.sh) with REPS=1 after lbdem's own runs, so that the ratios come from one run.
#
# usage: bash bench/peers/run_all.sh [section ...]   sections: stream palabos liggghts lammps
# environment (default in brackets):
#   REPS [3]  RANKS ["1 2"]  PLB_SIZES ["64 128"]  PLB_STEPS [200]  PLB_WARMUP [20]
#   DEM_SIZES ["20000 100000"]  STEPS_20000 [5000]  STEPS_100000 [1000]  SETTLE_STEPS [20000]
#   RESETTLE [0]: 1 settles the beds again even where a cached restart file exists
#   PEERS_WORK [${TMPDIR:-/tmp}/lbdem-peers]: binaries, settled beds, logs and tables
# Debian 12 packages: liggghts lammps libplb-dev libeigen3-dev libtinyxml-dev openmpi-bin
#                     libopenmpi-dev g++ make (bench/run_bench.sh installs the missing ones)
set -uo pipefail

HERE="$(cd "$(dirname "$0")" && pwd)"
cd "$HERE"
# Everything this script writes (binaries, settled beds, logs, tables) goes to a scratch folder,
# so that the script also runs from a read-only checkout.
W=${PEERS_WORK:-${TMPDIR:-/tmp}/lbdem-peers}
mkdir -p "$W"
STAMP="$(date +%Y%m%d_%H%M%S)"
RAW="$W/raw_$STAMP.log"
TABLE="$W/table_$STAMP.txt"

REPS=${REPS:-3}
RANKS=${RANKS:-"1 2"}
PLB_SIZES=${PLB_SIZES:-"64 128"}
PLB_STEPS=${PLB_STEPS:-200}
PLB_WARMUP=${PLB_WARMUP:-20}
DEM_SIZES=${DEM_SIZES:-"20000 100000"}
SETTLE_STEPS=${SETTLE_STEPS:-20000}
RESETTLE=${RESETTLE:-0}
MPIRUN=(mpirun --allow-run-as-root --oversubscribe --bind-to core)

SECTIONS=${*:-"stream palabos liggghts lammps"}

median() { sort -g | awk '{v[NR]=$1} END{if(NR==0){print "NA"; exit} if(NR%2) print v[(NR+1)/2]; else print (v[NR/2]+v[NR/2+1])/2}'; }
log() { echo "$@" | tee -a "$RAW" >&2; }
row() { printf '%-10s %-44s %5s %14s  %-18s %s\n' "$@" | tee -a "$TABLE"; }

{
  echo "# peer benchmark run $STAMP"
  echo "# host: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')"
  echo "# debian packages: $(dpkg-query -W -f='${Package}=${Version} ' liggghts lammps libplb-dev openmpi-bin 2>/dev/null)"
} | tee "$TABLE" >"$RAW"
row "peer" "case" "ranks" "median" "unit" "(all runs)"

# ---------------------------------------------------------------- stream + roofline
if [[ " $SECTIONS " == *" stream "* ]]; then
  if [[ ! -x $W/stream_triad || stream/stream_triad.c -nt $W/stream_triad ]]; then
    gcc -O3 -march=native -fopenmp stream/stream_triad.c -o "$W/stream_triad" || { log "stream build failed"; exit 1; }
  fi
  for t in $RANKS; do
    vals=()
    for r in $(seq "$REPS"); do
      out=$(OMP_NUM_THREADS=$t OMP_PROC_BIND=spread "$W/stream_triad"); log "$out"
      vals+=("$(sed -n 's/.*triad_GBps=\([0-9.]*\).*/\1/p' <<<"$out")")
    done
    bw=$(printf '%s\n' "${vals[@]}" | median)
    row stream "triad a=b+s*c, 3 x 358 MB doubles, best/10" "$t" "$bw" "GB/s" "${vals[*]}"
    row roofline "D3Q19 double, 304 B/cell = bw/304" "$t" "$(awk -v b="$bw" 'BEGIN{printf "%.1f", b*1e3/304}')" "MLUPS (bound)" ""
    row roofline "D3Q19 single, 152 B/cell = bw/152" "$t" "$(awk -v b="$bw" 'BEGIN{printf "%.1f", b*1e3/152}')" "MLUPS (bound)" ""
  done
fi

# ---------------------------------------------------------------- Palabos
if [[ " $SECTIONS " == *" palabos "* ]]; then
  if ! make -s -C palabos OUT="$W/plb_tgv_bench" >>"$RAW" 2>&1; then
    log "palabos build failed (see $RAW)"
  else
    for n in $PLB_SIZES; do
      for p in $RANKS; do
        vals=()
        for r in $(seq "$REPS"); do
          out=$("${MPIRUN[@]}" -np "$p" "$W/plb_tgv_bench" "$n" "$PLB_STEPS" "$PLB_WARMUP" 2>&1 | grep PALABOS_RESULT); log "$out"
          vals+=("$(sed -n 's/.*MLUPS=\([0-9.eE+-]*\).*/\1/p' <<<"$out")")
        done
        row palabos "D3Q19 BGK double, periodic TGV ${n}^3, ${PLB_STEPS} st" "$p" "$(printf '%s\n' "${vals[@]}" | median)" "MLUPS" "${vals[*]}"
      done
    done
  fi
fi

# ---------------------------------------------------------------- DEM (LIGGGHTS, LAMMPS)
dem() {  # $1 = liggghts|lammps
  local code=$1 exe
  if [[ $code == liggghts ]]; then exe=liggghts; else exe=lmp; fi
  command -v "$exe" >/dev/null || { log "$exe not found"; return; }
  for n in $DEM_SIZES; do
    local nz=$(( n / 2500 )) rst="$W/${code}_N${n}.restart"
    local steps_var="STEPS_$n"; local steps=${!steps_var:-}
    [[ -z $steps ]] && { if (( n <= 20000 )); then steps=5000; else steps=1000; fi; }
    if [[ $RESETTLE == 1 || ! -s $rst ]]; then
      log "settling $code N=$n ($SETTLE_STEPS steps of 1e-5 s, 2 ranks) ..."
      "${MPIRUN[@]}" -np 2 "$exe" -in "$code/in.settle" -log "$W/settle_${code}_N${n}.log" -screen none \
        -var NZ "$nz" -var out "$rst" -var SETTLE "$SETTLE_STEPS" >>"$RAW" 2>&1 || { log "settle failed"; continue; }
    fi
    for p in $RANKS; do
      local vals=() cns=()
      for r in $(seq "$REPS"); do
        local lg="$W/timed_${code}_N${n}_np${p}_r${r}.log"
        "${MPIRUN[@]}" -np "$p" "$exe" -in "$code/in.timed" -log "$lg" -screen none \
          -var rst "$rst" -var NSTEPS "$steps" >>"$RAW" 2>&1 || { log "$code run failed ($lg)"; continue; }
        local loop natoms cn
        loop=$(grep 'Loop time of' "$lg" | tail -1 | awk '{print $4}')
        natoms=$(grep 'Loop time of' "$lg" | tail -1 | awk '{print $12}')
        cn=$(awk '/^ *[0-9]+ +[0-9]+ /{last=$4} END{print last}' "$lg")
        log "$code N=$natoms np=$p steps=$steps loop_s=$loop contacts_per_particle=$cn"
        vals+=("$(awk -v n="$natoms" -v s="$steps" -v t="$loop" 'BEGIN{printf "%.4g", n*s/t}')")
        cns+=("$cn")
      done
      row "$code" "Hertz-Mindlin bed N=$n, dt=1e-6, $steps st, Z=$(printf '%s\n' "${cns[@]}" | median)" "$p" \
        "$(printf '%s\n' "${vals[@]}" | median)" "particle-steps/s" "${vals[*]}"
    done
  done
}
[[ " $SECTIONS " == *" liggghts "* ]] && dem liggghts
[[ " $SECTIONS " == *" lammps "* ]] && dem lammps

echo "# table: $TABLE   raw log: $RAW" >&2
