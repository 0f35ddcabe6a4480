#!/usr/bin/env bash
# One corpus test (tests/corpus/CMakeLists.txt registers them as corpus.*):
#   run_case.sh lower  DOUBLET VALIDATOR SHADER TARGET OUT_DIR
#       lowers SHADER for TARGET (-I include/) and re-validates the output with glslangValidator;
#   run_case.sh verify DOUBLET SHADER TARGET BACKEND MIN_BITS SAMPLES
#       runs `doublet verify` with SHADER.json as its spec (when there is one) and --min-bits;
#   run_case.sh sabotage DOUBLET SHADER TARGET BACKEND MIN_BITS SAMPLES
#       the same with --sabotage drop-lo, which must fail the check (exit 1; 0 or 2 fail the test).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
mode="$1"; shift
case "$mode" in
  lower)
    doublet="$1" validator="$2" shader="$3" target="$4" out_dir="$5"
    name="$(basename "$shader")"
    out="$out_dir/${name%.*}.$target.${name##*.}"  # keeps the stage extension for the validator
    mkdir -p "$out_dir"
    "$doublet" lower "$here/$shader" --target "$target" -I "$here/include" -o "$out"
    "$validator" "$out"
    ;;
  verify|sabotage)
    doublet="$1" shader="$2" target="$3" backend="$4" min_bits="$5" samples="$6"
    args=()
    [[ -f "$here/$shader.json" ]] && args=(--spec "$here/$shader.json")
    [[ "$mode" == sabotage ]] && args+=(--sabotage drop-lo)
    status=0
    "$doublet" verify "$here/$shader" --target "$target" --backend "$backend" -I "$here/include" \
      "${args[@]}" --min-bits "$min_bits" --samples "$samples" || status=$?
    if [[ "$mode" == sabotage ]]; then
      [[ $status == 1 ]] || { echo "run_case.sh: verify --sabotage drop-lo exited $status, expected 1 (FAIL)" >&2; exit 1; }
      exit 0
    fi
    exit $status
    ;;
  *) echo "run_case.sh: unknown mode '$mode'" >&2; exit 2 ;;
esac
