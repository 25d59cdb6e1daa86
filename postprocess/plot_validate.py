#!/usr/bin/python3
"""Linear NSS model against the unsteady solver, from `rollnoise validate` output.

  /usr/bin/python3 postprocess/plot_validate.py OUT.h5 [--prefix fig]

Writes PREFIX_time.png (forces against time: paper Figs. 3, 5, 6, 14) and PREFIX_spectra.png
(amplitude spectra, Hann window after the start transient: paper Figs. 7, 9, 10, 15).
"""
import argparse

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

NAMES = ["Fx [N]", "Fy [N]", "Mz [N m]"]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("file")
    ap.add_argument("--prefix", default=None, help="output prefix (default: the input name)")
    args = ap.parse_args()
    prefix = args.prefix or args.file.rsplit(".", 1)[0]
    with h5py.File(args.file, "r") as f:
        t = f["/validate/time"][:]
        fu = f["/validate/unsteady/force"][:]
        fl = f["/validate/linear/force"][:]
        fs = f["/validate/linear/force_synthesis"][:] if "/validate/linear/force_synthesis" in f else None
        spec_f = f["/validate/spectrum/frequency"][:]
        spec = {k: f["/validate/spectrum/" + k][:] for k in f["/validate/spectrum"] if k != "frequency"}
        err = f["/validate/errors/rms_relative"][:]

    fig, axes = plt.subplots(3, 1, figsize=(8, 8), sharex=True)
    for j, ax in enumerate(axes):
        ax.plot(t * 1e3, fu[:, j], "k-", lw=1.2, label="unsteady (paper Eq. 2)")
        ax.plot(t * 1e3, fl[:, j], "r--", lw=1.0, label="linear model, recursion")
        if fs is not None:
            ax.plot(t * 1e3, fs[:, j], "b:", lw=1.0, label="linear model, harmonic synthesis (Eqs. 33-34)")
        ax.set_ylabel(NAMES[j])
        ax.set_title(f"RMS error after the start: {100 * err[j]:.2f} % of the RMS variation", fontsize=9)
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8)
    axes[-1].set_xlabel("t [ms]")
    fig.tight_layout()
    fig.savefig(prefix + "_time.png", dpi=120)

    fig, axes = plt.subplots(3, 1, figsize=(8, 8), sharex=True)
    for j, (ax, comp) in enumerate(zip(axes, ["Fx", "Fy", "Mz"])):
        ax.semilogy(spec_f, np.abs(spec["unsteady_" + comp]), "k-", lw=1.0, label="unsteady")
        ax.semilogy(spec_f, np.abs(spec["linear_" + comp]), "r--", lw=1.0, label="linear model")
        ax.set_ylabel("|" + NAMES[j].split()[0] + "| " + NAMES[j].split()[1])
        ax.grid(alpha=0.3, which="both")
    axes[0].legend(fontsize=8)
    axes[-1].set_xlabel("f [Hz]")
    axes[-1].set_xlim(0, spec_f[-1])
    fig.tight_layout()
    fig.savefig(prefix + "_spectra.png", dpi=120)
    print("wrote", prefix + "_time.png", prefix + "_spectra.png")


if __name__ == "__main__":
    main()
