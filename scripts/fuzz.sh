#!/usr/bin/env bash
# Builds the readers' libFuzzer targets with clang (Debian's clang and
# libclang-rt-dev) under AddressSanitizer and UndefinedBehaviorSanitizer into
# build-fuzz/, then runs each for SECONDS (default: build only). The readers'
# sources are compiled instrumented; what they call in the other modules is
# linked from ./build (scripts/setup.sh builds it). docs/reliability.md says
# what the runs found.
#
#   bash scripts/fuzz.sh [SECONDS [JOBS]]
#
# Corpora start from fuzz/corpus/<target> (the seeds, committed) and
# fuzz/regressions/<target> (inputs that once crashed or hung a reader) and
# grow in build-fuzz/corpus/<target>; a finding is written to
# build-fuzz/crash-<target>-* and belongs in fuzz/regressions/<target>/ once
# fixed: the FuzzInputs tests (mesh and pipeline suites) replay both folders.
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_EACH=${1:-0}
JOBS=${2:-2}
OUT=build-fuzz
mkdir -p "$OUT"
CXX=${CXX_FUZZ:-clang++}

SAN="-fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined"
INCLUDES=(-I core/include -I mesh/include -I param/include -I spline/include -I iga_check/include
          -I export/include -I models/include -I pipeline/include -I pipeline/src -I build/pipeline
          -isystem /usr/include/eigen3 -isystem /usr/include/hdf5/serial)
FLAGS=(-std=c++17 -O1 -g $SAN "${INCLUDES[@]}")
CORE_SRC=(core/src/*.cpp)

echo "fuzz: building surface readers"
for ext in stl obj off ply; do
  "$CXX" "${FLAGS[@]}" -DFUZZ_EXTENSION="\".$ext\"" fuzz/fuzz_surface.cpp mesh/src/read_surface.cpp \
    "${CORE_SRC[@]}" -o "$OUT/fuzz_$ext" &
done
wait

echo "fuzz: building the case reader"
LIBS=(build/pipeline/libigaprep_pipeline.a build/iga_check/libigaprep_iga_check.a build/export/libigaprep_export.a
      build/models/libigaprep_models.a build/param/libigaprep_param.a build/spline/libigaprep_spline.a
      build/mesh/libigaprep_mesh.a build/core/libigaprep_core.a)
HDF5_LIB=$(pkg-config --libs hdf5 2>/dev/null || echo "-L/usr/lib/x86_64-linux-gnu/hdf5/serial -lhdf5")
"$CXX" "${FLAGS[@]}" fuzz/fuzz_case.cpp pipeline/src/case_read.cpp pipeline/src/case_sections.cpp \
  pipeline/src/json_reader.cpp "${LIBS[@]}" $HDF5_LIB -ltet -lceres -lglog -lcholmod -lgmp -lmpfr -lcrypto \
  -llapack -lblas -lpthread -o "$OUT/fuzz_case"

echo "fuzz: building the HDF5 model reader"
"$CXX" "${FLAGS[@]}" fuzz/fuzz_hdf5_model.cpp export/src/*.cpp build/spline/libigaprep_spline.a \
  build/core/libigaprep_core.a $HDF5_LIB -lceres -lglog -llapack -lblas -lpthread -o "$OUT/fuzz_hdf5_model"

[[ "$SECONDS_EACH" -gt 0 ]] || { echo "fuzz: built in $OUT"; exit 0; }

run_one() {
  local target=$1
  mkdir -p "$OUT/corpus/$target" "fuzz/corpus/$target"
  local seeds=("fuzz/corpus/$target")
  [[ -d "fuzz/regressions/$target" ]] && seeds+=("fuzz/regressions/$target")
  # An input that takes more than 10 s is a finding too (a reader spinning).
  "$OUT/fuzz_$target" -max_total_time="$SECONDS_EACH" -timeout=10 -print_final_stats=1 \
    -artifact_prefix="$OUT/crash-$target-" "$OUT/corpus/$target" "${seeds[@]}" >"$OUT/fuzz_$target.log" 2>&1 || true
  echo "fuzz: $target: $(grep -E 'stat::number_of_executed_units' "$OUT/fuzz_$target.log" | awk '{print $2}') executions," \
       "$(grep -oE 'cov: [0-9]+' "$OUT/fuzz_$target.log" | tail -1), findings: $(ls "$OUT" | grep -c "^crash-$target-" || true)"
}
export -f run_one
export OUT SECONDS_EACH
printf '%s\n' ${TARGETS:-stl obj off ply case hdf5_model} | xargs -P "$JOBS" -I{} bash -c 'run_one {}'
