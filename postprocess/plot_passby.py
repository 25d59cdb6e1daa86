#!/usr/bin/python3
"""A train's pass-by: the A-weighted level against time and the L_eq spectrum by source.

  /usr/bin/python3 postprocess/plot_passby.py OUT.h5 [-o passby.png]

OUT.h5 is the output of `rollnoise passby`: /passby/time (s) and /passby/level_a (dB(A), F time
weighting) on the left, with the pass-by time T_p (/passby/passage_time) shaded and the levels
L_pAeq,Tp, L_pAFmax and TEL (/passby/leq_a, lmax_a, tel) as lines; on the right /passby/spectrum
[band][wheel, rail, sleepers, total] (dB re 20 uPa, L_eq over T_p, unweighted) against
/passby/band_centre, with the TSI limit (/passby/limit_a, when the case named a category) in the
title beside L_pAeq,Tp normalised to 80 km/h (/passby/leq_a_80). The output defaults to
FILE_passby.png beside the file.
"""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rollnoise_h5 as rh  # noqa: E402

SOURCES = [("wheel", "tab:blue"), ("rail", "tab:red"), ("sleepers", "tab:green"), ("total", "k")]


def scalar(f, path):
    return float(np.atleast_1d(f[path][()])[-1])


def main():
    path, out = rh.file_and_output(__doc__, "_passby.png")
    need = [f"/passby/{k}" for k in ("time", "level_a", "leq_a", "tel", "lmax_a", "band_centre", "spectrum",
                                     "passage_time")]
    with rh.open_output(path, *need, command="rollnoise passby") as f:
        t, level = f["/passby/time"][()], f["/passby/level_a"][()]
        tp = scalar(f, "/passby/passage_time")
        leq, lmax, tel = scalar(f, "/passby/leq_a"), scalar(f, "/passby/lmax_a"), scalar(f, "/passby/tel")
        fc, spectrum = f["/passby/band_centre"][()], f["/passby/spectrum"][()]
        leq80 = scalar(f, "/passby/leq_a_80") if "/passby/leq_a_80" in f else None
        limit = scalar(f, "/passby/limit_a") if "/passby/limit_a" in f else None
        category = rh.attribute(f["/passby/limit_a"], "category", "") if limit is not None else ""
    if spectrum.ndim != 2 or spectrum.shape != (len(fc), 4) or len(t) != len(level):
        rh.fail(f"{path}: /passby/spectrum is not [band][4] or /passby/level_a not one per time")
    fig, (ah, asp) = plt.subplots(1, 2, figsize=(12, 4.5))
    ah.plot(t, level, "k", lw=1.0, label="$L_{pAF}(t)$")
    ah.axvspan(0.0, tp, color="0.9", label="$T_p$")
    for value, style, name in [(leq, "--", "$L_{pAeq,Tp}$"), (lmax, ":", "$L_{pAFmax}$"), (tel, "-.", "TEL")]:
        ah.axhline(value, ls=style, color="tab:purple", lw=1.0, label=f"{name} {value:.1f} dB(A)")
    finite = level[np.isfinite(level)]
    ah.set_ylim(max(finite.min(), lmax - 40.0), lmax + 5.0)
    ah.set_xlabel("time [s] (the front passes at 0)")
    ah.set_ylabel("A-weighted level [dB(A) re 20 uPa]")
    ah.grid(alpha=0.3)
    ah.legend(fontsize=8, loc="lower center")
    x = np.arange(len(fc))
    for k, (name, colour) in enumerate(SOURCES):
        asp.plot(x, spectrum[:, k], "o-" if name != "total" else "s-", color=colour, lw=1.2, ms=3, label=name)
    rh.set_band_axis(asp, fc, every=max(1, len(fc) // 12))
    asp.set_ylabel("$L_{eq,Tp}$ per band [dB re 20 uPa]")
    asp.grid(alpha=0.3)
    asp.legend(fontsize=8)
    title = f"{path}: $L_{{pAeq,Tp}}$ = {leq:.1f} dB(A)"
    if leq80 is not None:
        title += f", at 80 km/h {leq80:.1f} dB(A)"
    if limit is not None:
        title += f"; TSI limit ({category}) {limit:.0f} dB(A)"
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print("wrote", out)


if __name__ == "__main__":
    rh.run(main)
