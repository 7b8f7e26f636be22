#!/usr/bin/env bash
# One fuzz CTest (tests/fuzz/CMakeLists.txt): runs a harness for a bounded time on its seed corpus.
#   run_fuzz.sh HARNESS SECONDS INPUT_TIMEOUT MAX_LEN WORK_DIR SEED_DIR
# WORK_DIR is emptied first (each run starts from the seeds alone, so runs are comparable) and receives libFuzzer's
# new inputs (first corpus directory) and any finding (crash-*, timeout-*, or the driver's current-input).
set -uo pipefail
harness="$1" seconds="$2" input_timeout="$3" max_len="$4" work="$5" seed_dir="$6"
rm -rf "$work"
mkdir -p "$work/corpus" "$work/findings"
# -seed fixed: the driver is then deterministic; libFuzzer's run still depends on timing, so a finding is kept.
"$harness" -seed=1 -max_total_time="$seconds" -timeout="$input_timeout" -max_len="$max_len" -rss_limit_mb=2048 \
  -print_final_stats=1 -artifact_prefix="$work/findings/" "$work/corpus" "$seed_dir"
status=$?
if [ $status -ne 0 ]; then
  echo "run_fuzz: FINDING (exit $status); the input is kept in $work/findings/:" >&2
  ls -l "$work/findings" >&2
  echo "run_fuzz: replay it with: $harness $work/findings/<file>" >&2
fi
exit $status
