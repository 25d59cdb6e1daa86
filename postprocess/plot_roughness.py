#!/usr/bin/python3
"""Roughness spectra against the EN ISO 3095:2013 rail roughness limit, per wavelength band.

  /usr/bin/python3 postprocess/plot_roughness.py ROUGHNESS.csv [MORE.csv ...] [--label NAME ...]
      [--limit models/roughness/iso3095_2013_limit.csv] [-o roughness.png]

Each file is a roughness in 1/3-octave wavelength bands as EN 15610 and EN ISO 3095 give it, the
form `roughness.rail` and `roughness.wheel` read: CSV lines `wavelength_m,level_dB` (wavelength in
m, level in dB re 1 um), `#` comment lines and a header line allowed. The plot has the wavelength
on a logarithmic axis, long wavelengths on the left (as EN 15610 draws it), the limit as a black
line and each roughness with its bands above the limit marked in red. For each file the script
prints the bands above the limit (at the limit's wavelengths, within 1 % of a band centre) and the
largest excess in dB.
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rollnoise_h5 as rh  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_LIMIT = os.path.join(ROOT, "models", "roughness", "iso3095_2013_limit.csv")


def read_spectrum(path):
    """(wavelengths m, levels dB) of a `wavelength_m,level_dB` CSV; one-line errors otherwise."""
    rh.check_file(path)
    wavelength, level = [], []
    header = False
    with open(path, encoding="utf-8", errors="replace") as f:
        for number, line in enumerate(f, 1):
            text = line.strip()
            if not text or text.startswith("#"):
                continue
            cells = [c.strip() for c in text.split(",")]
            try:
                w, value = float(cells[0]), float(cells[1])
            except (ValueError, IndexError):
                if not wavelength and not header and any(c.isalpha() for c in text):
                    header = True  # the header line, once, before the bands
                    continue
                rh.fail(f"{path}: line {number}: expected 'wavelength_m,level_dB', got {text[:60]!r}")
            if not (w > 0.0 and np.isfinite(w) and np.isfinite(value)):
                rh.fail(f"{path}: line {number}: a wavelength > 0 m and a finite level are needed")
            wavelength.append(w)
            level.append(value)
    if len(wavelength) < 2:
        rh.fail(f"{path}: fewer than two wavelength bands")
    order = np.argsort(wavelength)[::-1]
    return np.array(wavelength)[order], np.array(level)[order]


def excess(limit, spectrum):
    """(wavelengths, level - limit) at the limit's wavelengths that the spectrum has."""
    lw, ll = limit
    sw, sl = spectrum
    at, over = [], []
    for w, value in zip(sw, sl):
        near = np.abs(lw / w - 1.0) < 0.01
        if near.any():
            at.append(w)
            over.append(value - ll[np.argmax(near)])
    return np.array(at), np.array(over)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("files", nargs="+", help="roughness CSV files (wavelength_m, level_dB)")
    ap.add_argument("--label", action="append", default=[], help="a legend label per file")
    ap.add_argument("--limit", default=DEFAULT_LIMIT, help="the limit spectrum (default: EN ISO 3095:2013)")
    ap.add_argument("-o", "--output", default="roughness.png", help="PNG file (default roughness.png)")
    args = ap.parse_args()
    if args.label and len(args.label) != len(args.files):
        rh.fail(f"--label: {len(args.label)} labels for {len(args.files)} files (one per file)")
    limit = read_spectrum(args.limit)
    spectra = [read_spectrum(path) for path in args.files]  # every file checked before plotting
    fig, ax = plt.subplots(figsize=(8.0, 4.8))
    ax.plot(limit[0], limit[1], "k-", lw=2.0, label="EN ISO 3095:2013 limit")
    for i, (path, spectrum) in enumerate(zip(args.files, spectra)):
        label = args.label[i] if args.label else os.path.basename(path)
        line, = ax.plot(spectrum[0], spectrum[1], "o-", ms=3.5, label=label)
        at, over = excess(limit, spectrum)
        above = over > 0.0
        if above.any():
            levels = [spectrum[1][np.argmin(np.abs(spectrum[0] - w))] for w in at[above]]
            ax.plot(at[above], levels, "o", ms=6.0, mfc="none", mec="red")
            bands = ", ".join(f"{100 * w:g} cm" for w in at[above])
            print(f"{label}: {above.sum()} of {len(at)} bands above the limit, largest excess "
                  f"{over.max():.1f} dB ({bands})")
        else:
            print(f"{label}: at or below the limit in all {len(at)} bands (closest {over.max():+.1f} dB)"
                  if len(at) else f"{label}: no band at the limit's wavelengths")
    ax.set_xscale("log")
    ax.invert_xaxis()
    ax.set_xlabel("wavelength (m)")
    ax.set_ylabel("roughness level (dB re 1 µm)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title("Roughness per 1/3-octave wavelength band (red circles: above the limit)")
    fig.tight_layout()
    fig.savefig(args.output, dpi=120)
    plt.close(fig)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    rh.run(main)
