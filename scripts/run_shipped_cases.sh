#!/bin/bash
# Run the shipped cases (cases/*.toml, without the parameter studies) with one binary into one
# folder, for a before/after comparison with scripts/compare_outputs.py.
#   scripts/run_shipped_cases.sh BINARY OUT_DIR
set -u
bin=$(realpath "$1"); out=$2; mkdir -p "$out"
cd "$(dirname "$0")/.."
run() { # command case [name] [args...]
  local cmd=$1 case=$2 name=$3; shift 3
  if ! "$bin" "$cmd" "cases/$case.toml" -q -o "$out/$name.h5" "$@" > "$out/$name.log" 2>&1; then
    echo "FAILED: $cmd $case (exit $?)"; fi
}
for c in curve_1000m curve_300m curve_300m_hertz curve_300m_table curve_300m_waveguide curve_500m \
         curve_flange_300m tangent; do run noise $c noise_$c; done
run receptance curve_300m receptance_curve_300m
for c in squeal_150m squeal_300m squeal_300m_table squeal_300m_waveguide; do run squeal $c squeal_$c; done
for c in hertz_paper nonhertz_s1002_uic60; do run steady $c steady_$c; done
run steady hertz_paper sweep_hertz_paper --sweep 'creepage.mean[0]=0:0.01:5'
for c in paper_s31_longitudinal paper_s32_combined paper_s33_pseudorandom nonhertz_s1002_uic60; do
  run validate $c validate_$c; done
run creep paper_s34_creep_coefficients creep_paper_s34
run transient paper_s31_longitudinal transient_paper_s31
run statespace paper_s34_creep_coefficients statespace_paper_s34
run response paper_s32_combined response_paper_s32
run modes curve_300m modes_curve_300m
echo done
