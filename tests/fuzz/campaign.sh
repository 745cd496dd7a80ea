#!/bin/sh
# One CTest fuzzing campaign: runs a libFuzzer target for a fixed time from the seed corpus
# into a fresh output folder, with a fixed seed (`-seed=0` picks a random one). The seed
# fixes the mutations, not the whole run: libFuzzer orders the seed files by size, and
# files of equal size in the order the file system lists them, which differs between
# machines. So a failure in CI must carry its own evidence: the run is quiet
# (-verbosity=0) so that the log ends with what matters, and on a failure the script
# prints the input that failed, byte by byte, and reruns it with GJKX_FUZZ_VERBOSE=1 (the
# decoded bodies and the violation).
#   campaign.sh <target> <artifact folder> <seed corpus> <seconds> <seed>
target=$1 artifacts=$2 seeds=$3 seconds=$4 seed=$5
out=$(mktemp -d) || exit 1
before=$(mktemp) || exit 1
ls "$artifacts" > "$before" 2>/dev/null
"$target" -seed="$seed" -verbosity=0 -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 \
  -print_final_stats=1 -artifact_prefix="$artifacts/" "$out" "$seeds"
status=$?
rm -rf "$out"
if [ "$status" -ne 0 ]; then
  for f in $(ls "$artifacts" | grep -E '^(crash|timeout|oom|leak|slow-unit)-' | grep -vxFf "$before"); do
    echo "=== the failing input, $artifacts/$f (od -An -tx1):"
    od -An -tx1 "$artifacts/$f"
    echo "=== rerun with GJKX_FUZZ_VERBOSE=1:"
    GJKX_FUZZ_VERBOSE=1 "$target" "$artifacts/$f" 2>&1 | tail -n 40
  done
fi
rm -f "$before"
exit "$status"
