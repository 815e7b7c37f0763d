#!/bin/bash
# docs/farm.md's Slurm recipes on a real one-node cluster: munge with a fresh key,
# slurmctld and slurmd on localhost, ports and every file in a temporary
# directory, all stopped at the end whatever happens. The blocks tagged
# walk.sbatch, bake.sbatch, merge.sbatch, slurm-walk, slurm-bake, slurm-requeue
# and completion-check run as the docs give them, with the changes the docs'
# last section lists: /shared is the scratch directory, --size 32x18,
# --array=1-4, and worlds/ a tiny world with a 7-frame walk.
# Checks: the array's frames are a one-machine run's byte for byte; a task
# killed and requeued completes them with nothing lost or written twice; the
# parts' merge (after the array, by --dependency=afterok) is a one-machine bake
# byte for byte; the completion check counts every frame.
# Skipped (exit 77) without root or the Slurm and munge programs, or where the
# daemons do not come up.
#   test_farm_slurm.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(cd "$1" && pwd) source=$(cd "$2" && pwd)
skip() { echo "SKIP: $*"; exit 77; }
fail() { echo "docs/farm.md: $*" >&2; exit 1; }

[ "$(id -u)" -eq 0 ] || skip "the daemons run as root; run as root to test the Slurm recipes"
for tool in munged mungekey slurmctld slurmd sbatch squeue scontrol scancel sinfo python3 flock; do
    command -v "$tool" >/dev/null || skip "$tool is missing (scripts/setup.sh installs slurm-wlm and munge)"
done

