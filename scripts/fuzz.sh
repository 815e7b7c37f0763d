#!/usr/bin/env bash
# Fuzzes the world JSON, camera-path JSON, .vdb, baked face cache (.gfc), MagicaVoxel .vox
# and glTF camera readers with libFuzzer, one
# target after another, SECONDS each (default 600), and prints each one's
# executions, speed and crashes. Not part of CI. Corpora grow in out/fuzz/TARGET/corpus
# (git-ignored) from run to run; crash, leak, timeout and out-of-memory inputs are
# written beside them. Reproduce one: build-fuzz/fuzz/fuzz_TARGET FILE
#   scripts/fuzz.sh [SECONDS] [TARGET...]     TARGET: world_json path_json vdb face_cache vox gltf_camera
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
targets=(world_json path_json vdb face_cache vox gltf_camera)
[ $# -gt 1 ] && targets=("${@:2}")

# Fuzzing only: jq to cut inline paths out of the worlds (clang and its runtimes
# are the sanitize preset's too).
scripts/setup.sh jq
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz

seed_dir() {  # the shipped inputs each target starts from
    local dir=out/fuzz/$1/seeds
    rm -rf "$dir" && mkdir -p "$dir"
    case $1 in
        world_json) cp worlds/*.json "$dir"/ ;;
        path_json)
            cp worlds/*-walk.json "$dir"/
            local i=0
            for w in worlds/*.json; do
                jq -c '.paths // {} | .[] | objects' "$w" | while read -r p; do
                    i=$((i + 1)); echo "$p" >"$dir/$(basename "$w" .json)-$i.json"
                done
            done ;;
        vdb) cp worlds/*.vdb "$dir"/ && build-fuzz/fuzz/fuzz_vdb_seeds "$dir" ;;
        face_cache) build-fuzz/fuzz/fuzz_face_cache_seeds "$dir" ;;
        vox) build-fuzz/fuzz/fuzz_vox_seeds "$dir" ;;
        gltf_camera) build-fuzz/fuzz/fuzz_gltf_camera_seeds "$dir" ;;
    esac
    echo "$dir"
}

# The targets write each input to a file under TMPDIR: keep those in memory, and remove them after.
TMPDIR=$(mktemp -d "$( [ -w /dev/shm ] && echo /dev/shm || echo /tmp )/grotto-fuzz.XXXXXX")
export TMPDIR
trap 'rm -rf "$TMPDIR"' EXIT

summary=()
for t in "${targets[@]}"; do
    out=out/fuzz/$t
    mkdir -p "$out/corpus"
    seeds=$(seed_dir "$t")
    dict=() supp=
    case $t in world_json | path_json) dict=(-dict=fuzz/json.dict) ;; esac
    [ "$t" = vdb ] && supp=suppressions=fuzz/lsan.supp  # OpenVDB's own leaks on damaged files
    echo "== fuzz_$t for ${seconds}s (log: $out/log.txt)"
    # Fork mode: a finding is saved and fuzzing goes on for the whole time (a
    # damaged .vdb that makes OpenVDB allocate gigabytes is not the last one looked at).
    LSAN_OPTIONS=$supp build-fuzz/fuzz/fuzz_"$t" "$out/corpus" "$seeds" "${dict[@]}" -max_total_time="$seconds" \
        -fork=1 -ignore_crashes=1 -ignore_ooms=1 -ignore_timeouts=1 \
        -rss_limit_mb=2048 -malloc_limit_mb=512 -timeout=10 -artifact_prefix="$out/" >"$out/log.txt" 2>&1 || true
    # The last status line: "#RUNS: cov: C ft: F corp: N exec/s S oom/timeout/crash: O/T/C time: Ts ..."
    status=$(grep -E '^#[0-9]+: cov:' "$out/log.txt" | tail -1)
    execs=$(sed -E 's/^#([0-9]+):.*/\1/' <<<"$status")
    secs=$(sed -E 's/.* time: ([0-9]+)s.*/\1/' <<<"$status")
    speed=$(( ${execs:-0} / (${secs:-0} > 0 ? secs : 1) ))  # the status line's own exec/s is the last job's
    counts=$(sed -E 's/.*oom\/timeout\/crash: ([0-9\/]+).*/\1/' <<<"$status")
    found=$(find "$out" -maxdepth 1 -type f \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' \
                 -o -name 'oom-*' \) | wc -l)
    line="$t: ${execs:-?} executions, ${speed:-?} exec/s, oom/timeout/crash ${counts:-?}, $found input(s) saved in $out/"
    echo "$line"
    summary+=("$line")
done
echo "== summary"
printf '%s\n' "${summary[@]}"
