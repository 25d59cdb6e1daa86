#!/usr/bin/python3
"""Creep coefficients against frequency, from one or more `rollnoise creep` outputs.

  /usr/bin/python3 postprocess/plot_creep.py A.h5 [B.h5 ...] [--entries 11,22] [--kalker C11] -o fig.png

Paper Fig. 11: one file, entries 11 and 22. Paper Fig. 12: several mean creepages, entry 11, with
Kalker's steady linear-theory value f11 = G c^2 C11 as a horizontal line (--kalker C11; G and c are
taken from the case in the first file).
"""
import argparse

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def case_value(toml_text, section, key):
    sec = None
    for line in toml_text.splitlines():
        line = line.split("#")[0].strip()
        if line.startswith("["):
            sec = line.strip("[]")
        elif "=" in line and sec == section and line.split("=")[0].strip() == key:
            return line.split("=", 1)[1].strip()
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("files", nargs="+")
    ap.add_argument("--entries", default="11,22", help="f_jk entries to draw, e.g. 11,22")
    ap.add_argument("--kalker", type=float, default=None, help="Kalker's C11 for the reference line")
    ap.add_argument("-o", "--output", default="creep.png")
    args = ap.parse_args()
    entries = [(int(e[0]) - 1, int(e[1]) - 1) for e in args.entries.split(",")]
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    for name in args.files:
        with h5py.File(name, "r") as f:
            fr = f["/creep/frequency"][:]
            c = f["/creep/f"][:]
            if c.dtype.names:  # older h5py: compound {r, i}
                c = c["r"] + 1j * c["i"]
            mean = f["/steady/creepage"][:]
            toml = f["/case"].attrs["toml"]
            toml = toml.decode() if isinstance(toml, bytes) else toml
        for (j, k) in entries:
            label = f"f{j + 1}{k + 1}, mean ({mean[0]:g}, {mean[1]:g}, {mean[2]:g})"
            ax1.loglog(fr, np.abs(c[:, j, k]), label=label)
            ax2.semilogx(fr, np.degrees(np.angle(c[:, j, k])), label=label)
    if args.kalker is not None:
        E = float(case_value(toml, "material", "E") or 210e9)
        nu = float(case_value(toml, "material", "nu") or 0.28)
        a = float(case_value(toml, "contact", "a"))
        b = float(case_value(toml, "contact", "b"))
        G = E / (2 * (1 + nu))
        ax1.axhline(G * a * b * args.kalker, color="k", ls=":", label="Kalker linear theory G c^2 C11")
    ax1.set_ylabel("|f_jk| [N]")
    ax2.set_ylabel("arg f_jk [deg]")
    ax2.set_xlabel("f [Hz]")
    for ax in (ax1, ax2):
        ax.grid(alpha=0.3, which="both")
    ax1.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(args.output, dpi=120)
    print("wrote", args.output)


if __name__ == "__main__":
    main()
