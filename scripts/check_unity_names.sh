#!/usr/bin/env bash
# Checks that the unity build (CMakeLists.txt, ROLLNOISE_UNITY_BUILD) compiles: each layer's sources,
# or each test folder's files, as ONE translation unit, syntax only. A clash means two files of a
# layer (a test folder) define the same file-local name (an anonymous-namespace function or
# constant): share it (src/core/constants.hpp, a layer header; tests/support/*.hpp for tests) or
# rename it.
#   bash scripts/check_unity_names.sh           the src/ layers and the program (about 2 min)
#   bash scripts/check_unity_names.sh --tests   the test programs, one per folder of tests/ (~4 min)
#   bash scripts/check_unity_names.sh --all     both
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:---src}
case "$mode" in
  --src | --tests | --all) ;;
  *) echo "usage: bash scripts/check_unity_names.sh [--src|--tests|--all]" >&2; exit 2 ;;
esac
dir=build-unity-check
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DROLLNOISE_UNITY_BUILD=ON -DROLLNOISE_UNITY_BATCH=0 \
  -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=ON >/dev/null
mkdir -p "$dir/generated"
[ -e "$dir/generated/rollnoise_version.h" ] ||
  echo '#define ROLLNOISE_GIT_VERSION "check"' >"$dir/generated/rollnoise_version.h"
/usr/bin/python3 - "$dir" "$mode" <<'PY'
import json, subprocess, sys, concurrent.futures as cf
def wanted(path):
    if "/Unity/" not in path:
        return False
    is_test = "/test_" in path
    return {"--src": not is_test, "--tests": is_test, "--all": True}[sys.argv[2]]
units = [c for c in json.load(open(sys.argv[1] + "/compile_commands.json")) if wanted(c["file"])]
def check(c):
    r = subprocess.run(c["command"] + " -fsyntax-only", shell=True, cwd=c["directory"],
                       capture_output=True, text=True)
    return c["file"], r.returncode, r.stderr
bad = 0
with cf.ThreadPoolExecutor(2) as pool:
    for f, rc, err in pool.map(check, units):
        if rc:
            bad += 1
            print(f, "\n" + "\n".join(l for l in err.splitlines() if "error" in l)[:6000])
print(f"check_unity_names: {len(units)} units, {bad} with clashes")
sys.exit(1 if bad else 0)
PY
