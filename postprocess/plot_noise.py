#!/usr/bin/python3
"""Contact-force spectra of a `rollnoise noise` run.

  /usr/bin/python3 postprocess/plot_noise.py OUT.h5 [--prefix fig]

Writes PREFIX_bands.png (1/3-octave force levels, the effective roughness, and with the run's
Kalker comparison the same levels with Kalker's steady creep coefficients) and PREFIX_transfer.png
(narrow-band force per unit roughness, |F/r|, in dB re 1 N/m).
"""
import argparse

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

LABELS = ["Fz", "Fx", "Fy", "Mz"]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("file")
    ap.add_argument("--prefix", default=None)
    args = ap.parse_args()
    prefix = args.prefix or args.file.rsplit(".", 1)[0]
    with h5py.File(args.file, "r") as f:
        centre = f["/noise/bands/centre"][:]
        level = f["/noise/bands/force_level"][:]
        rough = f["/noise/bands/roughness_level"][:]
        kalker = f["/noise/kalker/bands/force_level"][:] if "/noise/kalker/bands" in f else None
        freq = f["/noise/frequency"][:]
        force = f["/noise/force"][:]
        kforce = f["/noise/kalker/force"][:] if "/noise/kalker/force" in f else None
        creep = f["/steady/creepage"][:]
        model = f["/noise"].attrs["contact_model"]
    model = model.decode() if isinstance(model, bytes) else model
    title = f"{args.file}: mean creepage ({creep[0]:.3g}, {creep[1]:.3g}, {creep[2]:.3g} rad/m)"

    fig, ax = plt.subplots(figsize=(9, 5.5))
    x = np.arange(len(centre))
    for j, c in zip(range(4), ["k", "tab:blue", "tab:red", "tab:green"]):
        ax.plot(x, level[:, j], "-o", color=c, ms=3, label=f"{LABELS[j]} ({model})")
        if kalker is not None:
            ax.plot(x, kalker[:, j], ":", color=c, label=f"{LABELS[j]} (Kalker steady)")
    ax.plot(x, rough, "--", color="0.5", label="effective roughness, dB re 1 um")
    ax.set_xticks(x[::2])
    ax.set_xticklabels([f"{c:.0f}" for c in centre[::2]], rotation=45)
    ax.set_xlabel("1/3-octave band centre [Hz]")
    ax.set_ylabel("level [dB re 1 N; Mz re 1 N m]")
    ax.set_title(title, fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(prefix + "_bands.png", dpi=120)

    fig, axes = plt.subplots(4, 1, figsize=(9, 9), sharex=True)
    for j, ax in enumerate(axes):
        ax.semilogx(freq, 20 * np.log10(np.abs(force[:, j])), "k-", lw=0.8, label=model)
        if kforce is not None:
            ax.semilogx(freq, 20 * np.log10(np.abs(kforce[:, j])), "r:", lw=0.8, label="Kalker steady")
        ax.set_ylabel(f"|{LABELS[j]}/r| dB")
        ax.grid(alpha=0.3, which="both")
    axes[0].legend(fontsize=8)
    axes[0].set_title(title + "; dB re 1 N/m (Mz re 1 N m/m)", fontsize=9)
    axes[-1].set_xlabel("f [Hz]")
    fig.tight_layout()
    fig.savefig(prefix + "_transfer.png", dpi=120)
    print("wrote", prefix + "_bands.png", prefix + "_transfer.png")


if __name__ == "__main__":
    main()
