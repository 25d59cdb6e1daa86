#!/usr/bin/python3
"""Curve-squeal map: runs `rollnoise squeal` over curve radius x one friction parameter (--set on a
case), collects /squeal/* of every run and plots the occurrence (stable / squeal / contact alone
unstable) and the largest growth rate Re s with the labels of the unstable modes (docs/squeal.md);
legends explain the cell colours, titles name the contact the map shows (the top-level /squeal: the
leading outer wheel's single contact, as the files' `loop` attribute says) and the wheelsets' loop.

  /usr/bin/python3 postprocess/plot_squeal_map.py [--case cases/squeal_150m.toml]
      [--radii 100,150,200,300,500,1000] [--param friction.decay --values 0.5,1,2,3,4]
      [--binary build/rollnoise] [--work squeal_map] [-j 2] [-o squeal_map.png] [--set KEY=VALUE] [--fast]
      [--wheelsets]

--wheelsets: also the squeal of each wheelset with both its contacts (noise.squeal_wheelsets = "on",
profiles only, docs/squeal.md Sec. 8.2): a third panel shows which wheels squeal (the unstable roots
of /squeal/wheels/unstable by wheel, or that a wheelset was left out because a wheel's contact
alone is unstable), and summary.csv gets the unstable roots per wheel.

Each run writes WORK/r<R>_<i>.h5; a run the program refuses because the linearised contact alone
is unstable (InputError naming friction.decay, docs/squeal.md) is a cell of its own class; any other
failed run is marked "failed" with its message in WORK/summary.csv. --fast: 2 x 2 runs (smoke test).
"""
import argparse
import concurrent.futures
import csv
import os
import re
import subprocess

import numpy as np

import rollnoise_h5 as rh

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STABLE, SQUEAL, CONTACT_UNSTABLE, FAILED = 0, 1, 2, 3
CLASS_NAMES = ["stable", "squeal", "contact alone unstable", "failed"]
PARAM_UNITS = {"friction.mu": "-", "friction.decay": "s/m", "friction.kinetic_ratio": "-",
               "curve.cant_deficiency": "m", "rolling.speed": "m/s"}  # the axis unit of the varied key


def floats(text):
    try:
        return [float(v) for v in text.split(",") if v.strip()]
    except ValueError:
        rh.fail(f"not a comma-separated list of numbers: {text!r}")


def run_one(binary, case, work, radius, param, value, index, extra):
    out = os.path.join(work, f"r{radius:g}_{index}.h5")
    cmd = [binary, "squeal", case, "-o", out, "-q", "--set", f"curve.radius={radius!r}", "--set", f"{param}={value!r}"]
    for s in extra:
        cmd += ["--set", s]
    r = subprocess.run(cmd, capture_output=True, text=True)
    cell = {"radius": radius, "value": value, "file": out, "message": "", "growth": np.nan, "modes": [],
            "frequency": np.nan}
    if r.returncode != 0:
        msg = (r.stderr.strip() or r.stdout.strip()).splitlines()
        cell["message"] = msg[-1] if msg else f"exit {r.returncode}"
        unstable_contact = "linearised contact alone is unstable" in (r.stderr + r.stdout)
        cell["class"] = CONTACT_UNSTABLE if unstable_contact else FAILED
        return cell
    import h5py
    with h5py.File(out, "r") as f:
        s = np.asarray(f["/squeal/eigenvalue"][()])
        unstable = np.asarray(f["/squeal/unstable"][()]).astype(bool)
        labels = [rh.text(v) for v in f["/squeal/mode"][()]]
        freq = np.asarray(f["/squeal/frequency"][()])
    k = int(np.argmax(s.real))
    cell["growth"], cell["frequency"] = float(s.real[k]), float(freq[k])
    cell["modes"] = [f"{labels[i]} ({freq[i]:.0f} Hz)" for i in np.flatnonzero(unstable)]
    cell["class"] = SQUEAL if unstable.any() else STABLE
    cell.update(wheel_roots(out))
    return cell


WHEELS = ["leading_outer", "leading_inner", "trailing_outer", "trailing_inner"]
WHEEL_SHORT = {"leading_outer": "LO", "leading_inner": "LI", "trailing_outer": "TO", "trailing_inner": "TI"}


def wheel_roots(path):
    """The unstable roots of the wheelsets (/squeal/wheels/unstable) by wheel, and the wheelsets left
    out (attribute left_out); empty when the run has no per-wheelset squeal."""
    import h5py
    out = {"wheel_modes": {}, "left_out": "", "wheelsets": False, "loop": ""}
    with h5py.File(path, "r") as f:
        if "/squeal/wheels" not in f:
            return out
        g = f["/squeal/wheels"]
        out["wheelsets"] = True
        out["loop"] = rh.text(g.attrs.get("loop", ""))
        out["left_out"] = rh.text(g.attrs["left_out"]) if "left_out" in g.attrs else ""
        if "unstable" in g and "wheel" in g["unstable"]:
            u = g["unstable"]
            for w, m, fr in zip(u["wheel"][()], u["mode"][()], u["frequency"][()]):
                out["wheel_modes"].setdefault(rh.text(w), []).append(f"{rh.text(m)} ({fr:.0f} Hz)")
    return out


