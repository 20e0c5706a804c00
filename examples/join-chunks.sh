#!/usr/bin/env bash
# Joins the chunk folders that `tumble render SCENE --chunk I/N -o WORK` left in WORK into the
# render folder OUTPUT/<scene folder>/. Both examples end with it: parallel/render.sh runs it,
# slurm/submit.sh submits it as the join job (the #SBATCH line is read by sbatch only).
#
#   join-chunks.sh WORK CHUNKS OUTPUT
#
# TUMBLE names the tumble executable (default: tumble on PATH).
#SBATCH --job-name=tumble-join
set -euo pipefail

if [ "$#" -ne 3 ]; then
  echo "usage: $0 WORK CHUNKS OUTPUT" >&2
  exit 2
fi
work=$1
chunks=$2
output=$3

# Chunk I is in <scene folder>.chunk-I-of-N (the scene folder may hold slashes): the folder is
# named from chunk 1, then every chunk is listed in order, so that join names any that is missing.
first=$(cd "$work" && find . -type d -name "*.chunk-1-of-$chunks" -print -quit)
if [ -z "$first" ]; then
  echo "$0: no chunk folder *.chunk-1-of-$chunks in $work" >&2
  exit 2
fi
folder=${first#./}
folder=${folder%.chunk-1-of-"$chunks"}
chunk_folders=()
for ((i = 1; i <= chunks; i++)); do
  chunk_folders+=("$work/$folder.chunk-$i-of-$chunks")
done

# join checks the chunks (same scene and settings, every frame once) and writes the render folder
# whole or not at all.
exec "${TUMBLE:-tumble}" join "$output/$folder" "${chunk_folders[@]}"
