#!/usr/bin/env bash
# Runs every libFuzzer target of a PROX_BUILD_FUZZERS build for a bounded
# time on seed corpora made from the shared assets (make_corpus.py), and
# fails on any crash, sanitizer report, leak, timeout or out-of-memory.
#   run.sh BUILD_DIR ASSETS_DIR SECONDS_PER_TARGET [TARGET...]
# Corpora grow in BUILD_DIR/fuzz-corpus; what a failing input was is
# written to BUILD_DIR/fuzz-artifacts (copy it to tests/fuzz/regressions/
# TARGET/ with the fix). Ends with "N passed, N failed".
# PROX_FUZZ_JOBS targets run at once (default: one per core), each for the
# full SECONDS on a core of its own: the same fuzzing in less wall time.
set -uo pipefail
build=$1 assets=$2 seconds=$3
shift 3
jobs=${PROX_FUZZ_JOBS:-$(nproc)}
here=$(cd "$(dirname "$0")" && pwd)
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(obj poses gltf gltf_capi create_mesh capi hid_descriptor kernel)
corpus=$build/fuzz-corpus
artifacts=$build/fuzz-artifacts
mkdir -p "$artifacts"
python3 "$here/make_corpus.py" "$assets" "$corpus" >/dev/null || { echo "make_corpus.py failed"; exit 1; }

# One target: its result line goes to BUILD_DIR/fuzz-TARGET.result.
fuzz_one() {  # fuzz_one TARGET
  local t=$1
  local exe=$build/tests/fuzz/proxima_fuzz_$t log=$build/fuzz-$t.log result=$build/fuzz-$t.result
  if [ ! -x "$exe" ]; then
    echo "FAIL $t: $exe is not built" >"$result"
    return
  fi
  local dict=()
  case $t in
    obj) dict=(-dict="$here/obj.dict") ;;
    gltf | gltf_capi) dict=(-dict="$here/gltf.dict") ;;
  esac
  # Regressions first: a fixed crash must stay fixed before new ground is
  # searched.
  if [ -d "$here/regressions/$t" ] && ! "$exe" -rss_limit_mb=2048 "$here/regressions/$t"/* >"$log" 2>&1; then
    echo "FAIL $t: a regression input fails again (see $log)" >"$result"
    return
  fi
  # -timeout: one input may take at most 10 s; -rss_limit_mb: 2 GiB.
  if "$exe" "$corpus/$t" "${dict[@]}" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$artifacts/$t-" >"$log" 2>&1; then
    local runs cov
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
    cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1)
    echo "ok $t: $runs executions in ${seconds} s, $cov" >"$result"
  else
    echo "FAIL $t: $(grep -m1 -E 'ERROR|check failed|runtime error' "$log") (see $log, input in $artifacts)" >"$result"
  fi
}

for t in "${targets[@]}"; do
  rm -f "$build/fuzz-$t.result"
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do
    wait -n
  done
  fuzz_one "$t" &
done
wait

passed=0 failed=0
for t in "${targets[@]}"; do
  result=$build/fuzz-$t.result
  [ -s "$result" ] || echo "FAIL $t: no result (the run died)" >"$result"
  cat "$result"
  case $(cat "$result") in
    ok\ *) passed=$((passed + 1)) ;;
    *) failed=$((failed + 1)) ;;
  esac
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
