#!/usr/bin/env bash
# slurm.sh VITRINE OUTDIR: a film split across a real scheduler renders what one run renders. Starts its
# own single-node Slurm (munged with a fresh key, slurmctld and slurmd, every file under OUTDIR, free
# ports), submits scripts/slurm-film.sbatch for a 1 s neon film: its checkpoint job, 3 array tasks that
# start from those checkpoints, and its encode job, and holds each of the 30 frames to the same frame
# of a whole `vitrine record` run: max difference 0. Then
# the encode job's film.mp4 has 30 frames, when this vitrine has an encode mode (else that check alone
# is skipped, saying so). Slurm that cannot start here (not root, no munge, a daemon that refuses)
# skips the test (exit 77) with the reason; the trap stops every daemon it started.
set -euo pipefail
umask 022
vitrine=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
rm -rf "$2"; mkdir -p "$2"
out=$(cd "$2" && pwd)
started=$SECONDS

skip() { echo "SKIPPED: $*"; exit 77; }
fail() { echo "FAIL: $*" >&2; exit 1; }
tail_logs() { for log in "$@"; do [ -s "$log" ] && { echo "--- last lines of $log"; tail -n 15 "$log"; }; done; return 0; }

# A test run inside a Slurm job must not talk to that cluster, or look like an array task to the script.
while read -r name; do unset "$name"; done < <(compgen -e | grep -E '^(SLURM|SBATCH|SALLOC|SRUN)_' || true)

[ "$(id -u)" = 0 ] || skip "not root: slurmd starts jobs as their users and must run as root"
for tool in munged slurmctld slurmd sbatch squeue sinfo scontrol scancel; do
  command -v "$tool" >/dev/null || skip "$tool is not installed (Debian: slurm-wlm munge)"
done

# The reference first, before any daemon: the whole film in one run.
film=(--scene neon --size 64x36 --fps 30 --seconds 1 --spp 2 --set chains=256)
"$vitrine" record "${film[@]}" --out "$out/whole" >"$out/whole.log" 2>&1 || { cat "$out/whole.log"; fail "the whole run failed"; }

