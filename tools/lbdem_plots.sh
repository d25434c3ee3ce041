#!/usr/bin/env bash
# Plots for a run folder: tools/lbdem_plots.sh RUN_DIR
# Plotting is optional, so a machine without numpy/h5py/matplotlib gets a warning, not a failure.
set -u
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
[[ $# -eq 1 ]] || { echo "usage: $0 RUN_DIR" >&2; exit 2; }
run="$1"

# Debian's python3 first: a pyenv/conda python3 earlier on PATH often lacks h5py.
py=""
for cand in /usr/bin/python3 python3; do
  if command -v "$cand" >/dev/null 2>&1 &&
     "$cand" -c 'import numpy, h5py, matplotlib' >/dev/null 2>&1; then
    py="$cand"; break
  fi
done
if [[ -z $py ]]; then
  echo "lbdem_plots: no python3 with numpy, h5py and matplotlib; plots skipped" >&2
  exit 0
fi

"$py" "$here/plot_run.py" "$run"
rc=$?
if [[ -f $run/collisions.h5 ]]; then
  "$py" "$here/collision_summary.py" "$run"
  r=$?
  (( r > rc )) && rc=$r
fi
exit "$rc"
