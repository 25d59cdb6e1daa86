#!/usr/bin/env bash
# Checks that the sanitizer stage's unity build (CMakeLists.txt, ROLLNOISE_UNITY_BUILD) compiles:
# each layer's sources as ONE translation unit, syntax only (about 2 min on 2 cores). A clash means
# two files of a layer define the same file-local name (an anonymous-namespace function or
# constant): share it (src/core/constants.hpp, a layer header) or rename it.
#   bash scripts/check_unity_names.sh
set -euo pipefail
cd "$(dirname "$0")/.."
dir=build-unity-check
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DROLLNOISE_UNITY_BUILD=ON -DROLLNOISE_UNITY_BATCH=0 \
  -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=ON >/dev/null
mkdir -p "$dir/generated"
[ -e "$dir/generated/rollnoise_version.h" ] ||
  echo '#define ROLLNOISE_GIT_VERSION "check"' >"$dir/generated/rollnoise_version.h"
/usr/bin/python3 - "$dir" <<'PY'
import json, subprocess, sys, concurrent.futures as cf
units = [c for c in json.load(open(sys.argv[1] + "/compile_commands.json"))
         if "/Unity/" in c["file"] and "/test_" not in c["file"]]
def check(c):
    r = subprocess.run(c["command"] + " -fsyntax-only", shell=True, cwd=c["directory"],
                       capture_output=True, text=True)
    return c["file"], r.returncode, r.stderr
bad = 0
with cf.ThreadPoolExecutor(2) as pool:
    for f, rc, err in pool.map(check, units):
        if rc:
            bad += 1
            print(f, "\n" + "\n".join(l for l in err.splitlines() if "error" in l)[:3000])
print(f"check_unity_names: {len(units)} layers, {bad} with clashes")
sys.exit(1 if bad else 0)
PY
