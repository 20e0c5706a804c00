#!/usr/bin/env bash
# Renders SCENE in CHUNKS chunks with GNU Parallel, then joins them into the render folder that
# one `tumble render SCENE -o OUTPUT` would write (OUTPUT/<scene folder>/).
#
#   render.sh SCENE CHUNKS [OUTPUT]        (OUTPUT defaults to output)
#
# TUMBLE names the tumble executable (default: tumble on PATH), JOBS how many chunks run at once
# (default: GNU Parallel's, one per CPU thread). GNU Parallel's own options, such as
# --sshloginfile, go in the PARALLEL environment variable (see README.md beside this file).
# Exit status: 0 when the joined render is in place, else non-zero with nothing new left in OUTPUT.
set -euo pipefail

if [ "$#" -lt 2 ] || [ "$#" -gt 3 ]; then
  echo "usage: $0 SCENE CHUNKS [OUTPUT]" >&2
  exit 2
fi
# Absolute paths, so that a job on another machine (--sshlogin) finds the same shared files.
scene=$(realpath -m -- "$1")
chunks=$2
output=$(realpath -m -- "${3:-output}")
tumble=${TUMBLE:-tumble}
[[ "$tumble" != */* ]] || tumble=$(realpath -m -- "$tumble")

# The plan first: a bad scene or more chunks than frames stops here with tumble's message and
# exit status, before any folder is made. Each line is one chunk's frame range, A:B.
plan=$("$tumble" plan "$scene" --chunks "$chunks")

# Chunks render into a folder of their own inside OUTPUT (so on the same storage as the result),
# removed however the script ends, with OUTPUT itself if the script made it and it stayed empty.
created=
[ -d "$output" ] || created=$output
mkdir -p "$output"
work=$(mktemp -d "$output/.chunks.XXXXXX")
trap 'rm -rf "$work"; [ -z "$created" ] || rmdir "$created" 2>/dev/null || true' EXIT

# One job per plan line; {#} is the job's sequence number, 1..CHUNKS, which --chunk takes as I.
# --halt now,fail=1: the first failed chunk stops the others, as the join could not use them.
# -q quotes each word, so paths with spaces or shell characters reach tumble unchanged.
parallel --halt now,fail=1 -j "${JOBS:-100%}" -q \
  "$tumble" render "$scene" --chunk "{#}/$chunks" -o "$work" -q <<<"$plan"

# join-chunks.sh (beside this folder) checks and joins the chunks into OUTPUT/<scene folder>/.
TUMBLE=$tumble "$(dirname "$0")/../join-chunks.sh" "$work" "$chunks" "$output"
