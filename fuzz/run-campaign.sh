#!/usr/bin/env bash
# Runs a fuzzing campaign: builds the libFuzzer targets (clang-14, build-fuzz/) when needed, runs
# each target for EXECUTIONS inputs from its corpus, merges what was new into fuzz/corpus/,
# keeps every failing input in fuzz/crashes/<target>/ and prints a table per target.
#
#   fuzz/run-campaign.sh [EXECUTIONS] [TARGET...]     (default 10000000, every target)
#
# Environment: FUZZ_PARALLEL (targets run at once, default 1; each is one process, one worker),
# FUZZ_MAX_SECONDS (stop a target after this long even short of EXECUTIONS), CC/CXX (default
# clang-14/clang++-14), FUZZ_CAMPAIGN (its logs and tables, default build-fuzz/campaign: another
# directory lets a second campaign run beside the first). Everything runs under nice -n 19.
set -euo pipefail

runs=${1:-10000000}
shift || true
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
build=$root/build-fuzz
campaign=${FUZZ_CAMPAIGN:-$build/campaign}
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$(dirname "$root")}

if [[ $# -gt 0 ]]; then
    targets=("$@")
else
    targets=()
    for source in "$here"/fuzz_*.cpp; do
        name=$(basename "$source" .cpp)
        targets+=("${name#fuzz_}")
    done
fi

if [[ ! -f $build/build.ninja ]]; then
    launcher=()
    command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
    # Asserts on (Debug) at -O1 with line tables: what the sanitizers are meant for. Clang warns
    # where gcc does not: the normal build keeps warnings as errors, this one does not.
    CC=${CC:-clang-14} CXX=${CXX:-clang++-14} nice -n 19 cmake -S "$root" -B "$build" -G Ninja \
        -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" -DSERVOBENCH_FUZZ=ON \
        -DSERVOBENCH_BUILD_TESTS=OFF -DSERVOBENCH_WERROR=OFF "${launcher[@]}"
fi
nice -n 19 cmake --build "$build" --target "${targets[@]/#/fuzz_}"

# The longest input each kind of target is given: a few frames, or a file of a few kB.
max_len() {
    case $1 in
        # The decoder explains every frame four ways: longer streams only slow it down.
        *framer | decoder) echo 512 ;;
        register_table) echo 32768 ;; # the shipped tables are some 20 kB
        *) echo 8192 ;;
    esac
}

run_target() {
    local target=$1
    local program=$build/fuzz/fuzz_$target
    local corpus=$here/corpus/$target
    local crashes=$here/crashes/$target
    local found=$campaign/$target/new
    local log=$campaign/$target.log
    # A target the seed maker has nothing for runs from its corpus alone.
    mkdir -p "$corpus" "$crashes" "$found" "$build/seeds/$target"
    local dict=()
    [[ $(max_len "$target") -gt 1024 ]] && dict=(-dict="$here/json.dict")
    local limit=()
    [[ -n ${FUZZ_MAX_SECONDS:-} ]] && limit=(-max_total_time="$FUZZ_MAX_SECONDS")
    local before
    before=$(find "$crashes" -type f | wc -l)
    local start=$SECONDS
    # New inputs go to $found; the committed corpus is only read. No allocation stacks: the
    # frame-pointer unwinder walks into Qt (built without frame pointers) and stores a new,
    # garbage stack at nearly every allocation, which grows the process by kilobytes per input
    # (out of memory after a million) and halves the speed. Leaks and errors are still caught
    # and their input saved: run the target on it alone for the full report.
    ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1:malloc_context_size=0 \
    UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
        nice -n 19 "$program" -runs="$runs" -max_len="$(max_len "$target")" -timeout=30 \
        -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$crashes/" "${dict[@]}" \
        "${limit[@]}" "$found" "$corpus" "$build/seeds/$target" > "$log" 2>&1 || true
    local seconds=$((SECONDS - start))
    # The corpus again, minimized over the old inputs and the new ones together.
    local merged=$campaign/$target/merged
    rm -rf "$merged" && mkdir -p "$merged"
    if nice -n 19 "$program" -merge=1 -max_len="$(max_len "$target")" "$merged" "$corpus" \
        "$found" "$build/seeds/$target" > "$campaign/$target.merge.log" 2>&1; then
        rm -rf "$corpus" && mv "$merged" "$corpus"
    fi
    local executions
    executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    [[ -z $executions ]] && executions=$(grep -o '^#[0-9]*' "$log" | tail -1 | tr -d '#')
    local crashed=$(($(find "$crashes" -type f | wc -l) - before))
    local leaks sanitizer
    leaks=$(grep -c 'ERROR: LeakSanitizer' "$log" || true)
    sanitizer=$(grep -cE 'ERROR: AddressSanitizer|runtime error:|ERROR: UndefinedBehaviorSanitizer' "$log" || true)
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$target" "${executions:-0}" "$seconds" "$crashed" \
        "$leaks" "$sanitizer" "$(find "$corpus" -type f | wc -l)" > "$campaign/$target.row"
}
export -f run_target max_len
export build campaign here runs

# The first seeds (spec frames, shipped tables, the tests' files) are offered at every run: the
# merge keeps those that still add something.
mkdir -p "$campaign"
python3 "$here/make-seeds.py" "$build/seeds"
printf '%s\n' "${targets[@]}" | xargs -P "${FUZZ_PARALLEL:-1}" -I{} bash -c 'run_target {}'

{
    printf '| %-20s | %12s | %8s | %7s | %5s | %17s | %6s |\n' target executions seconds \
        crashes leaks "sanitizer reports" corpus
    printf '|%s|%s|%s|%s|%s|%s|%s|\n' ---------------------- -------------: ---------: \
        --------: ------: ------------------: -------:
    for target in "${targets[@]}"; do
        IFS=$'\t' read -r name executions seconds crashed leaks sanitizer corpus \
            < "$campaign/$target.row"
        printf '| %-20s | %12s | %8s | %7s | %5s | %17s | %6s |\n' "$name" "$executions" \
            "$seconds" "$crashed" "$leaks" "$sanitizer" "$corpus"
    done
} | tee "$campaign/table.md"
echo "logs: $campaign/<target>.log; failing inputs: fuzz/crashes/<target>/"
