#!/usr/bin/python3
"""The fitted state-space model of `rollnoise statespace` against the exact transfer [-f | g].

  /usr/bin/python3 postprocess/plot_statespace.py OUT.h5 [--entries 11,22,14,24] [-o fig.png]

Entry ij: output i (1 Fx [N], 2 Fy [N], 3 Mz [N m]) per input j (1 xi_x [-], 2 xi_y [-], 3 phi [rad/m],
4 N [N]); the transfer is [-f | g], so entries with j <= 3 are -f_ij and those with j = 4 are g_i.
Magnitude (top) and phase (bottom): the exact values at the fitted frequencies (/creep/frequency,
dots), the continuous model C (sI - A)^-1 B + D from /statespace/{A, B, C, D} (line, on a dense
axis over the band) and the discrete model's D + C (zI - A)^-1 B, z = exp(i 2 pi f dt) (dashed;
docs/statespace.md Sec. 3: its inputs are the samples at t_k, no correction applied).
The title gives /statespace/fit_error.
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rollnoise_h5 as rh  # noqa: E402

OUT = ["Fx", "Fy", "Mz"]
IN = ["xi_x", "xi_y", "phi", "N"]


def response(A, B, C, D, s):
    """C (s I - A)^-1 B + D at each s (plain numpy)."""
    n = A.shape[0]
    return np.array([D + C @ np.linalg.solve(sk * np.eye(n) - A, B) for sk in s])



def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("file")
    ap.add_argument("--entries", default="11,22,14,24", help="entries ij of [-f | g] to draw")
    ap.add_argument("-o", "--output", default=None, help="PNG file (default FILE_statespace.png)")
    args = ap.parse_args()
    entries = rh.matrix_entries(args.entries, 3, 4)
    out = args.output or args.file.rsplit(".", 1)[0] + "_statespace.png"
    with rh.open_output(args.file, "/statespace/A", "/statespace/discrete/A", "/creep/f",
                        command="rollnoise statespace") as f:
        A, B, C, D = (rh.values(f, f"/statespace/{m}") for m in "ABCD")
        Ad, Bd, Cd, Dd = (rh.values(f, f"/statespace/discrete/{m}") for m in "ABCD")
        dt = float(rh.values(f, "/statespace/discrete/dt"))
        band = rh.values(f, "/statespace/band")
        err = float(rh.values(f, "/statespace/fit_error"))
        fr = rh.values(f, "/creep/frequency")
        H = np.concatenate([-rh.values(f, "/creep/f"), rh.values(f, "/creep/g")[:, :, None]], axis=2)
    lo = band[0] if band[0] > 0 else band[1] * 1e-3
    dense = np.geomspace(lo, band[1], 400)
    Hc = response(A, B, C, D, 2j * np.pi * dense)
    Hd = response(Ad, Bd, Cd, Dd, np.exp(2j * np.pi * dense * dt))
    shown = fr > 0
    fig, axes = plt.subplots(2, len(entries), figsize=(3.6 * len(entries), 6), sharex=True, squeeze=False)
    for c, (i, j) in enumerate(entries):
        name = f"{'-f' if j < 3 else 'g'}: {OUT[i]}/{IN[j]}"
        axes[0, c].loglog(fr[shown], np.abs(H[shown, i, j]), "k.", ms=3, label="exact (sweep)")
        axes[0, c].loglog(dense, np.abs(Hc[:, i, j]), "C0-", label="continuous fit")
        axes[0, c].loglog(dense, np.abs(Hd[:, i, j]), "C1--", label="discrete (ERA)")
        axes[1, c].semilogx(fr[shown], np.degrees(np.angle(H[shown, i, j])), "k.", ms=3)
        axes[1, c].semilogx(dense, np.degrees(np.angle(Hc[:, i, j])), "C0-")
        axes[1, c].semilogx(dense, np.degrees(np.angle(Hd[:, i, j])), "C1--")
        axes[0, c].set_title(name, fontsize=9)
        axes[1, c].set_xlabel("f [Hz]")
        for ax in axes[:, c]:
            ax.grid(alpha=0.3, which="both")
    axes[0, 0].set_ylabel("magnitude (units of the entry)")
    axes[1, 0].set_ylabel("phase [deg]")
    axes[0, 0].legend(fontsize=7)
    fig.suptitle(f"{args.file}: order {A.shape[0]} (continuous), {Ad.shape[0]} (discrete); fit error {err:.2g}")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print("wrote", out)


if __name__ == "__main__":
    rh.run(main)
