#!/bin/sh
# One CTest fuzzing campaign: runs a libFuzzer target for a fixed number of inputs from the
# seed corpus, with a fixed seed (`-seed=0` picks a random one), so that a campaign is the
# same on every machine: same seed, same inputs, same order. What libFuzzer leaves to the
# machine is fixed here:
#  - the length: a count of runs (-runs), not a time, which a slower machine would cut short;
#  - the seeds' order: libFuzzer sorts its seed files by size, and leaves files of equal
#    size in the order it read them, which for a folder is the file system's (it differs
#    between machines). So the seeds are handed over as a list (-seed_inputs=@list), in the
#    order of their names in the C locale, and the output folder it fuzzes into is fresh and
#    never re-read (-reload=0);
#  - the mutations: libFuzzer also mutates with values the target compared (CMP traces,
#    -use_cmp, -use_memmem), and some of those are heap addresses, which differ between
#    runs (address-space randomisation): two runs with one seed drifted apart after a few
#    hundred inputs (689 and 632 new units in 3000 runs). Without them two runs give the
#    same corpus, file for file.
# A failure in CI carries its own evidence: the run is quiet (-verbosity=0) so that the log
# ends with what matters, and on a failure the script prints the input that failed, byte by
# byte, and reruns it with GJKX_FUZZ_VERBOSE=1 (the decoded bodies and the violation).
#   campaign.sh <target> <artifact folder> <seed corpus> <runs> <seed>
target=$1 artifacts=$2 seeds=$3 runs=$4 seed=$5
out=$(mktemp -d) || exit 1
before=$(mktemp) || exit 1
list=$(mktemp) || exit 1
ls "$artifacts" > "$before" 2>/dev/null
LC_ALL=C ls "$seeds" | LC_ALL=C sort | sed "s|^|$seeds/|" | paste -sd, - > "$list"
"$target" -seed="$seed" -runs="$runs" -seed_inputs=@"$list" -reload=0 -use_cmp=0 -use_memmem=0 -verbosity=0 -timeout=10 -rss_limit_mb=4096 \
  -print_final_stats=1 -artifact_prefix="$artifacts/" "$out"
status=$?
rm -rf "$out" "$list"
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
