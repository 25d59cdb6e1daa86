#!/usr/bin/python3
"""Run time against error under grid refinement, from the CSV of `rollnoise bench`.

  /usr/bin/python3 postprocess/plot_bench.py bench.csv [-o bench.png]

Left: error against run time (log-log), one series per quantity, each point labelled with the grid's
nx. The time of a quantity includes what it needs first: f_jk and the transient response start from the
steady state at the mean creepage, so their times are t_steady + t_creep and t_steady + t_transient
(t_steady includes the normal problem); C11 is the normal problem + one steady solve in full adhesion.
Right: error against element size dx with the observed order p, from the least-squares fit of
err_i = C (dx_i^p - dx_ref^p) to all grids but the finest (as `rollnoise bench` prints it; the error
against the finest grid falls faster than dx^p near it); pale lines are those fits.
Dashed: phase-corrected errors (the half-step phase lead w dt/2 of the discrete time stepping
removed, see src/cli/bench_command.cpp), same colour as the raw error.
Errors against the finest grid are zero there and are not drawn; NaN entries (frequencies above a
grid's Nyquist limit, columns missing from older CSVs) are skipped.
"""
import argparse
import csv
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.ticker  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rollnoise_h5 as rh  # noqa: E402

NEEDED = ["nx", "dx_m", "t_steady_s", "t_creep_s", "err_force_rel", "err_C11_kalker_rel"]


def read_table(name):
    """The CSV as a dict column -> numpy array (NaN for missing or unparsable cells)."""
    rh.check_file(name)
    try:
        with open(name, newline="") as f:
            rows = [r for r in csv.reader(line for line in f if line.strip() and not line.startswith("#"))]
    except UnicodeDecodeError:
        rh.fail(f"{name}: not a text file (expected the CSV of `rollnoise bench --csv`)")
    if len(rows) < 2:
        rh.fail(f"{name}: no table (expected the CSV of `rollnoise bench --csv`)")
    header, body = rows[0], rows[1:]
    missing = [c for c in NEEDED if c not in [h.strip() for h in header]]
    if missing:
        rh.fail(f"{name}: no column {', '.join(missing)}: not the CSV of `rollnoise bench --csv`")
    cols = {}
    for j, h in enumerate(header):
        vals = []
        for r in body:
            try:
                vals.append(float(r[j]))
            except (IndexError, ValueError):
                vals.append(math.nan)
        cols[h.strip()] = np.array(vals)
    return cols


def column(t, name):
    return t.get(name, np.full(len(t["nx"]), np.nan))


