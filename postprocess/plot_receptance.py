#!/usr/bin/python3
"""Wheel, rail and contact receptances of one or more `rollnoise receptance` runs.

  /usr/bin/python3 postprocess/plot_receptance.py OUT.h5 [MORE.h5 ...] [--label L ...]
      [--entries 11,22,33,44] [-o fig.png]

OUT.h5 is the output of `rollnoise receptance`: /receptance/wheel, /receptance/rail and
/receptance/contact, each [nf][4][4] complex at the contact point in the contact frame (order
normal, x, y, rotation about the normal; units from the `units` attribute: m/N, m/(N m), rad/N,
rad/(N m)), against /receptance/frequency (Hz). One column per entry of --entries (ij: response i to
a force or moment j, 1-based; default the four point receptances 11, 22, 33, 44): magnitude on top
in dB re 1 of its unit (20 log10 |alpha|, e.g. dB re 1 m/N), phase below (degrees). Colour:
wheel, rail, contact; line style: file (several files overlaid, labelled by --label, once per file in
order, or by the file's stem). The title names, per file, the case's wheel and track models.
The output defaults to FILE_receptance.png (one file) or receptance_compare.png beside the first.
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rollnoise_h5 as rh  # noqa: E402

DIRECTIONS = ["normal", "longitudinal (x)", "lateral (y)", "rotation about the normal"]
STRUCTURES = [("wheel", "tab:blue"), ("rail", "tab:red"), ("contact", "k")]


def entry_unit(units, i, j):
    """Unit of entry (i, j) from the dataset's units "m/N, m/(N m), rad/N, rad/(N m)": response i
    (translation for 0..2, rotation for 3) to load j (force 0..2, moment 3)."""
    u = [s.strip() for s in units.split(";")[0].split(",")]
    if len(u) < 4:
        u = ["m/N", "m/(N m)", "rad/N", "rad/(N m)"]
    return u[(2 if i == 3 else 0) + (1 if j == 3 else 0)]


def describe(f, label):
    """One title line per file: label, the contact, the wheel and the track of the case as run."""
    def value(section, key):
        v = rh.case_value(f, section, key)
        return v.strip("'\"") if v else None
    wheel = value("wheel", "model") or ("mode table" if value("wheel", "modes") else None)
    track = value("track", "model") or "beam"
    support = value("track", "support")
    parts = [f"{label}: at the case's contact point (contact frame)"]
    if wheel:
        parts.append(f"wheel: {wheel}")
    parts.append(f"track: {track}" + (f", {support} support" if support else ""))
    return "; ".join(parts)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("files", nargs="+", metavar="FILE")
    ap.add_argument("--label", action="append", default=[], help="legend label of a file (once per file, in order)")
    ap.add_argument("--entries", default="11,22,33,44", help="entries ij to draw (1..4: normal, x, y, rotation)")
    ap.add_argument("-o", "--output", default=None, help="PNG file")
    args = ap.parse_args()
    labels = rh.file_labels(args.files, args.label)
    entries = rh.matrix_entries(args.entries, rows=4, cols=4)
    if args.output:
        out = args.output
    elif len(args.files) == 1:
        out = args.files[0].rsplit(".", 1)[0] + "_receptance.png"
    else:
        out = os.path.join(os.path.dirname(args.files[0]), "receptance_compare.png")
    needed = ["/receptance/frequency", "/receptance/wheel", "/receptance/rail", "/receptance/contact"]
    runs = []
    for path, label in zip(args.files, labels):
        with rh.open_output(path, *needed, command="rollnoise receptance") as f:
            r = {"label": label, "freq": rh.values(f, "/receptance/frequency"), "title": describe(f, label),
                 "units": rh.units(f, "/receptance/wheel", "")}
            for name, _ in STRUCTURES:
                a = rh.values(f, "/receptance/" + name)
                if a.ndim != 3 or a.shape[1:] != (4, 4) or a.shape[0] != len(r["freq"]):
                    rh.fail(f"{path}: /receptance/{name} is not [nf][4][4] with nf = {len(r['freq'])}")
                r[name] = a
            runs.append(r)

    n = len(entries)
    fig, axes = plt.subplots(2, n, figsize=(4.2 * n + 1, 7.5), sharex=True, squeeze=False)
    for k, (i, j) in enumerate(entries):
        am, ap_ = axes[0, k], axes[1, k]
        unit = rh.pretty(entry_unit(runs[0]["units"], i, j))
        for m, r in enumerate(runs):
            style = rh.file_style(m)
            for name, c in STRUCTURES:
                a = r[name][:, i, j]
                mag = np.abs(a)
                with np.errstate(divide="ignore"):
                    db = np.where(mag > 0, 20 * np.log10(np.where(mag > 0, mag, 1)), np.nan)
                phase = np.where(mag > 0, np.degrees(np.angle(a)), np.nan)
                label = name + (f" ({r['label']})" if len(runs) > 1 else "")
                am.semilogx(r["freq"], db, style, color=c, lw=1.1, label=label)
                ap_.semilogx(r["freq"], phase, style, color=c, lw=1.1, label=label)
        what = DIRECTIONS[i] if i == j else f"{DIRECTIONS[i]} from {DIRECTIONS[j]}"
        am.set_title(f"{i + 1}{j + 1}: {what}", fontsize=10)
        am.set_ylabel(f"|receptance| [dB re 1 {unit}]")
        ap_.set_ylabel("phase [deg]")
        ap_.set_ylim(-185, 185)
        ap_.set_yticks(range(-180, 181, 90))
        ap_.set_xlabel("frequency [Hz]")
        for ax in (am, ap_):
            ax.grid(alpha=0.3, which="both")
    axes[0, 0].legend(fontsize=8)
    fig.suptitle("\n".join(["wheel, rail and contact receptances"] + [r["title"] for r in runs]), fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print("wrote", out)


if __name__ == "__main__":
    rh.run(main)
