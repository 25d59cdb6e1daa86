#!/usr/bin/python3
"""The discrete state-space model of `rollnoise statespace` through numpy, as a user reads it:
its transfer D + C (zI - A)^-1 B at z = exp(2 pi i f dt), from /statespace/discrete/{A, B, C, D,
dt} and nothing else, equals [-f | g] (/creep/f, /creep/g) of the same file, the formula of
docs/statespace.md Sec. 3 (its inputs the samples at t_k, no sampling factor applied).

  /usr/bin/python3 tests/postprocess/statespace_discrete_test.py ROLLNOISE_BINARY WORKDIR

Physical check: the contact forces a time-domain code gets from the discrete model fed with its
creepage samples are those of the creep coefficients, at 1 kHz and 4 kHz (the sample of
/creep/frequency nearest each) on the paper's Hertzian case (its default band 10 Hz-5 kHz):
max_ij |H_ij + f_ij| / max_ij |f_ij| < 1e-3 for the creepage columns and the same for g.
Run by CTest (test `postprocess_statespace_discrete`, CMakeLists.txt).
"""
import os
import subprocess
import sys

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TOLERANCE = 1e-3  # relative to the largest entry (the documented transfer function's acceptance)


def main():
    binary, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    out = os.path.join(work, "statespace_discrete.h5")
    subprocess.run([binary, "statespace", os.path.join(ROOT, "cases", "hertz_paper.toml"), "-q", "-o", out],
                   check=True)
    with h5py.File(out, "r") as h:
        A, B, C, D = (h["/statespace/discrete/" + m][()] for m in "ABCD")
        dt = float(h["/statespace/discrete/dt"][()])
        freq = h["/creep/frequency"][()]
        f = h["/creep/f"][()]
        g = h["/creep/g"][()]
    failures = 0
    for target in (1000.0, 4000.0):
        i = int(np.argmin(np.abs(freq - target)))
        z = np.exp(2j * np.pi * freq[i] * dt)
        H = D + C @ np.linalg.solve(z * np.eye(A.shape[0]) - A, B)
        err_f = np.max(np.abs(H[:, :3] + f[i])) / np.max(np.abs(f[i]))
        err_g = np.max(np.abs(H[:, 3] - g[i])) / np.max(np.abs(g[i]))
        ok = err_f < TOLERANCE and err_g < TOLERANCE
        failures += not ok
        print(f"{'ok  ' if ok else 'FAIL'} {freq[i]:.6g} Hz: |H + f|/|f| = {err_f:.3g}, |H - g|/|g| = {err_g:.3g} "
              f"(tolerance {TOLERANCE:g})")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
