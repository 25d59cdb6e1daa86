#!/usr/bin/python3
"""Band levels of a study against one or two of its parameters (docs/study.md).

  /usr/bin/python3 postprocess/plot_study.py OUTPUT/study.h5 --x curve.radius [--curves rolling.speed]
                                             [--band 1000] [--quantity Fy] [-o fig.png]

Reads the table `rollnoise collect` writes. Draws the level of QUANTITY (Fz, Fx, Fy, Mz: contact-force
band levels; wheel_vz, rail_vy, ...: velocity levels) in the 1/3-octave band nearest BAND Hz against
the parameter X, one curve per value of CURVES. Failed and missing cases are left out and counted
in the title.
"""
import argparse
import os

import numpy as np

import rollnoise_h5 as rh

FORCES = ["Fz", "Fx", "Fy", "Mz"]
VELOCITIES = ["vz", "vx", "vy", "wz"]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("file", help="study.h5 written by rollnoise collect")
    ap.add_argument("--x", required=True, help="the parameter on the horizontal axis (a key of the study's axes)")
    ap.add_argument("--curves", help="one curve per value of this parameter")
    ap.add_argument("--band", type=float, default=1000.0, help="band centre (Hz), the nearest band is drawn")
    ap.add_argument("--quantity", default="Fz", help="Fz, Fx, Fy, Mz or wheel_vz, rail_vy, ... (default Fz)")
    ap.add_argument("-o", "--output", help="PNG file (default: study_QUANTITY_BANDHz.png beside the table)")
    args = ap.parse_args()

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    with rh.open_output(args.file, "/study/parameters", "/study/force_level", command="rollnoise collect") as f:
        s = f["study"]
        params = s["parameters"]
        for key in [args.x] + ([args.curves] if args.curves else []):
            if key not in params:
                rh.fail(f"{args.file}: '{key}' is not a parameter of the study (its axes: {', '.join(params.keys())})")
        status = s["status"][:]
        centres = s["band_centre"][:]
        if centres.size == 0:
            rh.fail(f"{args.file}: no complete case in the study, nothing to draw")
        b = int(np.argmin(np.abs(np.log(centres / args.band))))
        q = args.quantity
        side, _, comp = q.partition("_")
        if q in FORCES:
            level = s["force_level"][:, b, FORCES.index(q)]
            units = "dB re 1 N m" if q == "Mz" else "dB re 1 N"
        elif side in ("wheel", "rail") and comp in VELOCITIES:
            level = s["velocity_level"][:, b, 0 if side == "wheel" else 1, VELOCITIES.index(comp)]
            units = "dB re 1e-9 rad/s" if comp == "wz" else "dB re 1e-9 m/s"
        else:
            rh.fail(f"unknown quantity '{q}' (Fz, Fx, Fy, Mz, wheel_vz, rail_vy, ...)")
        x = params[args.x][:]
        if x.dtype.kind not in "fiu":
            rh.fail(f"{args.file}: '{args.x}' is not numeric: choose a numeric parameter for the horizontal axis")
        x_units = rh.units(f, f"/study/parameters/{args.x}", "-")
        groups = [(None, np.ones(len(x), bool))]
        if args.curves:
            c = params[args.curves][:]
            groups = [(v, c == v) for v in np.unique(c)]
        ok = status == 0
        fig, ax = plt.subplots(figsize=(7, 4.5))
        for value, sel in groups:
            m = sel & ok
            order = np.argsort(x[m])
            label = None if value is None else f"{args.curves} = {rh.text(value)}"
            ax.plot(x[m][order], level[m][order], "o-", ms=3, label=label)
        if ok.any() and np.all(x[ok] > 0) and x[ok].max() > 5 * x[ok].min():
            ax.set_xscale("log")
        ax.set_xlabel(f"{args.x} [{x_units}]")
        ax.set_ylabel(f"{q}, {rh.band_label(centres[b])} Hz band [{units}]")
        bad = int(np.sum(~ok))
        ax.set_title(f"{len(x)} cases" + (f", {bad} failed or missing (not drawn)" if bad else ""))
        if args.curves:
            ax.legend(fontsize=8)
        ax.grid(True, which="both", alpha=0.3)
        out = args.output or os.path.join(os.path.dirname(args.file),
                                          f"study_{q}_{rh.band_label(centres[b])}Hz.png")
        fig.tight_layout()
        fig.savefig(out, dpi=120)
        print(f"wrote {out}")


if __name__ == "__main__":
    rh.run(main)