# --- daemons, each stopped by the trap whatever happens -------------------------------------------------
declare -A pids=()
pidfile() { case $1 in munged) echo "$out/munge/munged.pid" ;; *) echo "$out/slurm/$1.pid" ;; esac; }
remember() { [ -s "$(pidfile "$1")" ] && pids[$1]=$(cat "$(pidfile "$1")"); return 0; }
jobs_submitted=()
sockdir=
cleanup() {
  local rc=$?
  set +e
  if [ -n "${pids[slurmctld]:-}" ] && ((${#jobs_submitted[@]})); then
    scancel "${jobs_submitted[@]}" 2>/dev/null
    for _ in $(seq 30); do  # KillWait is 2 s: the steps end well before this
      [ -z "$(squeue -h -o %i 2>/dev/null)" ] && break
      sleep 0.5
    done
  fi
  local stopping=$SECONDS
  for daemon in slurmd slurmctld munged; do
    remember "$daemon"
    local pid=${pids[$daemon]:-}
    if [ -z "$pid" ] || ! kill -0 "$pid" 2>/dev/null; then continue; fi
    kill "$pid"
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    if kill -0 "$pid" 2>/dev/null; then echo "$daemon ($pid) ignored SIGTERM: killing it"; kill -9 "$pid"; fi
  done
  [ -n "$sockdir" ] && rm -rf "$sockdir"
  echo "daemons stopped in $((SECONDS - stopping)) s"
  exit "$rc"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
wait_for() {  # SECONDS COMMAND...: true once COMMAND succeeds
  local deadline=$((SECONDS + $1)); shift
  until "$@" >/dev/null 2>&1; do ((SECONDS < deadline)) || return 1; sleep 0.2; done
}

# munge: a fresh key and a daemon of our own (socket, key, pid, log and seed under OUTDIR), never the
# system's. The socket's folder must be reachable by all; a socket path is at most 107 bytes.
mkdir -p "$out/munge" "$out/slurm/state" "$out/slurm/spool" "$out/slurm/log"
key=$out/munge/munge.key
# (mungekey where munge has it; create-munge-key, its older form, writes only /etc/munge's key: not used.)
if command -v mungekey >/dev/null; then mungekey --create --keyfile="$key" >/dev/null 2>&1 || true; fi
[ -s "$key" ] || dd if=/dev/urandom of="$key" bs=1024 count=1 status=none 2>/dev/null || true
[ -s "$key" ] || skip "could not make a munge key in $out/munge"
chmod 600 "$key"
socket=$out/munge/munge.socket
if ((${#socket} > 100)); then
  sockdir=$(mktemp -d /tmp/vitrine-munge.XXXXXX); chmod 755 "$sockdir"; socket=$sockdir/munge.socket
fi
# --force: the test's key is private to it, and a build tree may sit under group-writable folders.
munged --force --socket="$socket" --key-file="$key" --pid-file="$(pidfile munged)" --log-file="$out/munge/munged.log" \
  --seed-file="$out/munge/munged.seed" </dev/null >>"$out/munge/munged.out" 2>&1 ||
  { tail_logs "$out/munge/munged.out" "$out/munge/munged.log"; skip "munged did not start"; }
wait_for 10 test -s "$(pidfile munged)" || { tail_logs "$out/munge/munged.log"; skip "munged wrote no pid file"; }
remember munged
wait_for 10 test -S "$socket" || { tail_logs "$out/munge/munged.log"; skip "munged made no socket"; }

# Slurm: one node, this host, on two free ports; no cgroups, no accounting (jobcomp/filetxt keeps each
# job's end), every path under OUTDIR.
read -r ctld_port slurmd_port < <(python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*(x.getsockname()[1] for x in s))')
node=$(hostname -s)
conf=$out/slurm/slurm.conf
: >"$out/slurm/plugstack.conf"  # not /etc/slurm's
cat >"$conf" <<EOF
ClusterName=vitrinetest
SlurmctldHost=$node(127.0.0.1)
SlurmUser=$(id -un)
SlurmdUser=root
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
AuthType=auth/munge
AuthInfo=socket=$socket
CredType=cred/munge
StateSaveLocation=$out/slurm/state
SlurmdSpoolDir=$out/slurm/spool
SlurmctldPidFile=$(pidfile slurmctld)
SlurmdPidFile=$(pidfile slurmd)
SlurmctldLogFile=$out/slurm/log/slurmctld.log
SlurmdLogFile=$out/slurm/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
PlugStackConfig=$out/slurm/plugstack.conf
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/filetxt
JobCompLoc=$out/slurm/log/jobcomp.txt
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/builtin
DependencyParameters=kill_invalid_depend
MpiDefault=none
ReturnToService=2
KillWait=2
MailProg=/bin/true
NodeName=$node NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=film Nodes=$node Default=YES DefaultTime=5 MaxTime=10 State=UP
EOF
export SLURM_CONF=$conf
slurmctld -f "$conf" </dev/null >>"$out/slurm/log/slurmctld.out" 2>&1 ||
  { tail_logs "$out/slurm/log/slurmctld.out" "$out/slurm/log/slurmctld.log"; skip "slurmctld refused to start"; }
wait_for 15 test -s "$(pidfile slurmctld)" || { tail_logs "$out/slurm/log/slurmctld.log"; skip "slurmctld wrote no pid file"; }
remember slurmctld
wait_for 15 sh -c 'scontrol ping | grep -q UP' ||
  { tail_logs "$out/slurm/log/slurmctld.log"; skip "slurmctld does not answer (scontrol ping)"; }
slurmd -f "$conf" </dev/null >>"$out/slurm/log/slurmd.out" 2>&1 ||
  { tail_logs "$out/slurm/log/slurmd.out" "$out/slurm/log/slurmd.log"; skip "slurmd refused to start"; }
wait_for 15 test -s "$(pidfile slurmd)" || { tail_logs "$out/slurm/log/slurmd.log"; skip "slurmd wrote no pid file"; }
remember slurmd
node_idle() { [ "$(sinfo -h -n "$node" -o %T)" = idle ]; }
wait_for 30 node_idle ||
  { sinfo -N; tail_logs "$out/slurm/log/slurmd.log" "$out/slurm/log/slurmctld.log"; skip "node $node never became idle"; }
echo "slurm up in $((SECONDS - started)) s (node $node, ports $ctld_port and $slurmd_port)"

# --- the film, split in 3 array tasks, and its encode job ----------------------------------------------
encode_available=0
# (The help read whole first: grep -q quitting early would make the pipe fail under pipefail.)
grep -q 'vitrine encode' <<<"$("$vitrine" --help 2>&1)" && encode_available=1
(
  cd "$out"
  export VITRINE=$vitrine FILM_SCENE=neon FILM_SECONDS=1 FILM_FPS=30 FILM_SIZE=64x36 FILM_SPP=2 FILM_TASKS=3 \
    FILM_FOLDER=$out/film FILM_MP4=$out/film.mp4 FILM_ARGS="--set chains=256"
  "$root/scripts/slurm-film.sbatch"
) | tee "$out/submit.log"
checkpoints=$(sed -n 's/^submitted checkpoint job \([0-9]*\):.*/\1/p' "$out/submit.log")
array=$(sed -n 's/^submitted array job \([0-9]*\):.*/\1/p' "$out/submit.log")
encode=$(sed -n 's/^submitted encode job \([0-9]*\):.*/\1/p' "$out/submit.log")
[ -n "$checkpoints" ] || fail "the script submitted no checkpoint job"
[ -n "$array" ] || fail "the script submitted no array job"
jobs_submitted=("$checkpoints" "$array" ${encode:+"$encode"})
if ((encode_available)); then
  [ -n "$encode" ] || fail "vitrine has an encode mode but the script submitted no encode job"
else
  grep -q "no encode job: .* has no encode mode" "$out/submit.log" || fail "the script did not say why it skipped encoding"
fi

pending() { [ -n "$(squeue -h -j "$(IFS=,; echo "${jobs_submitted[*]}")" -o %i 2>/dev/null)" ]; }
deadline=$((SECONDS + 200))
while pending; do
  ((SECONDS < deadline)) || { squeue; tail_logs "$out"/vitrine-film-*.out "$out/slurm/log/slurmd.log"; fail "jobs still queued after 200 s"; }
  sleep 0.5
done
echo "jobs done $((SECONDS - started)) s in"
scontrol -o show job "$checkpoints" | grep -q 'JobState=COMPLETED .* ExitCode=0:0' ||
  { tail_logs "$out"/vitrine-checkpoints-*.out; fail "the checkpoint job did not complete: $(scontrol -o show job "$checkpoints")"; }
# Every task, and the encode job, ended COMPLETED with exit code 0 (scontrol keeps ended jobs MinJobAge, 300 s).
states=$(scontrol -o show job "$array" | grep -o 'ArrayTaskId=[0-9]*\|JobState=[A-Z_]*\|ExitCode=[0-9:]*' | paste -sd' ')
tasks_ok=$(scontrol -o show job "$array" | grep -c 'JobState=COMPLETED .* ExitCode=0:0' || true)
[ "$tasks_ok" = 3 ] || { tail_logs "$out"/vitrine-film-*.out; fail "not 3 tasks COMPLETED with exit 0: $states"; }
for i in 0 1 2; do
  log=$out/vitrine-film-${array}_$i.out
  first=$((i * 10))
  grep -q "recorded 10 of frames $first..$((first + 9)) into $out/film" "$log" ||
    { tail_logs "$log"; fail "task $i did not render frames $first..$((first + 9))"; }
  ((i == 0)) || grep -q "simulated from the checkpoint at frame $first" "$log" ||
    { tail_logs "$log"; fail "task $i did not start from the checkpoint at frame $first"; }
done

# The split film is the whole film, frame for frame, and nothing else was left in its folder.
# (Four compares at a time: each is mostly its start-up.)
mkdir -p "$out/compare"
for f in $(seq 0 29); do
  name=$(printf 'frame_%06d.exr' "$f")
  [ -s "$out/film/$name" ] || fail "$name is missing from the split film"
  "$vitrine" compare --fail-fraction 0 --hard-limit 0 "$out/whole/$name" "$out/film/$name" >"$out/compare/$name.txt" 2>&1 &
  if ((f % 4 == 3)); then wait; fi
done
wait
for f in $(seq 0 29); do
  name=$(printf 'frame_%06d.exr' "$f")
  grep -q "^pass" "$out/compare/$name.txt" ||
    { cat "$out/compare/$name.txt"; fail "$name differs from the whole run's"; }
done
listing=$(ls -A "$out/film")
# shellcheck disable=SC2046
[ "$listing" = "$(printf 'checkpoint_%06d.state\n' 10 20; printf 'frame_%06d.exr\n' $(seq 0 29); echo record.json)" ] ||
  fail "the film's folder holds more than its 2 checkpoints, 30 frames and record.json: $(echo "$listing" | paste -sd' ')"
echo "30 frames from 3 array tasks equal the whole run's"

if ((encode_available)); then
  scontrol -o show job "$encode" | grep -q 'JobState=COMPLETED .* ExitCode=0:0' ||
    { tail_logs "$out"/vitrine-encode-*.out; fail "the encode job did not complete: $(scontrol -o show job "$encode")"; }
  [ -s "$out/film.mp4" ] || fail "the encode job wrote no film.mp4"
  if command -v ffprobe >/dev/null; then
    n=$(ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 "$out/film.mp4")
    [ "$n" = 30 ] || fail "film.mp4 has $n frames, not 30"
    echo "film.mp4: 30 frames"
  else
    echo "SKIPPED encode frame count: no ffprobe"
  fi
else
  echo "SKIPPED encode check: this vitrine has no encode mode ('vitrine encode' is not in --help)"
fi
echo "slurm ok in $((SECONDS - started)) s"