def wheel_cell_text(c):
    """Which wheels squeal in one cell: 'LI 3: axial n=2 (360 Hz) ...', or that wheelsets were left out."""
    lines = []
    for w in WHEELS:
        modes = c.get("wheel_modes", {}).get(w, [])
        if modes:
            lines.append(f"{WHEEL_SHORT[w]} {len(modes)}: {modes[0]}")
    if c.get("left_out"):
        lines.append("left out: " + ", ".join(WHEEL_SHORT[w] for w in WHEELS if w in c["left_out"]))
    return "\n".join(lines) if lines else ("no wheel squeals" if c.get("wheelsets") else "")


def wheel_class(c):
    """0 no wheel squeals, 1..4 one wheel (WHEELS order), 5 several wheels; +6 when a wheelset was left out."""
    squealing = [i for i, w in enumerate(WHEELS) if c.get("wheel_modes", {}).get(w)]
    k = 0 if not squealing else (squealing[0] + 1 if len(squealing) == 1 else 5)
    return k + (6 if c.get("left_out") else 0)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--case", default=os.path.join(ROOT, "cases", "squeal_150m.toml"))
    p.add_argument("--binary", default=os.path.join(ROOT, "build", "rollnoise"))
    p.add_argument("--radii", default="100,150,200,300,500,1000", help="curve radii (m)")
    p.add_argument("--param", default="friction.decay", help="friction key to vary (e.g. friction.mu)")
    p.add_argument("--values", default="0.5,1,2,3,4", help="its values")
    p.add_argument("--work", default="squeal_map", help="folder of the runs' outputs")
    p.add_argument("-j", "--jobs", type=int, default=2, help="parallel runs")
    p.add_argument("-o", "--output", default="squeal_map.png")
    p.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                   help="passed on to every run (repeatable), e.g. grid.nx=12")
    p.add_argument("--fast", action="store_true", help="2 x 2 runs (the first two of each list)")
    p.add_argument("--wheelsets", action="store_true",
                   help="also each wheelset with both its contacts (noise.squeal_wheelsets = \"on\"): which wheels squeal")
    a = p.parse_args()
    if a.wheelsets:
        a.set = a.set + ['noise.squeal_wheelsets="on"']
    radii, values = floats(a.radii), floats(a.values)
    if a.fast:
        radii, values = radii[:2], values[:2]
    if not radii or not values:
        rh.fail("--radii and --values need at least one value each")
    if not os.path.isfile(a.case):
        rh.fail(f"{a.case}: no such case file")
    if not os.access(a.binary, os.X_OK):
        rh.fail(f"{a.binary}: not an executable (give --binary)")
    os.makedirs(a.work, exist_ok=True)
    jobs = [(r, v, i) for r in radii for i, v in enumerate(values)]
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, a.jobs)) as ex:
        cells = list(ex.map(lambda t: run_one(a.binary, a.case, a.work, t[0], a.param, t[1], t[2], a.set), jobs))
    with open(os.path.join(a.work, "summary.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["radius_m", a.param, "class", "max_growth_rate_1_per_s", "frequency_Hz", "unstable_modes"] +
                   [f"{wh}_unstable_modes" for wh in WHEELS] + ["wheelsets_run", "wheelsets_left_out", "message"])
        for c in cells:
            w.writerow([c["radius"], c["value"], CLASS_NAMES[c["class"]], c["growth"], c["frequency"],
                        "; ".join(c["modes"])] + ["; ".join(c.get("wheel_modes", {}).get(wh, [])) for wh in WHEELS] +
                       [int(c.get("wheelsets", False)), c.get("left_out", ""), c["message"]])

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import ListedColormap

    from matplotlib.patches import Patch

    nr, nv = len(radii), len(values)
    cls = np.array([c["class"] for c in cells]).reshape(nr, nv)
    growth = np.array([c["growth"] for c in cells]).reshape(nr, nv)
    with_wheels = any(c.get("wheelsets") for c in cells)
    # which contact the top-level /squeal is: the file's `loop` attribute of /squeal/wheels says so
    loop = next((c["loop"] for c in cells if c.get("loop")), "")
    m = re.search(r"top-level /squeal is (the [^;.]*)", loop)
    top = m.group(1) if m else "the case's single contact"
    plt.rcParams.update({"font.size": 10, "axes.titlesize": 11, "axes.labelsize": 10})
    cell_font = 9  # >= 9 pt at the saved dpi
    fig, axes = plt.subplots(1, 3 if with_wheels else 2, figsize=(19 if with_wheels else 12.5, 7))
    ax1, ax2 = axes[0], axes[1]
    class_colours = ["#c6dbef", "#fc9272", "#fdd0a2", "#d9d9d9"]  # light: black text stays readable
    ax1.imshow(cls.T, origin="lower", cmap=ListedColormap(class_colours), vmin=-0.5, vmax=3.5, aspect="auto")
    for i in range(nr):
        for j in range(nv):
            c = cells[i * nv + j]
            txt = CLASS_NAMES[c["class"]] if c["class"] != SQUEAL else "\n".join(c["modes"][:3])
            ax1.text(i, j, txt, ha="center", va="center", fontsize=cell_font)
    ax1.set_title(f"squeal occurrence\n{top}\n(text: unstable wheel modes, frequency)")
    ax1.legend([Patch(facecolor=c, edgecolor="0.3") for c in class_colours], CLASS_NAMES, loc="upper center",
               bbox_to_anchor=(0.5, -0.14), ncol=2, fontsize=9, title="cell colour", title_fontsize=9)
    g_max = np.nanmax(np.abs(growth)) if np.isfinite(growth).any() else 1.0
    im = ax2.imshow(growth.T, origin="lower", cmap="coolwarm", aspect="auto", vmin=-g_max, vmax=g_max)
    fig.colorbar(im, ax=ax2, label="largest Re s [1/s] (> 0: growing, squeal)")
    for i in range(nr):
        for j in range(nv):
            if np.isfinite(growth[i, j]):
                strong = abs(growth[i, j]) > 0.6 * g_max  # white on the saturated colours
                ax2.text(i, j, f"{growth[i, j]:.3g} 1/s\n{cells[i * nv + j]['frequency']:.0f} Hz", ha="center",
                         va="center", fontsize=cell_font, color="w" if strong else "k")
    ax2.set_title(f"largest growth rate of the coupled roots\n{top}\n(text: Re s and the root's frequency)")
    if with_wheels:  # which wheels squeal (the wheelsets with both contacts)
        ax3 = axes[2]
        wcls = np.array([wheel_class(c) for c in cells]).reshape(nr, nv)
        wheel_colours = ["#c6dbef", "#fc9272", "#a1d99b", "#bcbddc", "#fdd0a2", "#fa9fb5"]
        wheel_names = ["no wheel squeals", "LO only", "LI only", "TO only", "TI only", "several wheels"]
        ax3.imshow(wcls.T % 6, origin="lower", cmap=ListedColormap(wheel_colours), vmin=-0.5, vmax=5.5,
                   aspect="auto")
        for i in range(nr):
            for j in range(nv):
                if wcls[i, j] >= 6:  # a wheelset left out: hatched
                    ax3.add_patch(plt.Rectangle((i - 0.5, j - 0.5), 1, 1, fill=False, hatch="//", edgecolor="0.4",
                                                lw=0))
                ax3.text(i, j, wheel_cell_text(cells[i * nv + j]), ha="center", va="center", fontsize=cell_font,
                         bbox=dict(facecolor="w", alpha=0.6, lw=0) if wcls[i, j] >= 6 else None)
        ax3.set_title("which wheels squeal\neach wheelset's two contacts coupled (LO, LI, TO, TI: leading/"
                      "trailing outer/inner)\n(text: wheel, its unstable roots, the first root)")
        handles = [Patch(facecolor=c, edgecolor="0.3") for c in wheel_colours]
        handles.append(Patch(facecolor="w", edgecolor="0.4", hatch="//"))
        names = wheel_names + ["hatched: a wheelset left out (contact alone unstable)"]
        ax3.legend(handles, names, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=3, fontsize=9,
                   title="cell colour", title_fontsize=9)
    for ax in axes:
        ax.set_xticks(range(nr), [f"{r:g}" for r in radii])
        ax.set_yticks(range(nv), [f"{v:g}" for v in values])
        ax.set_xlabel("curve radius [m]")
        ax.set_ylabel(f"{a.param} [{PARAM_UNITS.get(a.param, 'as in the case')}]")
    fig.suptitle(f"rollnoise squeal {os.path.basename(a.case)}: radius x {a.param}", fontsize=12)
    fig.tight_layout()
    fig.savefig(a.output, dpi=110)
    print(f"{len(cells)} runs: {sum(c['class'] == SQUEAL for c in cells)} squeal, "
          f"{sum(c['class'] == CONTACT_UNSTABLE for c in cells)} contact unstable, "
          f"{sum(c['class'] == FAILED for c in cells)} failed; {a.output}, {os.path.join(a.work, 'summary.csv')}")


if __name__ == "__main__":
    rh.run(main)
