#!/usr/bin/env bash
# The place recognition and kidnapped-robot tables (docs/measurements.md,
# "Place recognition", "Kidnapped robot"): every shipped
# world, `pirouette places` (100 random queries, seed 1) and `pirouette
# locate` (20 random poses a seed, on the map `explore` makes of the world,
# with its colour layer) at the default range factor and, for comparison,
# at 1x (the map's range) with and without colours. Prints Markdown rows.
#   usage: [JOBS=2] [SEEDS="1 2"] bench/recognition_table.sh [BINARY]
#   (default: build/release, seeds 1 and 2, 2 runs at a time)
set -euo pipefail
bin=$(realpath "${1:-build/release/apps/pirouette/pirouette}")
jobs=${JOBS:-2}
seeds=${SEEDS:-1 2}
out=$(mktemp -d)
worlds=()
for world in worlds/*.yaml; do
  grep -q "^format: pirouette-world" "$world" && worlds+=("$(realpath "$world")")
done
# The maps first, one a world.
printf '%s\n' "${worlds[@]}" | xargs -P "$jobs" -I{} bash -c '
  name=$(basename "$1" .yaml)
  "$0" explore --world "$1" --out "'"$out"'/$name" --quiet >/dev/null 2>&1
  echo "recognition_table: $name explored" >&2' "$bin" {}
# Then one line a job: kind world seed variant.
{
  for w in "${worlds[@]}"; do
    echo "places $w 1 default"
    for s in $seeds; do
      echo "locate $w $s default"
      echo "locate $w $s 1x"
      echo "locate $w $s 1x-no-colours"
    done
  done
} | xargs -P "$jobs" -L 1 bash -c '
  kind=$1; name=$(basename "$2" .yaml); seed=$3; variant=$4
  dir="'"$out"'/$name"
  case $variant in
    default) extra=() ;;
    1x) extra=(--range-factor 1) ;;
    1x-no-colours) extra=(--range-factor 1 --no-colours) ;;
  esac
  if [ "$kind" = places ]; then
    "$0" places --world "$2" --queries 100 --seed "$seed" --quiet \
      --out "$dir/places-$variant.json" >/dev/null 2>&1
  else
    "$0" locate --map "$dir/map.yaml" --world "$2" --random 20 --seed "$seed" --quiet \
      "${extra[@]}" --table "$dir/places-$variant.yaml" \
      --out "$dir/locate-$seed-$variant.json" >/dev/null 2>&1
  fi
  echo "recognition_table: $kind $name seed $seed $variant done" >&2' "$bin"
python3 - "$out" <<'PY'
import json, os, sys
out = sys.argv[1]
print("places (100 queries, seed 1): world | places (spacing) | signature: place / heading | s")
for name in sorted(os.listdir(out)):
    p = os.path.join(out, name, "places-default.json")
    if not os.path.exists(p):
        continue
    r = json.load(open(p))
    sigs = " | ".join(
        f"{k} {100*s['place_rate']:.0f}% / {100*s['heading_rate']:.0f}%"
        if s.get('heading_rate') is not None else f"{k} {100*s['place_rate']:.0f}%"
        for k, s in r["signatures"].items())
    t = r["table"]
    print(f"| {name} | {t['places']} ({t['spacing_m']:.2f} m) | {sigs} | {r['build_s'] + r['query_s']:.0f} |")
print()
print("locate (20 random poses a seed): world | variant | seed | places | found right | cannot tell | wrong | s a query")
for name in sorted(os.listdir(out)):
    d = os.path.join(out, name)
    for f in sorted(os.listdir(d)):
        if not f.startswith("locate-"):
            continue
        r = json.load(open(os.path.join(d, f)))
        _, seed, variant = f[:-5].split("-", 2)
        print(f"| {name} | {variant} | {seed} | {r['table_places']} | {r['found_right']} | "
              f"{r['cannot_tell']} | {r['wrong']} | {r['mean_locate_s']:.1f} |")
PY
rm -rf "$out"
