#!/usr/bin/python3
"""Corrugation growth against wavelength (`rollnoise corrugation`, docs/corrugation.md): the growth
rate per passage of each rail (one bogie passage: the sum of its contacts with the wheelbase phase)
and of each contact, against the rail wavelength (top axis: the frequency at the case's speed),
with the peaks of the loop's forces and receptances marked; below, the magnitude and phase of the
depth ratio (wear depth per passage / roughness amplitude) of each rail.

  /usr/bin/python3 postprocess/plot_corrugation.py FILE.h5 [-o OUT.png]

Several files (e.g. a speed sweep) may be given: each adds its rails' growth to the top panel, to
see whether a peak keeps its wavelength (wavelength fixing) or its frequency.
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rollnoise_h5 as rh  # noqa: E402


def read(name):
    """The datasets of one corrugation output: wavelength (mm), speed, rails, contacts, peaks, unit."""
    with rh.open_output(name, "/corrugation/wavelength", "/corrugation/frequency",
                        command="rollnoise corrugation") as f:
        d = {"lam": rh.values(f, "/corrugation/wavelength") * 1e3, "rails": [], "contacts": [], "peaks": []}
        speed = rh.case_value(f, "rolling", "speed")
        d["speed"] = float(speed) if speed else None
        for rail in ("outer", "inner"):
            if f"/corrugation/{rail}/growth_rate" in f:
                d["unit"] = rh.units(f, f"/corrugation/{rail}/growth_rate").split(":")[0]
                d["rails"].append((rail, rh.values(f, f"/corrugation/{rail}/growth_rate"),
                                   rh.values(f, f"/corrugation/{rail}/depth_ratio")))
        if not d["rails"]:
            rh.fail(f"{name}: no /corrugation/outer or /corrugation/inner growth_rate")
        for wheel, grp in f["/corrugation/contacts"].items() if "/corrugation/contacts" in f else []:
            d["contacts"].append((wheel, rh.attribute(grp, "rail"),
                                  rh.values(f, f"/corrugation/contacts/{wheel}/growth_rate")))
        if "/corrugation/peaks/frequency" in f:
            d["peaks"] = list(rh.values(f, "/corrugation/peaks/frequency"))
    return d


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("files", nargs="+")
    ap.add_argument("-o", "--output", default=None, help="PNG file (default FILE_corrugation.png)")
    args = ap.parse_args()
    out = args.output or args.files[0].rsplit(".", 1)[0] + "_corrugation.png"
    data = [read(name) for name in args.files]  # every file checked before any figure
    fig, axes = plt.subplots(3, 1, figsize=(9, 10), sharex=True)
    for i, d in enumerate(data):
        tag = f" (V = {d['speed']:.3g} m/s)" if len(data) > 1 and d["speed"] else ""
        for rail, g, depth in d["rails"]:
            style = "-" if rail == "outer" else "--"
            axes[0].semilogx(d["lam"], g, style, color=rh.file_colour(i), label=f"{rail} rail, bogie{tag}")
            axes[1].loglog(d["lam"], np.abs(depth), style, color=rh.file_colour(i), label=f"{rail} rail{tag}")
            axes[2].semilogx(d["lam"], np.degrees(np.angle(depth)), style, color=rh.file_colour(i),
                             label=f"{rail} rail{tag}")
        if i == 0:
            for k, (wheel, rail, g) in enumerate(d["contacts"]):
                axes[0].semilogx(d["lam"], g, ":", lw=1, color=f"C{k + 2}", label=f"{wheel.replace('_', ' ')} ({rail})")
            for fp in d["peaks"] if d["speed"] else []:
                axes[0].axvline(1e3 * d["speed"] / fp, color="0.8", lw=0.6, zorder=0)
    axes[0].axhline(0.0, color="k", lw=0.8)
    axes[0].set_ylabel(f"growth rate [{data[0]['unit']}]")
    axes[0].set_title("growth of rail roughness per passage (> 0 grows); grey: the loop's peaks")
    axes[1].set_ylabel("|depth / roughness| per passage")
    axes[2].set_ylabel("phase of depth / roughness [deg]")
    axes[2].set_xlabel("rail wavelength [mm]")
    for ax in axes:
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)
    print("wrote", out)


if __name__ == "__main__":
    rh.run(main)
