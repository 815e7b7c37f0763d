#!/bin/sh
# Checks that two grotto binaries render identically: every shipped world's
# cameras through `render`, every path through `flythrough` (PNG, and EXR with
# all AOVs) and `stability`. Images must match byte for byte; the JSON outputs
# must match once timings, paths and dates are removed.
# Usage: scripts/identical.sh OLD_GROTTO NEW_GROTTO [WORKDIR]
# Exit 0 when identical, 1 when any output differs (each difference is listed).
set -eu
old=$(realpath "$1"); new=$(realpath "$2")
work=${3:-$(mktemp -d)}
root=$(cd "$(dirname "$0")/.." && pwd)
size=${IDENTICAL_SIZE:-160x90}
mkdir -p "$work/old" "$work/new"

# One command line per output; run by both binaries into their own folder.
jobs="$work/jobs.txt"
python3 - "$root/worlds" >"$jobs" <<'EOF'
import json, os, sys
worlds = sys.argv[1]
for name in sorted(os.listdir(worlds)):
    if not name.endswith('.json'):
        continue
    desc = json.load(open(os.path.join(worlds, name)))
    if 'grid' not in desc and 'generator' not in desc:
        continue  # a path file, not a world
    stem = name[:-5]
    for cam in desc.get('cameras', []):
        cam = cam['name'] if isinstance(cam, dict) else cam
        print(f"render|{stem}-{cam}.png|render worlds/{name} --camera {cam} --accumulate 4 -o OUT")
        print(f"render|{stem}-{cam}.exr|render worlds/{name} --camera {cam} --accumulate 2 --aov -o OUT")
    for ao in ('voxel', 'hybrid', 'ssao', 'hbao'):
        print(f"render|{stem}-{ao}.png|render worlds/{name} --ao {ao} --accumulate 2 -o OUT")
    print(f"render|{stem}-off.png|render worlds/{name} --ao off -o OUT")
    for path in desc.get('paths', {}):
        print(f"flythrough|{stem}-{path}-png|flythrough worlds/{name} --path {path} --fps 8 --warmup 2 --quiet -o OUT")
        print(f"flythrough|{stem}-{path}-exr|flythrough worlds/{name} --path {path} --fps 4 --warmup 1 --format exr --quiet -o OUT")
        print(f"stability|{stem}-{path}.json|stability worlds/{name} --path {path} --fps 8 --spp 8 --reference-every 8 --quiet --json OUT")
EOF

run() {  # binary folder
    while IFS='|' read -r kind out args; do
        target="$2/$out"
        # shellcheck disable=SC2086
        (cd "$root" && "$1" $(echo "$args" | sed "s|OUT|$target|") --size "$size") >"$target.log" 2>&1 ||
            echo "$1 failed: $args" >>"$2/failures.txt"
    done <"$jobs"
}
run "$old" "$work/old"
run "$new" "$work/new"

status=0
[ -f "$work/old/failures.txt" ] && { cat "$work/old/failures.txt"; status=1; }
[ -f "$work/new/failures.txt" ] && { cat "$work/new/failures.txt"; status=1; }
python3 - "$work/old" "$work/new" <<'EOF' || status=1
import json, os, sys, filecmp
old, new = sys.argv[1:3]
volatile = ('ms', 'seconds', 'time', 'date', 'path', 'output', 'json', 'binary', 'version', 'timestamp')
def exr_bytes(path):
    # An EXR's capDate attribute is the time it was written: blank its value.
    data = bytearray(open(path, 'rb').read())
    key = b'capDate\0string\0'
    at = data.find(key)
    if at >= 0:
        start = at + len(key)
        size = int.from_bytes(data[start:start + 4], 'little')
        data[start + 4:start + 4 + size] = bytes(size)
    return bytes(data)
def strip(v):
    if isinstance(v, dict):
        return {k: strip(x) for k, x in v.items() if not any(t in k for t in volatile)}
    if isinstance(v, list):
        return [strip(x) for x in v]
    return v
bad = compared = 0
for dirpath, _, files in os.walk(old):
    for f in sorted(files):
        if f.endswith('.log') or f == 'failures.txt':
            continue
        a = os.path.join(dirpath, f)
        b = os.path.join(new, os.path.relpath(a, old))
        compared += 1
        if not os.path.exists(b):
            print('missing in new:', os.path.relpath(a, old)); bad += 1
        elif f.endswith('.json'):
            if strip(json.load(open(a))) != strip(json.load(open(b))):
                print('differs:', os.path.relpath(a, old)); bad += 1
        elif f.endswith('.exr'):
            if exr_bytes(a) != exr_bytes(b):
                print('differs:', os.path.relpath(a, old)); bad += 1
        elif not filecmp.cmp(a, b, shallow=False):
            print('differs:', os.path.relpath(a, old)); bad += 1
print(f'{compared} outputs compared, {bad} differ')
sys.exit(1 if bad else 0)
EOF
exit $status
