#!/usr/bin/env bash
# Submits a chunked render to Slurm: a job array of CHUNKS tasks (chunk.sbatch), a join job that
# runs once every task has succeeded (../join-chunks.sh), and a cleanup job that removes the chunk
# folders after the join, whatever became of it. The result is OUTPUT/<scene folder>/, as one
# `tumble render SCENE -o OUTPUT` would write it.
#
#   submit.sh SCENE CHUNKS [OUTPUT]        (OUTPUT defaults to output)
#
# SCENE, OUTPUT and tumble (TUMBLE, default: tumble on PATH) must be at the same paths on every
# node: jobs get the submitting shell's environment (sbatch's default --export=ALL), so TUMBLE
# reaches them. sbatch's own settings come from its environment (SBATCH_PARTITION,
# SBATCH_ACCOUNT, SBATCH_TIMELIMIT, ...). Prints "array ID", "join ID" and "cleanup ID", one a
# line. Exit status 0 once all three are submitted; otherwise none is left queued.
set -euo pipefail

if [ "$#" -lt 2 ] || [ "$#" -gt 3 ]; then
  echo "usage: $0 SCENE CHUNKS [OUTPUT]" >&2
  exit 2
fi
here=$(dirname "$(realpath -- "$0")")
scene=$(realpath -m -- "$1")
chunks=$2
output=$(realpath -m -- "${3:-output}")
tumble=${TUMBLE:-tumble}
[[ "$tumble" != */* ]] || tumble=$(realpath -m -- "$tumble")
export TUMBLE=$tumble

# A bad scene or more chunks than frames stops here with tumble's message, before any job.
"$tumble" plan "$scene" --chunks "$chunks" >/dev/null

# The chunks' folder, on the shared storage of the result; the cleanup job removes it.
created=
[ -d "$output" ] || created=$output
mkdir -p "$output"
work=$(mktemp -d "$output/.chunks.XXXXXX")

# Until the cleanup job is queued, a failure here cancels what was submitted and removes WORK
# (and OUTPUT if this script made it).
submitted=()
trap '[ "${#submitted[@]}" -eq 0 ] || scancel "${submitted[@]}"
  rm -rf "$work"; [ -z "$created" ] || rmdir "$created" 2>/dev/null || true' EXIT

# --parsable prints "ID" or "ID;CLUSTER".
array=$(sbatch --parsable --array="1-$chunks" "$here/chunk.sbatch" "$scene" "$chunks" "$work")
array=${array%%;*}
submitted+=("$array")

# afterok on an array waits for every task to exit 0. --kill-on-invalid-dep=yes: when a task
# fails, the dependency can never be met, and without it Slurm leaves the join PENDING for ever
# (Reason=DependencyNeverSatisfied) instead of cancelling it.
join=$(sbatch --parsable --dependency="afterok:$array" --kill-on-invalid-dep=yes \
  "$here/../join-chunks.sh" "$work" "$chunks" "$output")
join=${join%%;*}
submitted+=("$join")

# afterany: also after a join that failed or was cancelled, so no chunk folders are left behind.
cleanup=$(sbatch --parsable --dependency="afterany:$join" --job-name=tumble-cleanup \
  --wrap="rm -rf $(printf '%q' "$work")")
cleanup=${cleanup%%;*}
trap - EXIT

printf 'array %s\njoin %s\ncleanup %s\n' "$array" "$join" "$cleanup"
