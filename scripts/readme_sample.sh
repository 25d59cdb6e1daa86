#!/usr/bin/env bash
# Runs the README's main job (noise cases/curve_300m.toml) and writes its printed summary to
# docs/sample_output.txt, so that the sample output the README links to is the program's own.
#   bash scripts/readme_sample.sh
#   ROLLNOISE_BINARY=/path/to/rollnoise bash scripts/readme_sample.sh   (default build/rollnoise)
# The result file goes to a temporary folder and is removed; the wheel's modes and the rail's
# samplings go to the usual cache folder (ROLLNOISE_CACHE_DIR, default ~/.cache/rollnoise).
# Wall and CPU times in the summary ("0.8 s", "total 18.2 s") vary from run to run and machine to
# machine: they are replaced by "<t> s" so that a rerun changes the file only when the results do.
set -euo pipefail
cd "$(dirname "$0")/.."
binary=${ROLLNOISE_BINARY:-build/rollnoise}
[ -x "$binary" ] || { echo "readme_sample: no program at $binary (set ROLLNOISE_BINARY or build first)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$binary" noise cases/curve_300m.toml -o "$work/curve_300m.noise.h5" > "$work/summary.txt"
{
  echo "\$ build/rollnoise noise cases/curve_300m.toml"
  # times: "<number> s" after a word that names a duration; the output path: the default name
  sed -E -e 's/([0-9]+(\.[0-9]+)?) s([,;):]|$| )/<t> s\3/g' \
         -e "s#$work/##g" "$work/summary.txt"
  echo "(written by scripts/readme_sample.sh; times shown as <t>: they vary with the machine and the cache)"
} > docs/sample_output.txt
echo "readme_sample: wrote docs/sample_output.txt"