scratch=$(mktemp -d)
chmod 755 "$scratch"
export SLURM_CONF="$scratch/slurm.conf"
stop() {
    set +e
    if [ -e "$scratch/slurmctld.pid" ]; then
        scancel --quiet --user=root 2>/dev/null
        scontrol shutdown >/dev/null 2>&1
    fi
    for pidfile in slurmd.pid slurmctld.pid munged.pid; do
        pid=$(cat "$scratch/$pidfile" 2>/dev/null) || continue
        kill "$pid" 2>/dev/null
        for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    done
    rm -rf "$scratch"
}
trap stop EXIT
logs() { tail -n 15 "$scratch"/*.log "$run"/logs/* 2>/dev/null >&2 || true; }

# --- the cluster --------------------------------------------------------------
mungekey --create --keyfile="$scratch/munge.key" >/dev/null
chmod 600 "$scratch/munge.key"
munged --force --key-file="$scratch/munge.key" --socket="$scratch/munge.sock" --pid-file="$scratch/munged.pid" \
    --log-file="$scratch/munged.log" --seed-file="$scratch/munged.seed" ||
    skip "munged does not start: $(tail -n 1 "$scratch/munged.log" 2>/dev/null)"
read -r ctld_port slurmd_port < <(python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*[x.getsockname()[1] for x in s])')
node=$(hostname -s)
mkdir "$scratch/state" "$scratch/spool"
# A requeued task waits out the credential's lifetime (cred_expire, 120 s by
# default) before it starts again, and then the scheduler's next pass
# (sched_interval, 60 s): 5 s and 1 s here. One node that claims enough CPUs and memory for the recipes' requests
# (config_overrides: Slurm takes them from here, not from the machine).
cat > "$SLURM_CONF" <<EOF
ClusterName=grottotest
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$scratch/munge.sock,cred_expire=5
StateSaveLocation=$scratch/state
SlurmdSpoolDir=$scratch/spool
SlurmctldPidFile=$scratch/slurmctld.pid
SlurmdPidFile=$scratch/slurmd.pid
SlurmctldLogFile=$scratch/slurmctld.log
SlurmdLogFile=$scratch/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SwitchType=switch/none
MpiDefault=none
SchedulerType=sched/builtin
SchedulerParameters=sched_interval=1
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SlurmdParameters=config_overrides
ReturnToService=2
NodeName=$node NodeAddr=127.0.0.1 CPUs=64 RealMemory=65536 State=UNKNOWN
PartitionName=farm Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF
slurmctld -i >/dev/null 2>&1 || skip "slurmctld does not start: $(tail -n 1 "$scratch/slurmctld.log" 2>/dev/null)"
slurmd >/dev/null 2>&1 || skip "slurmd does not start: $(tail -n 1 "$scratch/slurmd.log" 2>/dev/null)"
for _ in $(seq 100); do
    [ "$(sinfo -h -o %t 2>/dev/null)" = idle ] && break
    sleep 0.2
done
[ "$(sinfo -h -o %t 2>/dev/null)" = idle ] || skip "the node did not come up: $(tail -n 1 "$scratch/slurmd.log")"

# --- the recipes, as docs/farm.md gives them ----------------------------------
run="$scratch/shared"  # /shared
mkdir -p "$run/grotto/worlds"
ln -s "$build" "$run/grotto/build"
unset GROTTO_SHADER_DIR
"$build/grotto" mkworld sphere --size 12 -o "$run/grotto/worlds/tiny.vdb" >/dev/null
for world in caves big; do
    cat > "$run/grotto/worlds/$world.json" <<'EOF'
{"grid": {"file": "tiny.vdb"}, "paths": {"walk": {"keys": [
  {"time": 0, "position": [6, 14, 30], "target": [6, 6, 6]},
  {"time": 0.25, "position": [24, 10, 20], "target": [6, 6, 6]}]}}}
EOF
done
frames=7  # floor(0.25 s x 24 fps) + 1

# The block tagged $1, changed as the docs' last section says.
block() {
    awk -v tag="$1" '$0 == "```sh " tag { run = 1; next } /^```/ { run = 0 } run' "$source/docs/farm.md" |
        sed -E -e "s#/shared/#$run/#g" -e 's/--size [0-9]+x[0-9]+/--size 32x18/g' -e 's/--array=1-8/--array=1-4/'
}
for tag in walk.sbatch bake.sbatch merge.sbatch slurm-walk slurm-bake slurm-requeue completion-check; do
    block "$tag" > "$run/grotto/$tag"
    [ -s "$run/grotto/$tag" ] || fail "no \`\`\`sh $tag block"
done
cd "$run/grotto"

# Every task and job of these ids has left the queue (60 s at most).
wait_for() {
    for _ in $(seq 300); do
        [ -z "$(squeue -h -j "$1" 2>/dev/null)" ] && return
        sleep 0.2
    done
    logs
    fail "jobs $1 still queued after 60 s: $(squeue -h -j "$1")"
}
# A task's state (RUNNING, CANCELLED, COMPLETED...).
state() { scontrol show job "$1" | sed -nE 's/.*JobState=([A-Z_]+).*/\1/p'; }

# The one-machine runs to compare with.
"$build/grotto" flythrough worlds/caves.json --path walk --size 32x18 --quiet -o "$scratch/one/walk" >/dev/null
"$build/grotto" bake worlds/big.json -o "$scratch/one/big.gfc" >/dev/null 2>&1

# The walk, with task 3 killed and requeued. The tasks wait for the directory's
# lock, held here, so the kill lands before task 3 has written anything and the
# others finish while it is gone.
mkdir -p "$run/walk"
exec 9> "$run/walk/.flythrough.lock"
flock 9
source ./slurm-walk
for _ in $(seq 300); do [ "$(state "${walk}_3" 2>/dev/null)" = RUNNING ] && break; sleep 0.2; done
[ "$(state "${walk}_3")" = RUNNING ] || { logs; fail "task ${walk}_3 did not start"; }
grep -v requeue slurm-requeue > slurm-kill   # the recipe's scancel, now
source ./slurm-kill
for _ in $(seq 100); do [ "$(state "${walk}_3")" = CANCELLED ] && break; sleep 0.1; done
[ "$(state "${walk}_3")" = CANCELLED ] || fail "task ${walk}_3 is $(state "${walk}_3") after scancel"
exec 9>&-
wait_for "$walk"
[ ! -e "$run/walk/frame.0005.png" ] || fail "the killed task wrote its frames"  # chunk 3/4: frames 5 and 6
before=$(cd "$run/walk" && stat -c '%n %i %Y' frame.*.png)
grep requeue slurm-requeue > slurm-again     # and its requeue, once the others are done
source ./slurm-again
wait_for "$walk"
for k in 1 2 3 4; do
    [ "$(state "${walk}_$k")" = COMPLETED ] || { logs; fail "task ${walk}_$k is $(state "${walk}_$k")"; }
done
for f in $(cd "$scratch/one/walk" && ls frame.*.png); do
    cmp -s "$scratch/one/walk/$f" "$run/walk/$f" || fail "$f of the array differs from the one-machine run's"
done
[ "$(ls "$run/walk" | grep -c '^frame\..*\.png$')" -eq "$frames" ] || fail "the array wrote other frames: $(ls "$run/walk")"
after=$(cd "$run/walk" && stat -c '%n %i %Y' $(echo "$before" | cut -d' ' -f1))
[ "$before" = "$after" ] || fail "the requeued task wrote frames other tasks had written"
grep -q "wrote 2 frames" logs/walk-"${walk}"_3.out || fail "the requeued task: $(tail -n 1 logs/walk-"${walk}"_3.out)"
checked=$(bash ./completion-check | tr -d ' ')
[ "$checked" = "$frames" ] || fail "the completion check counts $checked frames, not $frames"

# The bake by region, and its merge after the array.
source ./slurm-bake > merge.id
merge=$(cat merge.id)
wait_for "$bake,$merge"
[ "$(state "$merge")" = COMPLETED ] || { logs; fail "the merge is $(state "$merge")"; }
cmp -s "$scratch/one/big.gfc" "$run/big.gfc" || fail "the merged bake differs from the one-machine bake"
echo "walk: $frames frames in 4 tasks, one killed and requeued; bake: 4 parts and the merge; all as one machine's"
