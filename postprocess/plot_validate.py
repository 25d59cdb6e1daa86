#!/usr/bin/python3
"""Linear NSS model against the unsteady solver, from `rollnoise validate` output.

  /usr/bin/python3 postprocess/plot_validate.py OUT.h5 [--prefix fig]

Writes PREFIX_time.png (forces against time: paper Figs. 3, 5, 6, 14) and PREFIX_spectra.png
(amplitude spectra, Hann window after the start transient: paper Figs. 7, 9, 10, 15). Units are
those of the datasets' `units` attributes.
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rollnoise_h5 as rh  # noqa: E402

COMPONENTS = ["Fx", "Fy", "Mz"]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("file")
    ap.add_argument("--prefix", default=None, help="output prefix (default: the input name)")
    args = ap.parse_args()
    prefix = args.prefix or args.file.rsplit(".", 1)[0]
    needed = ["/validate/time", "/validate/unsteady/force", "/validate/linear/force",
              "/validate/spectrum/frequency", "/validate/errors/rms_relative"]
    with rh.open_output(args.file, *needed, command="rollnoise validate") as f:
        t = rh.values(f, "/validate/time")
        fu = rh.values(f, "/validate/unsteady/force")
        fl = rh.values(f, "/validate/linear/force")
        force_units = rh.component_units(f, "/validate/unsteady/force", 3)
        fs = rh.values(f, "/validate/linear/force_synthesis") if "/validate/linear/force_synthesis" in f else None
        spec_f = rh.values(f, "/validate/spectrum/frequency")
        spec, spec_units = {}, {}
        for c in COMPONENTS:
            for kind in ("unsteady", "linear"):
                path = f"/validate/spectrum/{kind}_{c}"
                if path not in f:
                    rh.fail(f"{args.file}: no {path}: not the output of `rollnoise validate`")
                spec[kind + "_" + c] = rh.values(f, path)
            spec_units[c] = rh.units(f, f"/validate/spectrum/unsteady_{c}")
        err = rh.values(f, "/validate/errors/rms_relative")
        # CONTACT's own run (validate --reference contact DIR), drawn beside the built-in solver
        tc = rh.values(f, "/validate/contact/time") if "/validate/contact/time" in f else None
        fc = rh.values(f, "/validate/contact/force") if tc is not None else None

    fig, axes = plt.subplots(3, 1, figsize=(8, 8), sharex=True)
    for j, ax in enumerate(axes):
        ax.plot(t * 1e3, fu[:, j], "k-", lw=1.2, label="unsteady (paper Eq. 2)")
        ax.plot(t * 1e3, fl[:, j], "r--", lw=1.0, label="linear model, recursion")
        if fc is not None:
            ax.plot(tc * 1e3, fc[:, j], "g.", ms=3, label="CONTACT (printed totals)")
        if fs is not None:
            ax.plot(t * 1e3, fs[:, j], "b:", lw=1.0, label="linear model, harmonic synthesis (Eqs. 33-34)")
        ax.set_ylabel(f"{COMPONENTS[j]} [{force_units[j]}]")
        ax.set_title(f"RMS error after the start: {100 * err[j]:.2f} % of the RMS variation", fontsize=9)
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8)
    axes[-1].set_xlabel("t [ms]")
    fig.tight_layout()
    fig.savefig(prefix + "_time.png", dpi=120)

    fig, axes = plt.subplots(3, 1, figsize=(8, 8), sharex=True)
    for ax, c in zip(axes, COMPONENTS):
        ax.semilogy(spec_f, np.abs(spec["unsteady_" + c]), "k-", lw=1.0, label="unsteady")
        ax.semilogy(spec_f, np.abs(spec["linear_" + c]), "r--", lw=1.0, label="linear model")
        ax.set_ylabel(f"|{c}| [{spec_units[c]}]")
        ax.grid(alpha=0.3, which="both")
    axes[0].legend(fontsize=8)
    axes[-1].set_xlabel("f [Hz]")
    axes[-1].set_xlim(0, spec_f[-1])
    fig.tight_layout()
    fig.savefig(prefix + "_spectra.png", dpi=120)
    print("wrote", prefix + "_time.png", prefix + "_spectra.png")


if __name__ == "__main__":
    rh.run(main)
