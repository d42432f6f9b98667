#!/usr/bin/env bash
# pcl_ext_tiles on a cluster without MPI: the plan here, then the estimates, the tiles, the
# tiles' second pass (segment_variance's section 4) and their grouping of the points left
# out (segment_variance's new segments; neither for the other methods) as Slurm array jobs
# (one task per tile; tile 0 alone first in a pass whose first task reduces what the tiles
# before it saved: the estimates into the plan, the segments joined), then the merge, each
# job waiting for the one before.
# Without sbatch the same steps run here, one after another.
# segment_profiles runs its passes over the parts one at a time, as each depends on what
# the one before found (-method auto's choice, the curve ends): here the script waits for
# every job (sbatch --wait), so keep it running (in a job of its own, or under nohup).
#
#   scripts/tiles_slurm.sh METHOD OUTPUT INPUT... [-- OPTIONS]
#
# OPTIONS are the method's and the plan's (-tile_size, -halo, ...), as pcl_ext_tiles takes
# them. Environment:
#   PCL_EXT_TILES   the tool (default: pcl_ext_tiles on the PATH, else build/apps/pcl_ext_tiles)
#   WORKDIR         the work folder (default: OUTPUT.tiles); kept, for 'resume' after a failure
#   SBATCH_OPTIONS  options for every sbatch call (e.g. "--partition=x --time=1:00:00")
#   THREADS         threads per tile task (default: SLURM_CPUS_PER_TASK in the job, else 0: all)
#
# A task that fails or dies leaves its tile unfinished and the jobs after it do not start:
# 'pcl_ext_tiles merge OUTPUT -workdir WORKDIR' names the tiles left, and
# 'pcl_ext_tiles resume OUTPUT -workdir WORKDIR' runs them and merges.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(dirname "$here")"

