#!/usr/bin/python3
"""The contact patch: normal pressure, tangential tractions (arrows, with a scale key), adhesion
and slip (paper Figs. 4, 8, 13).

  /usr/bin/python3 postprocess/plot_patch.py OUT.h5 [--snapshot K] [-o patch.png]

Reads the steady state (/steady) of `rollnoise steady`, `creep`, `response`, `validate`, `noise`
and `receptance` outputs, and the traction snapshots of a `rollnoise transient` output
(/transient/snapshots/K, written at the times of `transient.snapshots`): --snapshot K picks one
(default 0; --list prints them). A `steady --sweep` output keeps forces, not tractions, per point:
plot it with plot_sweep.py.
"""
import argparse
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rollnoise_h5 as rh  # noqa: E402


def nice_value(v):
    """A round number (1, 2 or 5 times a power of ten) not above v."""
    e = 10.0 ** math.floor(math.log10(v))
    return max(m for m in (1, 2, 5, 10) if m * e <= v * (1 + 1e-12)) * e


def snapshot_names(f):
    g = f["/transient/snapshots"]
    return sorted(g.keys(), key=lambda k: int(k) if k.isdigit() else k)


def read_state(f, path, args):
    """(group of px, py, state, creepage, force; description) of the chosen state."""
    if "/steady/px" in f:
        return "/steady", "steady state"
    if "/transient/snapshots" in f:
        names = snapshot_names(f)
        if args.list:
            for i, n in enumerate(names):
                print(f"{i}: t = {rh.values(f, f'/transient/snapshots/{n}/time') * 1e3:.4g} ms")
            raise SystemExit(0)
        k = args.snapshot
        if not names or not (-len(names) <= k < len(names)):
            rh.fail(f"--snapshot {k}: {path} has {len(names)} snapshots (0 ... {len(names) - 1})")
        g = f"/transient/snapshots/{names[k]}"
        return g, f"snapshot {k}, t = {rh.values(f, g + '/time') * 1e3:.4g} ms"
    if "/transient" in f:
        rh.fail(f"{path}: a transient run without snapshots: set transient.snapshots = [t1, ...] (s) to "
                "store tractions (plot_transient.py draws the force histories)")
    if "/sweep" in f:
        rh.fail(f"{path}: a sweep keeps forces, not tractions, per point: plot_sweep.py draws them; "
                "for one point's patch run `rollnoise steady CASE --set KEY=VALUE`")
    rh.fail(f"{path}: no /steady/px or /transient/snapshots: not a rollnoise output with tractions")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("file")
    ap.add_argument("--snapshot", type=int, default=0, help="transient output: index of the snapshot (default 0)")
    ap.add_argument("--list", action="store_true", help="transient output: list the snapshots and stop")
    ap.add_argument("-o", "--output", default=None)
    args = ap.parse_args()
    with rh.open_output(args.file, "/grid/x", "/grid/y", "/normal/pn", command="rollnoise steady") as f:
        group, what = read_state(f, args.file, args)
        out = args.output or args.file.rsplit(".", 1)[0] + (
            "_patch.png" if group == "/steady" else f"_patch_{group.rsplit('/', 1)[1]}.png")
        x = rh.values(f, "/grid/x") * 1e3
        y = rh.values(f, "/grid/y") * 1e3
        pn = rh.values(f, "/normal/pn") * 1e-6
        px = rh.values(f, group + "/px") * 1e-6
        py = rh.values(f, group + "/py") * 1e-6
        state = rh.values(f, group + "/state")
        creep = rh.values(f, group + "/creepage")
        force = rh.values(f, group + "/force")
        force_units = rh.component_units(f, group + "/force", 3)
    X, Y = np.meshgrid(x, y)
    fig, ax = plt.subplots(figsize=(8, 7))
    mesh = ax.pcolormesh(X, Y, np.ma.masked_where(pn <= 0, pn), shading="nearest", cmap="Greys", alpha=0.6)
    fig.colorbar(mesh, ax=ax, label="normal pressure [MPa]")
    pmax = float(np.hypot(px, py).max())
    dx = float(x[1] - x[0]) if len(x) > 1 else 1.0
    scale = pmax / (0.9 * dx) if pmax > 0 else 1.0  # the longest arrow spans 0.9 elements
    arrows = None
    for s, colour, label in [(1, "tab:blue", "adhesion"), (2, "tab:red", "slip")]:
        m = state == s
        q = ax.quiver(X[m], Y[m], px[m], py[m], color=colour, angles="xy", scale_units="xy",
                      scale=scale, width=0.003, label=label)
        arrows = arrows or (q if m.any() else None)
        if s == 2:
            ax.plot(X[m], Y[m], ".", color=colour, ms=2)
    if arrows is not None and pmax > 0:
        ref = nice_value(pmax)
        ax.quiverkey(arrows, 0.12, 1.02, ref, f"tangential traction {ref:g} MPa", labelpos="E",
                     coordinates="axes", color="k", fontproperties={"size": 8})
    ax.set_aspect("equal")
    ax.set_xlabel("x (rolling) [mm]")
    ax.set_ylabel("y [mm]")
    ax.set_title(f"{what}: creepage ({creep[0]:.4g}, {creep[1]:.4g}, {creep[2]:.4g} rad/m)\n"
                 f"Fx = {force[0]:.5g} {force_units[0]}, Fy = {force[1]:.5g} {force_units[1]}, "
                 f"Mz = {force[2]:.4g} {force_units[2]}; {int((state == 1).sum())} adhesion, "
                 f"{int((state == 2).sum())} slip elements", fontsize=8, pad=22)
    ax.legend(fontsize=8, loc="upper right")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print("wrote", out)


if __name__ == "__main__":
    rh.run(main)
