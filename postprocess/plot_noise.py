#!/usr/bin/python3
"""Contact-force spectra of a `rollnoise noise` run.

  /usr/bin/python3 postprocess/plot_noise.py OUT.h5 [--prefix fig]

Writes PREFIX_bands.png (1/3-octave levels of Fz, Fx, Fy, Mz, one panel each: the run's contact
model with the normal -> tangential coupling (solid), without it (dashed, /noise/uncoupled) and the
comparison baseline (dotted, /noise/quasi_steady or /noise/kalker), with the effective roughness
and, on the Fy panel, the mu-scaled normal force 20 log10|Fy_mean/N| + L_Fz) and PREFIX_transfer.png
(narrow-band force per unit roughness, |F/r|, in dB re 1 N/m, the same variants), and with
/noise/wheels (curve.wheels) PREFIX_wheels.png: each wheel's band levels of Fz, Fx, Fy, Mz (its
attribute `loop` says whether the wheels were coupled, noise.contact_coupling), and a second patch's
(noise.second_patch) as one more line; with /noise/sound (noise.sound = "on") PREFIX_sound.png: the
sound power spectra of wheel, rail, sleepers and total (dB re 1 pW, with the A-weighted totals in
the legend) and the mechanical input power, beside the track decay rates (/track/decay_rate) against
the EN ISO 3095:2013 minimum decay rates where the file has them.
Files written before the coupling existed (only /noise/kalker) are plotted too. Band axes are
labelled with the nominal band centres (..., 400, 500, 630, ..., 5000 Hz).
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rollnoise_h5 as rh  # noqa: E402

LABELS = ["Fz", "Fx", "Fy", "Mz"]
WHEELS = ["leading_outer", "leading_inner", "trailing_outer", "trailing_inner"]
BASELINES = [("/noise/quasi_steady", "quasi-steady f(0), g(0)"), ("/noise/kalker", "Kalker steady")]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("file")
    ap.add_argument("--prefix", default=None)
    args = ap.parse_args()
    prefix = args.prefix or args.file.rsplit(".", 1)[0]
    needed = ["/noise/bands/centre", "/noise/bands/force_level", "/noise/bands/roughness_level",
              "/noise/frequency", "/noise/force", "/steady/creepage"]
    with rh.open_output(args.file, *needed, command="rollnoise noise") as f:
        centre = f["/noise/bands/centre"][:]
        rough = f["/noise/bands/roughness_level"][:]
        freq = f["/noise/frequency"][:]
        creep = f["/steady/creepage"][:]
        model = rh.attribute(f["/noise"], "contact_model", "contact model")
        coupling = rh.attribute(f["/noise"], "normal_coupling", "off")
        mean = f["/steady/force"][:] if "/steady/force" in f else None
        normal = f["/noise/contact/normal_force"][()] if "/noise/contact/normal_force" in f else None
        # variants: (label, band levels, narrow-band force, line style)
        main_label = f"{model}" + (", with g" if coupling == "on" else "")
        variants = [(main_label, f["/noise/bands/force_level"][:], f["/noise/force"][:], "-")]
        if "/noise/uncoupled/bands" in f:
            variants.append(("without g (uncoupled)", f["/noise/uncoupled/bands/force_level"][:],
                             f["/noise/uncoupled/force"][:], "--"))
        for path, name in BASELINES:
            if path + "/bands" in f:
                variants.append((name, f[path + "/bands/force_level"][:], f[path + "/force"][:], ":"))
        wheels, wheels_loop = [], ""
        if "/noise/wheels" in f:
            wheels_loop = rh.attribute(f["/noise/wheels"], "loop", "")
            for name in WHEELS:
                if f"/noise/wheels/{name}/bands/force_level" in f:
                    wheels.append((name, f[f"/noise/wheels/{name}/bands/force_level"][:]))
                patch = f"/noise/wheels/{name}/patches/1/bands/force_level"
                if patch in f:  # noise.second_patch = "coupled": the flange patch (noise_loop.md 7.4)
                    wheels.append((name + " flange patch", f[patch][:]))
        sound = read_sound(f)
    title = f"{args.file}: mean creepage ({creep[0]:.3g}, {creep[1]:.3g}, {creep[2]:.3g} rad/m)"

    fig, axes = plt.subplots(2, 2, figsize=(11, 7.5), sharex=True)
    x = np.arange(len(centre))
    colours = ["k", "tab:blue", "tab:red", "tab:green"]
    for j, ax in enumerate(axes.flat):
        for (label, level, _, style), c in zip(variants, ["k", "tab:blue", "tab:orange"]):
            ax.plot(x, level[:, j], style, color=c, marker="o" if style == "-" else None, ms=3, label=label)
        if j == 2 and mean is not None and normal:
            mu_fz = 20 * np.log10(abs(mean[1] / normal)) + variants[0][1][:, 0]
            ax.plot(x, mu_fz, "-", color="tab:red", alpha=0.5, lw=3, label="20 log10|Fy_mean/N| + L_Fz")
        ax.plot(x, rough, "-.", color="0.6", lw=0.8, label="effective roughness, dB re 1 um")
        ax.set_title(LABELS[j], fontsize=10, color=colours[j])
        ax.set_ylabel("dB re 1 N m" if j == 3 else "dB re 1 N")
        rh.set_band_axis(ax, centre, every=1 if len(centre) <= 20 else 2, label=j >= 2)
        ax.grid(alpha=0.3)
    axes[0, 0].legend(fontsize=7)
    axes[1, 0].legend(fontsize=7)
    fig.suptitle(title + f"; normal coupling {coupling}", fontsize=9)
    fig.tight_layout()
    fig.savefig(prefix + "_bands.png", dpi=120)

    fig, axes = plt.subplots(4, 1, figsize=(9, 10), sharex=True)
    for j, ax in enumerate(axes):
        for (label, _, force, style), c in zip(variants, ["k", "tab:blue", "tab:orange"]):
            ax.semilogx(freq, 20 * np.log10(np.abs(force[:, j])), style, color=c, lw=0.8, label=label)
        ax.set_ylabel(f"|{LABELS[j]}/r| dB")
        ax.grid(alpha=0.3, which="both")
    axes[0].legend(fontsize=8)
    axes[0].set_title(title + "; dB re 1 N/m (Mz re 1 N m/m)", fontsize=9)
    axes[-1].set_xlabel("f [Hz]")
    fig.tight_layout()
    fig.savefig(prefix + "_transfer.png", dpi=120)
    written = [prefix + "_bands.png", prefix + "_transfer.png"]
    if wheels:
        plot_wheels(wheels, wheels_loop, centre, args.file, prefix + "_wheels.png")
        written.append(prefix + "_wheels.png")
    if sound:
        plot_sound(sound, args.file, prefix + "_sound.png")
        written.append(prefix + "_sound.png")
    print("wrote", *written)


def read_sound(f):
    """/noise/sound and /track/decay_rate as a dict, or None for a run with noise.sound = "off"."""
    if "/noise/sound/power" not in f:
        return None
    s = {"centre": f["/noise/sound/band_centre"][:], "power": f["/noise/sound/power"][:],
         "power_a": np.atleast_1d(f["/noise/sound/power_a"][()]),
         "input": f["/noise/sound/input_power"][:] if "/noise/sound/input_power" in f else None,
         "note": rh.attribute(f["/noise/sound"], "wheel_missing", "")}
    for d in ("vertical", "lateral"):
        key = "/track/decay_rate/" + d
        s[d] = f[key][:] if key in f else None
        limit = "/track/decay_rate/limit_" + d
        s["limit_" + d] = f[limit][:] if limit in f else None
    return s


def plot_sound(s, name, path):
    """Sound power by source (left) and the track decay rates (right)."""
    fig, (ax, ad) = plt.subplots(1, 2, figsize=(12, 5), gridspec_kw={"width_ratios": [3, 2]})
    x = np.arange(len(s["centre"]))
    sources = [("wheel", "tab:blue", "-"), ("rail", "tab:red", "-"), ("sleepers", "tab:green", "-"),
               ("total", "k", "-")]
    for j, (label, c, ls) in enumerate(sources):
        level = s["power"][:, j]
        if np.all(np.isnan(level)):
            continue
        ax.plot(x, level, ls, color=c, marker="o", ms=3, lw=2 if label == "total" else 1.2,
                label=f"{label}: {s['power_a'][j]:.1f} dB(A)")
    if s["input"] is not None:
        ax.plot(x, s["input"], ":", color="0.5", label="mechanical input power (bound)")
    ax.set_ylabel("sound power, dB re 1 pW")
    rh.set_band_axis(ax, s["centre"], every=1 if len(x) <= 20 else 2)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title(f"{name}: sound power by source" + (" (no wheel surface)" if s["note"] else ""), fontsize=9)
    for d, c in (("vertical", "k"), ("lateral", "tab:blue")):
        if s[d] is not None:
            ad.plot(x, s[d], "-o", color=c, ms=3, label=f"{d}")
        if s["limit_" + d] is not None:
            ad.plot(x, s["limit_" + d], "--", color=c, label=f"{d}: EN ISO 3095 minimum")
    ad.set_yscale("log")
    ad.set_ylabel("decay rate, dB/m")
    rh.set_band_axis(ad, s["centre"], every=2)
    ad.grid(alpha=0.3, which="both")
    ad.legend(fontsize=8)
    ad.set_title("track decay rates (EN 15461)", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def plot_wheels(wheels, loop, centre, name, path):
    """One panel per force component, one line per wheel of /noise/wheels."""
    fig, axes = plt.subplots(2, 2, figsize=(11, 7.5), sharex=True)
    x = np.arange(len(centre))
    styles = {"leading_outer": ("k", "-"), "leading_inner": ("tab:blue", "-"),
              "trailing_outer": ("k", "--"), "trailing_inner": ("tab:blue", "--"),
              "leading_outer flange patch": ("tab:red", ":")}
    for j, ax in enumerate(axes.flat):
        for wheel, level in wheels:
            c, ls = styles[wheel]
            ax.plot(x, level[:, j], ls, color=c, marker="o", ms=3, label=wheel)
        ax.set_title(LABELS[j], fontsize=10)
        ax.set_ylabel("dB re 1 N m" if j == 3 else "dB re 1 N")
        rh.set_band_axis(ax, centre, every=1 if len(centre) <= 20 else 2, label=j >= 2)
        ax.grid(alpha=0.3)
    axes[0, 0].legend(fontsize=7)
    coupled = "coupled" if loop.startswith("coupled") else "each wheel alone"
    fig.suptitle(f"{name}: band levels of every wheel ({coupled})", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


if __name__ == "__main__":
    rh.run(main)