if [ $# -lt 3 ] || [ "$1" = "-h" ] || [ "$1" = "--help" ]; then
  sed -n '2,20p' "${BASH_SOURCE[0]}"
  [ $# -ge 1 ] && { [ "$1" = "-h" ] || [ "$1" = "--help" ]; } && exit 0
  exit 2
fi
method="$1"
output="$2"
shift 2
inputs=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
  inputs+=("$1")
  shift
done
[ $# -gt 0 ] && shift # the --
options=("$@")

tool="${PCL_EXT_TILES:-}"
if [ -z "$tool" ]; then
  tool="$(command -v pcl_ext_tiles || true)"
  [ -z "$tool" ] && tool="$root/build/apps/pcl_ext_tiles"
fi
if [ ! -x "$tool" ]; then
  echo "Error: pcl_ext_tiles not found (set PCL_EXT_TILES)." >&2
  exit 1
fi
workdir="${WORKDIR:-$output.tiles}"
threads="${THREADS:-}"
have_sbatch=0
command -v sbatch >/dev/null 2>&1 && have_sbatch=1
# shellcheck disable=SC2206
extra=(${SBATCH_OPTIONS:-})
task_threads="${threads:-\${SLURM_CPUS_PER_TASK:-0}}"
q() { printf '%q' "$1"; }

if [ "$method" = segment_profiles ]; then
  "$tool" plan segment_profiles "${inputs[@]}" -workdir "$workdir" "${options[@]}"
  setting() { awk -v k="$1" '$1 == "setting" && $2 == k { print $3 }' "$workdir/plan.txt"; }
  [ "$have_sbatch" -eq 1 ] || echo "sbatch not found: running the parts here, one after another."
  # A pass over every part, then its reduction, until the plan names the merge.
  while [ "$(setting profile_stage)" != merge ]; do
    stage="$(setting profile_stage)"
    last=$(($(setting profile_part_count) - 1))
    if [ "$have_sbatch" -eq 0 ]; then
      for i in $(seq 0 "$last"); do
        "$tool" part "$i" -workdir "$workdir" -threads "${threads:-0}"
      done
      "$tool" next -workdir "$workdir"
    else
      sbatch --wait --parsable "${extra[@]}" --job-name="pcl_ext_$stage" --array="0-$last" \
        --wrap="$(q "$tool") part \$SLURM_ARRAY_TASK_ID -workdir $(q "$workdir") -threads $task_threads" >/dev/null
      sbatch --wait --parsable "${extra[@]}" --job-name=pcl_ext_next \
        --wrap="$(q "$tool") next -workdir $(q "$workdir")" >/dev/null
    fi
  done
  if [ "$have_sbatch" -eq 0 ]; then
    exec "$tool" merge "$output" -workdir "$workdir"
  fi
  sbatch --wait --parsable "${extra[@]}" --job-name=pcl_ext_merge \
    --wrap="$(q "$tool") merge $(q "$output") -workdir $(q "$workdir")" >/dev/null
  echo "Done: $output"
  exit 0
fi

"$tool" plan "$method" "${inputs[@]}" -workdir "$workdir" "${options[@]}"
tiles=0
while [ -e "$workdir/tile_$tiles.points" ]; do
  tiles=$((tiles + 1))
done
if [ "$tiles" -eq 0 ]; then
  echo "Error: the plan in $workdir has no tile." >&2
  exit 1
fi
last=$((tiles - 1))
# A method with a second pass over the tiles, or a pass grouping the points left out,
# has that pass's results file in the plan's folder.
second_pass=0
[ -e "$workdir/refined.bin" ] && second_pass=1
grow_pass=0
[ -e "$workdir/grown.bin" ] && grow_pass=1

if [ "$have_sbatch" -eq 0 ]; then
  echo "sbatch not found: running the $tiles tiles here, one after another."
  for t in $(seq 0 "$last"); do
    "$tool" estimate "$t" -workdir "$workdir" -threads "${threads:-0}"
  done
  for t in $(seq 0 "$last"); do
    "$tool" tile "$t" -workdir "$workdir" -threads "${threads:-0}"
  done
  if [ "$second_pass" -eq 1 ]; then
    for t in $(seq 0 "$last"); do
      "$tool" refine "$t" -workdir "$workdir" -threads "${threads:-0}"
    done
  fi
  if [ "$grow_pass" -eq 1 ]; then
    for t in $(seq 0 "$last"); do
      "$tool" grow "$t" -workdir "$workdir" -threads "${threads:-0}"
    done
  fi
  exec "$tool" merge "$output" -workdir "$workdir"
fi

estimate=$(sbatch --parsable "${extra[@]}" --job-name=pcl_ext_estimate --array="0-$last" \
  --wrap="$(q "$tool") estimate \$SLURM_ARRAY_TASK_ID -workdir $(q "$workdir") -threads $task_threads")
# A pass over the tiles after job $2: tile 0 alone first (in the tiles' pass it reduces the
# estimates into the plan, in the later passes it joins the segments: what the others read), then
# the other tiles as an array job. Prints the last job's id.
submit_pass() {
  local step="$1" after="$2" job
  job=$(sbatch --parsable "${extra[@]}" --job-name="pcl_ext_$step" \
    --dependency="afterok:$after" \
    --wrap="$(q "$tool") $step 0 -workdir $(q "$workdir") -threads $task_threads")
  job="${job%%;*}"
  if [ "$last" -ge 1 ]; then
    job=$(sbatch --parsable "${extra[@]}" --job-name="pcl_ext_$step" --array="1-$last" \
      --dependency="afterok:$job" \
      --wrap="$(q "$tool") $step \$SLURM_ARRAY_TASK_ID -workdir $(q "$workdir") -threads $task_threads")
    job="${job%%;*}"
  fi
  echo "$job"
}
tile=$(submit_pass tile "${estimate%%;*}")
refine="$tile"
[ "$second_pass" -eq 1 ] && refine=$(submit_pass refine "$tile")
grow="$refine"
[ "$grow_pass" -eq 1 ] && grow=$(submit_pass grow "$refine")
merge=$(sbatch --parsable "${extra[@]}" --job-name=pcl_ext_merge \
  --dependency="afterok:$grow" \
  --wrap="$(q "$tool") merge $(q "$output") -workdir $(q "$workdir")")
echo "Submitted: estimates ${estimate%%;*} (array 0-$last), tiles up to $tile,$([ "$second_pass" -eq 1 ] && echo " second pass up to $refine,")$([ "$grow_pass" -eq 1 ] && echo " points left out grouped up to $grow,") merge ${merge%%;*}."
echo "After a failure: $tool resume $output -workdir $workdir"
