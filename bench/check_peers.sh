#!/usr/bin/env bash
# Fails when a benchmark executable would load two builds of one shared
# library (for example FCL's liboctomap.so.1.9 beside Coal's 1.10, which
# corrupted the heap), or FCL and Coal together, or a library it cannot find.
# Usage: check_peers.sh EXECUTABLE...
set -euo pipefail
status=0
for program in "$@"; do
  if [ ! -x "$program" ]; then
    echo "$program: missing"
    status=1
    continue
  fi
  libs=$(ldd "$program" | awk '$2 == "=>" { print $1, $3 }')
  if grep -q " not$" <<<"$libs"; then
    echo "$program: cannot find $(awk '$2 == "not" { print $1 }' <<<"$libs" | tr '\n' ' ')"
    status=1
  fi
  # Two sonames with one stem (libX.so.A and libX.so.B) in one process.
  clashes=$(awk '{ stem = $1; sub(/\.so.*/, "", stem); print stem, $1 }' <<<"$libs" | sort -u |
    awk '{ n[$1]++; names[$1] = names[$1] " " $2 } END { for (s in n) if (n[s] > 1) print names[s] }')
  if [ -n "$clashes" ]; then
    echo "$program: loads two builds of one library:$clashes"
    status=1
  fi
  if grep -q "^libfcl" <<<"$libs" && grep -q "^libcoal" <<<"$libs"; then
    echo "$program: loads FCL and Coal in one process; Coal belongs in proxima_coal_peer"
    status=1
  fi
done
[ $status -eq 0 ] && echo "no clash in: $*"
exit $status