def observed_order(dx, err):
    """(p, C): least-squares fit in log of err_i = C (dx_i^p - dx_ref^p) over all grids but the
    finest (finite, positive errors); p scanned over [0.2, 4] as in bench_command.cpp."""
    href = dx[-1]
    ok = np.isfinite(err[:-1]) & (err[:-1] > 0) & (dx[:-1] > href)
    h, le = dx[:-1][ok], np.log(err[:-1][ok])
    if len(h) < 2:
        return math.nan, math.nan
    best = (math.inf, math.nan, math.nan)
    for p in np.arange(0.2, 4.0 + 1e-12, 0.002):
        y = le - np.log(h**p - href**p)
        ss = np.sum((y - y.mean()) ** 2)
        if ss < best[0]:
            best = (ss, p, math.exp(y.mean()))
    _, p, C = best
    if p < 0.2 + 1e-9 or p > 4.0 - 1e-9:
        return math.nan, math.nan
    return p, C


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("csv")
    ap.add_argument("-o", "--output", default="bench.png")
    args = ap.parse_args()
    t = read_table(args.csv)
    nx, dx = t["nx"].astype(int), t["dx_m"]
    ts = t["t_steady_s"]
    t_c11 = column(t, "t_C11_s")
    if np.all(np.isnan(t_c11)):
        t_c11 = ts  # older CSVs: the steady solve at the mean creepage as a stand-in
    tc = ts + t["t_creep_s"]
    tt = ts + column(t, "t_transient_s")
    series = [  # label, time, error, style, colour (phase-corrected: the raw one's colour, dashed)
        ("steady forces (Fx, Fy)", ts, t["err_force_rel"], "o-", "C0"),
        ("steady Mz", ts, column(t, "err_mz_rel"), "o:", "C1"),
        ("f11/f22/f23 at 100 Hz", tc, column(t, "err_f_100Hz_rel"), "s-", "C2"),
        ("f11/f22/f23 at 1 kHz", tc, column(t, "err_f_1kHz_rel"), "s-", "C3"),
        ("f11/f22 at 1 kHz, phase-corrected", tc, column(t, "err_f11f22_1kHz_pc_rel"), "s--", "C3"),
        ("f11/f22/f23 at 5 kHz", tc, column(t, "err_f_5kHz_rel"), "s-", "C4"),
        ("f11/f22 at 5 kHz, phase-corrected", tc, column(t, "err_f11f22_5kHz_pc_rel"), "s--", "C4"),
        ("transient Fx, Fy at 1 kHz", tt, column(t, "err_transient_rel"), "^-", "C5"),
        ("transient, phase-corrected", tt, column(t, "err_transient_pc_rel"), "^--", "C5"),
        ("C11 against Kalker's table", t_c11, t["err_C11_kalker_rel"], "d-", "C6"),
    ]
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(14, 8))
    for label, x, y, style, color in series:
        ok = np.isfinite(x) & np.isfinite(y) & (y > 0) & (x > 0)
        if not ok.any():
            continue
        big = label.startswith("transient")  # hollow and larger: drawn over f at 1 kHz otherwise
        kw = dict(color=color, ms=8 if big else 5, mfc="none" if big else color)
        if label.startswith("C11"):
            p, C = math.nan, math.nan  # its limit is not Kalker's table value: no order
            name = f"{label} (no order: the limit is not the table's value)"
        else:
            p, C = observed_order(dx, y)
            name = f"{label}: order {p:.2f}" if np.isfinite(p) else f"{label}: no power law"
        ax1.loglog(x[ok], y[ok], style, label=name, **kw)
        if not label.endswith("corrected"):
            for xi, yi, n in zip(x[ok], y[ok], nx[ok]):
                ax1.annotate(str(n), (xi, yi), textcoords="offset points", xytext=(3, 3), fontsize=7, color=color)
        ax2.loglog(dx[ok] * 1e3, y[ok], style, **kw)
        if np.isfinite(p):
            xx = np.geomspace(dx[-2], dx[:-1][np.isfinite(y[:-1]) & (y[:-1] > 0)].max(), 50)
            ax2.loglog(xx * 1e3, C * (xx**p - dx[-1] ** p), "-", color=color, lw=4, alpha=0.2)
    for ax in (ax1, ax2):
        for tgt in (0.1, 0.01, 0.001):
            ax.axhline(tgt, color="0.6", lw=0.8, ls="-.")
        ax.grid(True, which="both", alpha=0.3)
    ax1.set_xlabel("run time [s] (incl. the steady solve it needs)")
    ax1.set_ylabel(f"relative error (against the finest grid, nx = {nx[-1]})")
    ax1.set_title("error against run time (points labelled with nx)")
    ax2.set_xlabel("element size dx [mm]")
    ax2.set_ylabel("relative error")
    ax2.set_title("error against dx; pale: fits C (dx^p - dx_ref^p)")
    ax2.xaxis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
    ax2.xaxis.set_minor_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
    ax2.invert_xaxis()
    fig.legend(*ax1.get_legend_handles_labels(), loc="lower center", ncol=3, fontsize=9,
               title="quantity: observed order of convergence")
    fig.suptitle(f"rollnoise bench: grid refinement ({args.csv})")
    fig.tight_layout(rect=(0, 0.17, 1, 1))
    fig.savefig(args.output, dpi=120)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    rh.run(main)
