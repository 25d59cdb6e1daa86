#!/usr/bin/python3
"""Contact forces, velocities and sound power of one or more `rollnoise noise` runs.

  /usr/bin/python3 postprocess/plot_noise.py OUT.h5 [MORE.h5 ...] [--label L ...] [--wheel W] [--prefix P]

OUT.h5 is the output of `rollnoise noise`. With several files, each run is one more line on the
same axes, labelled by --label (once per file, in order) or else by the file's stem; the band axis
is the union of the runs' bands. The levels are those of one wheel: with per-wheel groups
(/noise/wheels/<wheel>, curve.wheels) the wheel --wheel (default leading_outer), else the file's
single contact (/noise). Each title says which wheel and which loop (from the file's `loop`
attribute, e.g. "leading outer wheel, bogie loop (4 contacts coupled)").

Writes
  PREFIX_bands.png     1/3-octave levels of Fz, Fx, Fy, Mz (one panel each; dB re 1 N, Mz re 1 N m)
                       and, in a panel of its own, the effective roughness (dB re 1 um). One file:
                       also the variants the file holds for its top-level loop (without the normal
                       -> tangential coupling g, /noise/uncoupled; the baseline /noise/quasi_steady or
                       /noise/kalker) and, on the Fy panel, the mu-scaled normal force
                       20 log10|Fy_mean/N| + L_Fz.
  PREFIX_transfer.png  narrow-band force per unit roughness |F/r| (dB re 1 N/m, Mz re 1 N m/m).
  PREFIX_velocity.png  1/3-octave velocity levels of wheel and rail at the contact (dB re 1e-9 m/s,
                       rotation re 1e-9 rad/s), when the files have them.
  PREFIX_wheels.png    with /noise/wheels: every wheel's band levels (colour: wheel; line style: file).
  PREFIX_sound.png     with /noise/sound (noise.sound = "on"): sound power of wheel, rail, sleepers
                       and total (dB re 1 pW, A-weighted totals in the legend; what the sum covers
                       from the attribute `sum`), the mechanical input power, and the track decay
                       rates against the EN ISO 3095:2013 minimum (colour: source; line style: file).
PREFIX defaults to the file name without its extension (one file) or to noise_compare beside the
first file (several). Band axes are labelled with the nominal band centres (..., 400, 500, 630 Hz).
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rollnoise_h5 as rh  # noqa: E402

LABELS = ["Fz", "Fx", "Fy", "Mz"]
FORCE_UNITS = ["dB re 1 N", "dB re 1 N", "dB re 1 N", "dB re 1 N m"]
TRANSFER_UNITS = ["dB re 1 N/m", "dB re 1 N/m", "dB re 1 N/m", "dB re 1 N m/m"]
VELOCITY_LABELS = ["vertical (z)", "longitudinal (x)", "lateral (y)", "rotation about z"]
VELOCITY_UNITS = ["dB re 1e-9 m/s"] * 3 + ["dB re 1e-9 rad/s"]
BASELINES = [("/noise/quasi_steady", "quasi-steady f(0), g(0)"), ("/noise/kalker", "Kalker steady")]
WHEEL_COLOURS = {"leading_outer": "k", "leading_inner": "tab:blue", "trailing_outer": "tab:green",
                 "trailing_inner": "tab:purple"}
DPI = 110


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("files", nargs="+", metavar="FILE")
    ap.add_argument("--label", action="append", default=[], help="legend label of a file (once per file, in order)")
    ap.add_argument("--wheel", choices=rh.WHEELS, default=None,
                    help="the wheel whose levels are drawn when the files have /noise/wheels (default leading_outer)")
    ap.add_argument("--prefix", default=None, help="output file prefix")
    args = ap.parse_args()
    labels = rh.file_labels(args.files, args.label)
    runs = [read_run(path, label, args.wheel) for path, label in zip(args.files, labels)]
    if args.prefix:
        prefix = args.prefix
    elif len(args.files) == 1:
        prefix = args.files[0].rsplit(".", 1)[0]
    else:
        prefix = os.path.join(os.path.dirname(args.files[0]), "noise_compare")
    nominal, xs = rh.band_union([r["centre"] for r in runs])
    for r, x in zip(runs, xs):
        r["x"] = x
    written = [plot_bands(runs, nominal, prefix + "_bands.png"), plot_transfer(runs, prefix + "_transfer.png")]
    if any(r["velocity"] is not None for r in runs):
        written.append(plot_velocity(runs, nominal, prefix + "_velocity.png"))
    if any(r["wheels"] for r in runs):
        written.append(plot_wheels(runs, nominal, prefix + "_wheels.png"))
    if any(r["sound"] for r in runs):
        written.append(plot_sound(runs, prefix + "_sound.png"))
    print("wrote", *written)


def read_run(path, label, wheel):
    """Everything the figures need from one file, as a dict."""
    needed = ["/noise/bands/centre", "/noise/bands/force_level", "/noise/bands/roughness_level",
              "/noise/frequency", "/noise/force"]
    with rh.open_output(path, *needed, command="rollnoise noise") as f:
        group, where, coupled = rh.noise_group(f, wheel)
        r = {"label": label, "where": where, "centre": f["/noise/bands/centre"][:],
             "rough": f["/noise/bands/roughness_level"][:],
             "rough_units": rh.units(f, "/noise/bands/roughness_level", "dB re 1 um").split(" (")[0],
             "freq": f["/noise/frequency"][:], "level": f[group + "/bands/force_level"][:],
             "force": f[group + "/force"][:] if group + "/force" in f else None,
             "velocity": f[group + "/bands/velocity_level"][:] if group + "/bands/velocity_level" in f else None}
        if r["force"] is None:  # a wheel without its own source: no narrow-band force of its own
            r["force"] = np.full((len(r["freq"]), 4), np.nan)
        contact = group + "/contact/creepage" if group != "/noise" else "/steady/creepage"
        r["creep"] = f[contact][:] if contact in f else None
        model = rh.attribute(f["/noise"], "contact_model", "contact model")
        coupling = rh.attribute(f["/noise"], "normal_coupling", "off")
        r["coupling"] = coupling
        # the variants the file holds for its top-level loop: (label, band levels, narrow-band force, style,
        # colour). They belong to the drawn wheel when /noise is its loop; with a coupled bogie loop /noise
        # is another loop (the file's `loop` attribute says which): drawn, labelled as such, when it is
        # the same wheel's contact alone, left out for the other wheels.
        main = f"{model}" + (", with g" if coupling == "on" else "")
        # files that name their reported wheel (/noise attribute `wheel`): /noise is that wheel's answer
        # in the case's loop, the same numbers as its group
        reported = rh.attribute(f["/noise"], "wheel", "")
        same_loop = group == "/noise" or (group == f"/noise/wheels/{reported}" if reported else
                                          (not coupled and group == "/noise/wheels/leading_outer"))
        r["variants"] = [(main if same_loop else f"{main} [{r['where']}]", r["level"], r["force"], "-", "k")]
        top = rh.top_level_words(f)
        suffix = "" if same_loop else f" [{top}]"
        # the top-level loop of the same wheel (its own contact alone): worth the comparison
        same_wheel = same_loop or (coupled and rh.wheel_words(group.rsplit("/", 1)[-1]) in top)
        if coupled and same_wheel and not same_loop:
            r["variants"].append((f"{main}{suffix}", f["/noise/bands/force_level"][:], f["/noise/force"][:], "-",
                                  "tab:purple"))
        if same_wheel:
            if "/noise/uncoupled/bands" in f:
                r["variants"].append((f"without g (uncoupled){suffix}", f["/noise/uncoupled/bands/force_level"][:],
                                      f["/noise/uncoupled/force"][:], "--", "tab:blue"))
            for p, name in BASELINES:
                if p + "/bands" in f:
                    r["variants"].append((name + suffix, f[p + "/bands/force_level"][:], f[p + "/force"][:], ":",
                                          "tab:orange"))
        # the mean lateral force over the normal force (the mu-scaled line of the Fy panel)
        mean_path = group + "/contact/loop_mean_force" if group != "/noise" else "/steady/force"
        normal_path = group + "/contact/normal_force" if group != "/noise" else "/noise/contact/normal_force"
        r["fy_over_n"] = (abs(f[mean_path][1] / f[normal_path][()]) if mean_path in f and normal_path in f
                          and f[normal_path][()] else None)
        r["wheels"], r["wheels_loop"] = [], ""
        if "/noise/wheels" in f:
            loop = rh.attribute(f["/noise/wheels"], "loop", "") or ""
            coupled_loop = loop.startswith("coupled")
            for name in rh.WHEELS:
                if f"/noise/wheels/{name}/bands/force_level" in f:
                    r["wheels"].append((name, f[f"/noise/wheels/{name}/bands/force_level"][:]))
                patch = f"/noise/wheels/{name}/patches/1/bands/force_level"
                if patch in f:  # noise.second_patch = "coupled": the flange patch (noise_loop.md 7.4)
                    r["wheels"].append((name + " flange patch", f[patch][:]))
            r["wheels_loop"] = (f"bogie loop ({len(r['wheels'])} contacts coupled)"
                                if coupled_loop and len(r["wheels"]) > 1
                                else "a loop of one contact" if len(r["wheels"]) == 1
                                else "each wheel's single-contact loop alone (wheels not coupled)")
        r["sound"] = read_sound(f)
    return r


def read_sound(f):
    """/noise/sound and /track/decay_rate as a dict, or None for a run with noise.sound = "off"."""
    if "/noise/sound/power" not in f:
        return None
    total = rh.attribute(f["/noise/sound"], "sum", "") or ""
    if total.startswith("the bogie"):
        covers = "the bogie: every wheel and rail"
    elif total:
        covers = total.split(" (")[0]
    else:
        covers = "the run's contact"
    s = {"centre": f["/noise/sound/band_centre"][:], "power": f["/noise/sound/power"][:],
         "power_a": np.atleast_1d(f["/noise/sound/power_a"][()]), "covers": covers,
         "input": f["/noise/sound/input_power"][:] if "/noise/sound/input_power" in f else None,
         "note": rh.attribute(f["/noise/sound"], "wheel_missing", "")}
    for d in ("vertical", "lateral"):
        key = "/track/decay_rate/" + d
        s[d] = f[key][:] if key in f else None
        limit = "/track/decay_rate/limit_" + d
        s["limit_" + d] = f[limit][:] if limit in f else None
    return s


def describe(r, with_creep=True):
    """One line per file for a title: label, wheel and loop, mean creepage."""
    text = f"{r['label']}: {r['where']}"
    if with_creep and r["creep"] is not None:
        c = r["creep"]
        text += f"; mean creepage ({c[0]:.3g}, {c[1]:.3g}, {c[2]:.3g} rad/m)"
    return text


def suptitle(fig, runs, what, with_creep=True):
    lines = [what] + [describe(r, with_creep) for r in runs]
    fig.suptitle("\n".join(lines), fontsize=10)


def band_axes(ax, nominal, label=True, most=20):
    rh.set_band_axis(ax, nominal, every=1 if len(nominal) <= most else 2, label=label)
    ax.set_xlim(-0.5, len(nominal) - 0.5)
    ax.grid(alpha=0.3)


def lines(runs):
    """(run, label, band levels, narrow-band force, style, colour) of every line: one file, its
    variants; several files, each file's main level in a colour of its own."""
    if len(runs) == 1:
        r = runs[0]
        return [(r, label, level, force, style, c) for label, level, force, style, c in r["variants"]]
    return [(r, r["label"], r["level"], r["force"], "-", rh.file_colour(i)) for i, r in enumerate(runs)]


