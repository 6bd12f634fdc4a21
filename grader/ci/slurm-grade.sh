#!/usr/bin/env bash
# Grades a class on a Slurm cluster: a job array of SHARDS tasks, task K grading every SHARDS-th submission
# (gsv-grade --batch --shard K/SHARDS), then a job that merges them when all have ended (gsv-grade merge), into
# OUT/class/: class.csv, class.txt and a folder per student. Run it on a login node, from the kit's root, with the
# kit built there (scripts/kit build) on a file system the compute nodes share:
#
#   GSVGRADE_SEED=4711 grader/ci/slurm-grade.sh SUBMISSIONS OUT [SHARDS] [WORKERS]
#
# SUBMISSIONS: one folder per student (on the shared file system); OUT: new. SHARDS (default 8) array tasks of
# WORKERS (default 2) submissions at a time, each with 2 cores per worker (timing checks want a core or two).
# The seed comes from the environment (sbatch passes it on), so it shows in no job's command line; keep it secret
# until grades are out. Extra sbatch options (partition, account, time): SBATCH_PARTITION, SBATCH_ACCOUNT,
# SBATCH_TIMELIMIT, which sbatch reads itself.
#
# The sandbox: the grader runs as your user and makes its walls in a user namespace. Clusters that disable
# unprivileged user namespaces (sysctl user.max_user_namespaces=0, or kernel.unprivileged_userns_clone=0) refuse
# it; the grader then stops with one line, and `--allow-readable-kit` (GSV_SLURM_READABLE_KIT=yes here) grades
# without hiding the kit from student code (see "Where the walls cannot go up" in grader/README.md).
set -euo pipefail
usage() { echo "usage: GSVGRADE_SEED=N grader/ci/slurm-grade.sh SUBMISSIONS OUT [SHARDS] [WORKERS]" >&2; exit 2; }
[ $# -ge 2 ] && [ $# -le 4 ] || usage
submissions=$(cd "$1" 2>/dev/null && pwd) || { echo "slurm-grade: no folder of submissions '$1'" >&2; exit 2; }
out=$2
shards=${3:-8}
workers=${4:-2}
case "$shards" in ''|*[!0-9]*|0) echo "slurm-grade: SHARDS must be a whole number >= 1, got '$shards'" >&2; exit 2 ;; esac
case "$workers" in ''|*[!0-9]*|0) echo "slurm-grade: WORKERS must be a whole number >= 1, got '$workers'" >&2; exit 2 ;; esac
case "${GSVGRADE_SEED:-}" in ''|*[!0-9]*) echo "slurm-grade: set GSVGRADE_SEED to the seed (a whole number)" >&2; exit 2 ;; esac
kit=$(cd "$(dirname "$0")/../.." && pwd)
grade=$kit/build/bin/gsv-grade
[ -x "$grade" ] || { echo "slurm-grade: no $grade: build the kit first (scripts/kit build)" >&2; exit 2; }
[ ! -e "$out" ] || { echo "slurm-grade: '$out' exists: give a new folder" >&2; exit 2; }
command -v sbatch >/dev/null || { echo "slurm-grade: no sbatch: run this on a Slurm login node" >&2; exit 2; }
mkdir -p "$out/logs"
out=$(cd "$out" && pwd)
readable=""
[ "${GSV_SLURM_READABLE_KIT:-no}" = yes ] && readable=--allow-readable-kit

# The array: task K is shard K/SHARDS. gsv-grade reads the seed from GSVGRADE_SEED; sbatch exports the environment.
array_job=$(sbatch --parsable --job-name=gsv-grade --array="1-$shards" --cpus-per-task=$((2 * workers)) \
  --output="$out/logs/shard-%a.log" --chdir="$kit" \
  --wrap="exec '$grade' --batch '$submissions' --shard \"\$SLURM_ARRAY_TASK_ID/$shards\" --workers $workers --out '$out/shard-'\"\$SLURM_ARRAY_TASK_ID\" $readable")
# The merge, when every task has ended (afterany: a failed shard makes merge refuse, naming it; rerun that task).
merge_job=$(sbatch --parsable --job-name=gsv-merge --dependency="afterany:$array_job" --output="$out/logs/merge.log" \
  --chdir="$kit" --wrap="exec '$grade' merge '$out/class' \$(seq -f '$out/shard-%g' 1 $shards)")
echo "slurm-grade: array job $array_job ($shards shards of $workers workers), merge job $merge_job"
echo "slurm-grade: the class will be in $out/class/class.csv; logs in $out/logs/"
