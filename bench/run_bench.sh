#!/usr/bin/env bash
# ./lbdem bench [--peers]: lbdem's particle-steps/s on the settled-bed case of ../shared/bench.
set -euo pipefail
BUILD_DIR="$1"; shift
echo "lbdem bench: not yet implemented in this build (see the issue 'Foundation and DEM engine' §8)" >&2
exit 0
