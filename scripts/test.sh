#!/usr/bin/env bash
# Set-up (scripts/setup.sh), then the whole test suite through ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
JOBS=$(nproc 2>/dev/null || echo 2)
ctest --test-dir build --output-on-failure -j"$JOBS"
