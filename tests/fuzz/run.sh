#!/usr/bin/env bash
# Runs every libFuzzer target of a PROX_BUILD_FUZZERS build for a bounded
# time on seed corpora made from the shared assets (make_corpus.py), and
# fails on any crash, sanitizer report, leak, timeout or out-of-memory.
#   run.sh BUILD_DIR ASSETS_DIR SECONDS_PER_TARGET [TARGET...]
# Corpora grow in BUILD_DIR/fuzz-corpus; what a failing input was is
# written to BUILD_DIR/fuzz-artifacts (copy it to tests/fuzz/regressions/
# TARGET/ with the fix). Ends with "N passed, N failed".
set -uo pipefail
build=$1 assets=$2 seconds=$3
shift 3
here=$(cd "$(dirname "$0")" && pwd)
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(obj poses gltf gltf_capi create_mesh capi)
corpus=$build/fuzz-corpus
artifacts=$build/fuzz-artifacts
mkdir -p "$artifacts"
python3 "$here/make_corpus.py" "$assets" "$corpus" >/dev/null || { echo "make_corpus.py failed"; exit 1; }

passed=0 failed=0
for t in "${targets[@]}"; do
  exe=$build/tests/fuzz/proxima_fuzz_$t
  if [ ! -x "$exe" ]; then
    echo "FAIL $t: $exe is not built"
    failed=$((failed + 1))
    continue
  fi
  dict=()
  case $t in
    obj) dict=(-dict="$here/obj.dict") ;;
    gltf | gltf_capi) dict=(-dict="$here/gltf.dict") ;;
  esac
  # Regressions first: a fixed crash must stay fixed before new ground is
  # searched.
  log=$build/fuzz-$t.log
  if [ -d "$here/regressions/$t" ] && ! "$exe" -rss_limit_mb=2048 "$here/regressions/$t"/* >"$log" 2>&1; then
    echo "FAIL $t: a regression input fails again (see $log)"
    failed=$((failed + 1))
    continue
  fi
  # -timeout: one input may take at most 10 s; -rss_limit_mb: 2 GiB.
  if "$exe" "$corpus/$t" "${dict[@]}" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$artifacts/$t-" >"$log" 2>&1; then
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
    cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1)
    echo "ok $t: $runs executions in ${seconds} s, $cov"
    passed=$((passed + 1))
  else
    echo "FAIL $t: $(grep -m1 -E 'ERROR|check failed|runtime error' "$log") (see $log, input in $artifacts)"
    failed=$((failed + 1))
  fi
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
