#!/usr/bin/env bash
# The pose tracking table (docs/measurements.md, "Pose tracking" and "Pose
# graph"): every shipped world, seeds 1..N, with odometry noise of 5%
# translation and 5% rotation, explored with --localize none and --localize
# scan, and with scan and no noise (what the tracker costs where there is
# nothing to correct); MODES="graph:0.05 graph:0" for the pose graph's rows.
# Prints a Markdown table.
#   usage: [JOBS=2] [MODES="none:0.05 scan:0.05 scan:0"] \
#          bench/localization_table.sh [BINARY] [SEEDS]
#   (default: build/release, 5 seeds, 2 runs at a time, all three modes;
#   MODES picks some, for instance only the tracker's after a change to it)
set -euo pipefail
bin=${1:-build/release/apps/pirouette/pirouette}
seeds=${2:-5}
jobs=${JOBS:-2}
modes=${MODES:-none:0.05 scan:0.05 scan:0}
out=$(mktemp -d)
# One line a run: world seed localize noise; run JOBS at a time.
for world in worlds/*.yaml; do
  grep -q "^format: pirouette-world" "$world" || continue
  for seed in $(seq 1 "$seeds"); do
    for mode in $modes; do
      echo "$world $seed ${mode%%:*} ${mode##*:}"
    done
  done
done | xargs -P "$jobs" -L 1 bash -c '
  name=$(basename "$1" .yaml)
  "$0" explore --world "$1" --seed "$2" --odometry-noise "$4,$4" --localize "$3" \
    --out "'"$out"'/$name-$2-$3@$4" --quiet >/dev/null 2>&1 || true
  echo "localization_table: $name seed $2 $3 noise $4 done" >&2' "$bin"
python3 - "$out" <<'PY'
import json, os, sys, collections
out = sys.argv[1]
rows = collections.defaultdict(list)
for d in sorted(os.listdir(out)):
    path = os.path.join(out, d, "run.json")
    if not os.path.exists(path):
        print(f"localization_table: no run.json for {d}", file=sys.stderr)
        continue
    r = json.load(open(path))
    name, seed, loc = d.rsplit("-", 2)
    rows[(name, loc)].append(r)
print("| world | localize @ noise | complete | coverage (mean, worst) | false_free (mean, worst) | wall_error_m (mean, worst) | pose error m (mean) | ATE RMS m (mean) | heading error ° (mean) | localize time |")
print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
for (name, loc), rs in sorted(rows.items()):
    e = [r["eval"] for r in rs]
    mean = lambda xs: sum(xs) / len(xs)
    cov = [x["coverage"] for x in e]; ff = [x["false_free"] for x in e]; we = [x["wall_error_m"] for x in e]
    pe = [r["pose_error"]["mean_m"] for r in rs]; pd = [r["pose_error"]["mean_deg"] for r in rs]
    ate = [r["pose_error"].get("ate_rms_m", 0.0) for r in rs]
    loc_json = [r["localization"] for r in rs if "localization" in r]
    if loc_json and "time_per_matched_frame_s" in loc_json[0]:
        t = f"{mean([l['time_per_matched_frame_s'] for l in loc_json]) * 1000:.1f} ms a matched frame"
    elif loc_json and "per_stop_s" in loc_json[0]:
        t = (f"{mean([l['per_stop_s']['mean'] for l in loc_json]) * 1000:.1f} ms a stop (max "
             f"{max(l['per_stop_s']['max'] for l in loc_json) * 1000:.0f})")
    else:
        t = "—"
    print(f"| {name} | {loc} | {sum(r['status'] == 'complete' for r in rs)}/{len(rs)} | "
          f"{mean(cov):.3f}, {min(cov):.3f} | {mean(ff):.4f}, {max(ff):.4f} | {mean(we):.4f}, {max(we):.4f} | "
          f"{mean(pe):.3f} | {mean(ate):.3f} | {mean(pd):.1f} | {t} |")
PY
rm -rf "$out"