def legend_panel(ax, axes, ncol=2):
    """The legend of the lines on `axes` (each label once) in the empty panel `ax`, off the data."""
    seen = {}
    for a in axes:
        for h, label in zip(*a.get_legend_handles_labels()):
            seen.setdefault(label, h)
    ax.axis("off")
    ax.legend(list(seen.values()), list(seen.keys()), loc="center", ncol=ncol, fontsize=9, frameon=False)


def plot_bands(runs, nominal, path):
    """Force band levels (2 x 2 panels) above the effective roughness (its own panel and unit); the
    legend in a row of its own above the panels."""
    n = len(lines(runs)) + (1 if len(runs) == 1 and runs[0]["fy_over_n"] else 0)
    ncol = 1 if len(runs) == 1 else 2
    rows = -(-n // ncol)
    fig = plt.figure(figsize=(11, 10.2 + 0.16 * rows))
    gs = fig.add_gridspec(4, 2, height_ratios=[0.045 * rows + 0.03, 1, 1, 0.7])
    axes = [fig.add_subplot(gs[1, 0]), fig.add_subplot(gs[1, 1]), fig.add_subplot(gs[2, 0]),
            fig.add_subplot(gs[2, 1])]
    ar = fig.add_subplot(gs[3, :])
    for j, ax in enumerate(axes):
        for r, label, level, _, style, c in lines(runs):
            ax.plot(r["x"], level[:, j], style, color=c, marker="o" if style == "-" else None, ms=3, label=label)
        if j == 2 and len(runs) == 1 and runs[0]["fy_over_n"]:
            r = runs[0]
            ax.plot(r["x"], 20 * np.log10(r["fy_over_n"]) + r["level"][:, 0], "-", color="tab:red", alpha=0.5,
                    lw=3, label="Fy panel: 20 log10|Fy_mean/N| + L_Fz (mu-scaled normal force)")
        ax.set_title(f"{LABELS[j]} (contact force band level)", fontsize=10)
        ax.set_ylabel(f"{LABELS[j]} [{FORCE_UNITS[j]}]")
        band_axes(ax, nominal, label=False)
    legend_panel(fig.add_subplot(gs[0, :]), axes, ncol=ncol)
    for i, r in enumerate(runs):
        ar.plot(r["x"], r["rough"], "-", color=rh.file_colour(i), marker="o", ms=3, label=r["label"])
    ar.set_title("effective roughness (wheel + rail, after the contact filter)", fontsize=10)
    ar.set_ylabel(f"roughness [{rh.pretty(runs[0]['rough_units'])}]")
    band_axes(ar, nominal)
    if len(runs) > 1:
        ar.legend(fontsize=8)
    suptitle(fig, runs, "contact force band levels")
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    return path


def plot_transfer(runs, path):
    """Narrow-band force per unit roughness, one panel per component."""
    fig, axes = plt.subplots(4, 1, figsize=(9, 11), sharex=True)
    for j, ax in enumerate(axes):
        for r, label, _, force, style, c in lines(runs):
            with np.errstate(divide="ignore", invalid="ignore"):
                ax.semilogx(r["freq"], 20 * np.log10(np.abs(force[:, j])), style, color=c, lw=0.8, label=label)
        ax.set_ylabel(f"|{LABELS[j]}/r| [{TRANSFER_UNITS[j]}]")
        ax.grid(alpha=0.3, which="both")
    axes[0].legend(fontsize=8)
    axes[-1].set_xlabel("frequency [Hz]")
    suptitle(fig, runs, "narrow-band contact force per unit roughness")
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    return path


def plot_velocity(runs, nominal, path):
    """Band velocity levels at the contact: wheel (top row) and rail (bottom row), one column per
    direction; one line per file."""
    fig, axes = plt.subplots(2, 4, figsize=(15, 7.5), sharex=True)
    for k, side in enumerate(["wheel", "rail"]):
        for j in range(4):
            ax = axes[k, j]
            for i, r in enumerate(runs):
                if r["velocity"] is not None:
                    ax.plot(r["x"], r["velocity"][:, k, j], "-", color=rh.file_colour(i), marker="o", ms=3,
                            label=r["label"])
            ax.set_title(f"{side}, {VELOCITY_LABELS[j]}", fontsize=10)
            ax.set_ylabel(f"velocity level [{VELOCITY_UNITS[j]}]")
            band_axes(ax, nominal, label=k == 1, most=12)
    axes[0, 0].legend(fontsize=8)
    suptitle(fig, runs, "velocity band levels at the contact")
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    return path


def plot_wheels(runs, nominal, path):
    """One panel per force component, one line per wheel of /noise/wheels (colour), per file (style)."""
    fig, axes = plt.subplots(2, 2, figsize=(11, 8), sharex=True)
    runs = [r for r in runs if r["wheels"]]
    nominal, xs = rh.band_union([r["centre"] for r in runs])  # the bands of the files with wheels
    several = len(runs) > 1
    for j, ax in enumerate(axes.flat):
        for i, (r, x) in enumerate(zip(runs, xs)):
            for wheel, level in r["wheels"]:
                patch = wheel.endswith("flange patch")
                c = "tab:red" if patch else WHEEL_COLOURS[wheel]
                style = ":" if patch else rh.file_style(i)
                label = rh.wheel_words(wheel) + (f" ({r['label']})" if several else "")
                ax.plot(x, level[:, j], style, color=c, marker="o", ms=3, label=label)
        ax.set_title(f"{LABELS[j]} (contact force band level)", fontsize=10)
        ax.set_ylabel(f"{LABELS[j]} [{FORCE_UNITS[j]}]")
        band_axes(ax, nominal, label=j >= 2)
    axes[0, 1].legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.02, 1))
    lines_ = ["band levels of every wheel"] + [f"{r['label']}: {r['wheels_loop']}" for r in runs]
    fig.suptitle("\n".join(lines_), fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    return path


def plot_sound(runs, path):
    """Sound power by source (top) and the track decay rates (bottom), legends on the right; colour:
    source or direction, line style: file."""
    fig, (ax, ad) = plt.subplots(2, 1, figsize=(13, 10), gridspec_kw={"height_ratios": [3, 2]})
    sound = [(i, r, r["sound"]) for i, r in enumerate(runs) if r["sound"]]
    nominal, xs = rh.band_union([s["centre"] for _, _, s in sound])
    several = len(sound) > 1
    sources = [("wheel", "tab:blue"), ("rail", "tab:red"), ("sleepers", "tab:green"), ("total", "k")]
    limits_drawn = set()
    for (i, r, s), x in zip(sound, xs):
        style = rh.file_style(i)
        tag = f"{r['label']}: " if several else ""
        for j, (name, c) in enumerate(sources):
            level = s["power"][:, j]
            if np.all(np.isnan(level)):
                continue
            ax.plot(x, level, style, color=c, marker="o", ms=3, lw=2 if name == "total" else 1.2,
                    label=f"{tag}{name}: {s['power_a'][j]:.1f} dB(A)")
        if s["input"] is not None:
            ax.plot(x, s["input"], style, color="0.6", lw=1, label=f"{tag}mechanical input power (bound)")
        for d, c in (("vertical", "k"), ("lateral", "tab:blue")):
            if s[d] is not None:
                ad.plot(x, s[d], style, color=c, marker="o", ms=3, label=f"{tag}{d}")
            if s["limit_" + d] is not None and d not in limits_drawn:
                limits_drawn.add(d)
                ad.plot(x, s["limit_" + d], "-", color=c, lw=4, alpha=0.25, label=f"{d}: EN ISO 3095 minimum")
    ax.set_ylabel("sound power level [dB re 1 pW]")
    ax.set_title("sound power by source", fontsize=10)
    band_axes(ax, nominal)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1))
    ad.set_yscale("log")
    ad.set_ylabel("decay rate [dB/m]")
    ad.set_title("track decay rates (EN 15461)", fontsize=10)
    band_axes(ad, nominal)
    ad.grid(alpha=0.3, which="both")
    ad.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1))
    lines_ = ["sound power"] + [f"{r['label']}: {s['covers']}" + (" (no wheel surface to radiate from: wheel.model ="
                                                                  " \"table\")" if s["note"] else "")
                                for _, r, s in sound]
    fig.suptitle("\n".join(lines_), fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    return path


if __name__ == "__main__":
    rh.run(main)
