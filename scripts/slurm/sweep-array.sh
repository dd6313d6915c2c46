#!/usr/bin/env bash
# Submits a rastrace sweep to Slurm as a job array, one task per shard (`rastrace sweep --shard
# K/N -o PART.json`), and a merge job that starts when every task has succeeded
# (`rastrace merge`), writing the same table as the unsharded sweep.
#
# Usage: scripts/slurm/sweep-array.sh --shards N --out DIR [--format md|csv|latex|json]
#          [--rastrace PATH] [--sbatch "EXTRA SBATCH FLAGS"] [--dry-run] TRACE [SWEEP FLAGS...]
#   DIR must be on a filesystem every node sees; it receives sweep.sbatch, merge.sbatch, the parts
#   (part-K.json), the logs and the merged table (sweep.FORMAT). The sweep flags (--cache,
#   --keep-vertex-cache, --threads) are passed to every task unchanged.
#   --dry-run writes the two batch scripts and prints the sbatch commands without submitting.
# Prints the two job ids. Example:
#   scripts/slurm/sweep-array.sh --shards 16 --out /shared/sweep1 --format csv \
#     /shared/frame.rtrace --cache size=1KiB..4MiB,assoc=1/2/4/8/full,policy=fifo/lru/opt
set -euo pipefail

usage() { sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
shards="" out="" format=md rastrace="" extra="" dry_run=0
while (($#)); do
  case "$1" in
    --shards) shards=${2:-}; shift 2 ;;
    --out) out=${2:-}; shift 2 ;;
    --format) format=${2:-}; shift 2 ;;
    --rastrace) rastrace=${2:-}; shift 2 ;;
    --sbatch) extra=${2:-}; shift 2 ;;
    --dry-run) dry_run=1; shift ;;
    -h|--help) usage ;;
    --*) echo "sweep-array.sh: unknown option $1" >&2; usage ;;
    *) break ;;
  esac
done
(($# >= 1)) || { echo "sweep-array.sh: expected TRACE" >&2; usage; }
[[ "$shards" =~ ^[1-9][0-9]*$ ]] || { echo "sweep-array.sh: --shards '$shards': expected a positive count" >&2; exit 2; }
[ -n "$out" ] || { echo "sweep-array.sh: expected --out DIR" >&2; exit 2; }
case "$format" in md|csv|latex|json) ;; *) echo "sweep-array.sh: --format '$format': expected md, csv, latex or json" >&2; exit 2 ;; esac
trace=$(realpath "$1"); shift
[ -f "$trace" ] || { echo "sweep-array.sh: $trace: no such trace" >&2; exit 1; }
if [ -z "$rastrace" ]; then
  here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
  rastrace=$(command -v rastrace || echo "$here/build/apps/rastrace")
fi
rastrace=$(realpath "$rastrace")
[ -x "$rastrace" ] || { echo "sweep-array.sh: $rastrace: not an executable" >&2; exit 1; }
mkdir -p "$out"
out=$(realpath "$out")

quoted_flags=$(printf ' %q' "$@")
cat > "$out/sweep.sbatch" <<BATCH
#!/usr/bin/env bash
#SBATCH --job-name=rastrace-sweep
#SBATCH --array=1-$shards
#SBATCH --output=$out/sweep-%a.log
set -euo pipefail
exec $(printf '%q' "$rastrace") sweep $(printf '%q' "$trace")$quoted_flags \\
  --shard "\$SLURM_ARRAY_TASK_ID/$shards" -o "$out/part-\$SLURM_ARRAY_TASK_ID.json"
BATCH
parts=""
for ((k = 1; k <= shards; ++k)); do parts+=" $(printf '%q' "$out/part-$k.json")"; done
cat > "$out/merge.sbatch" <<BATCH
#!/usr/bin/env bash
#SBATCH --job-name=rastrace-merge
#SBATCH --output=$out/merge.log
set -euo pipefail
exec $(printf '%q' "$rastrace") merge$parts --format $format -o "$out/sweep.$format"
BATCH

if ((dry_run)); then
  echo "sbatch --parsable $extra $out/sweep.sbatch"
  echo "sbatch --parsable --dependency=afterok:<sweep job> $extra $out/merge.sbatch"
  exit 0
fi
# shellcheck disable=SC2086  # the extra flags are split on purpose
array=$(sbatch --parsable $extra "$out/sweep.sbatch")
array=${array%%;*}
# shellcheck disable=SC2086
merge=$(sbatch --parsable --dependency="afterok:$array" --kill-on-invalid-dep=yes $extra "$out/merge.sbatch")
merge=${merge%%;*}
echo "sweep array job $array ($shards tasks), merge job $merge: the table will be $out/sweep.$format"
