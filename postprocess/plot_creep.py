#!/usr/bin/python3
"""Creep coefficients against frequency, from one or more `rollnoise creep` outputs.

  /usr/bin/python3 postprocess/plot_creep.py A.h5 [B.h5 ...] [--entries 11,22] [--kalker C11] -o fig.png

Paper Fig. 11: one file, entries 11 and 22. Paper Fig. 12: several mean creepages, entry 11, with
Kalker's steady linear-theory value f11 = G c^2 C11 as a horizontal line (--kalker C11; G and c are
taken from the case in the first file). The units of each entry come from the `units` attribute
of /creep/f (f11, f12, f21, f22 in N; f13, f23, f31, f32 in N m; f33 in N m^2): entries of
different units go to separate panels.
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rollnoise_h5 as rh  # noqa: E402



def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("files", nargs="+")
    ap.add_argument("--entries", default="11,22", help="f_jk entries to draw, e.g. 11,22")
    ap.add_argument("--kalker", type=float, default=None, help="Kalker's C11 for the reference line")
    ap.add_argument("-o", "--output", default="creep.png")
    args = ap.parse_args()
    entries = rh.matrix_entries(args.entries)
    curves = []  # (label, unit, frequency, values)
    case = None
    for name in args.files:
        with rh.open_output(name, "/creep/f", "/creep/frequency", command="rollnoise creep") as f:
            fr = rh.values(f, "/creep/frequency")
            c = rh.values(f, "/creep/f")
            unit = rh.creep_entry_units(rh.units(f, "/creep/f"))
            mean = rh.values(f, "/steady/creepage") if "/steady/creepage" in f else None
            if case is None:
                case = {k: rh.case_value(f, *k.split(".")) for k in
                        ("material.E", "material.nu", "contact.a", "contact.b")}
        where = f", mean ({mean[0]:g}, {mean[1]:g}, {mean[2]:g})" if mean is not None else ""
        for (j, k) in entries:
            curves.append((f"f{j + 1}{k + 1}{where}", unit[j][k], fr, c[:, j, k]))
    units = list(dict.fromkeys(u for _, u, _, _ in curves))  # panel per unit, in order
    fig, axes = plt.subplots(len(units) + 1, 1, figsize=(8, 3.5 * (len(units) + 1)), sharex=True,
                             squeeze=False)
    axes = axes[:, 0]
    for label, u, fr, v in curves:
        axes[units.index(u)].loglog(fr, np.abs(v), label=label)
        axes[-1].semilogx(fr, np.degrees(np.angle(v)), label=label)
    if args.kalker is not None:
        if not (case and case["contact.a"] and case["contact.b"]):
            rh.fail(f"{args.files[0]}: --kalker needs a Hertzian case (contact.a, contact.b in /case)")
        E = float(case["material.E"] or 210e9)
        nu = float(case["material.nu"] or 0.28)
        G = E / (2 * (1 + nu))
        ax = axes[units.index("N")] if "N" in units else axes[0]
        ax.axhline(G * float(case["contact.a"]) * float(case["contact.b"]) * args.kalker, color="k", ls=":",
                   label="Kalker linear theory G c^2 C11")
    for ax, u in zip(axes, units):
        ax.set_ylabel(f"|f_jk| [{rh.pretty(u)}]")
        ax.legend(fontsize=7)
    axes[-1].set_ylabel("arg f_jk [deg]")
    axes[-1].set_xlabel("f [Hz]")
    for ax in axes:
        ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(args.output, dpi=120)
    print("wrote", args.output)


if __name__ == "__main__":
    rh.run(main)
