#!/usr/bin/python3
"""The contact patch of a steady solution: pressure, tangential tractions, adhesion and slip
(paper Figs. 4, 8, 13), from the output of `rollnoise steady` (or creep/response/validate).

  /usr/bin/python3 postprocess/plot_patch.py OUT.h5 [-o patch.png]
"""
import argparse

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("file")
    ap.add_argument("-o", "--output", default=None)
    args = ap.parse_args()
    out = args.output or args.file.rsplit(".", 1)[0] + "_patch.png"
    with h5py.File(args.file, "r") as f:
        x = f["/grid/x"][:] * 1e3
        y = f["/grid/y"][:] * 1e3
        pn = f["/normal/pn"][:] * 1e-6
        px = f["/steady/px"][:] * 1e-6
        py = f["/steady/py"][:] * 1e-6
        state = f["/steady/state"][:]
        creep = f["/steady/creepage"][:]
        force = f["/steady/force"][:]
    X, Y = np.meshgrid(x, y)
    fig, ax = plt.subplots(figsize=(8, 7))
    mesh = ax.pcolormesh(X, Y, np.ma.masked_where(pn <= 0, pn), shading="nearest", cmap="Greys", alpha=0.6)
    fig.colorbar(mesh, ax=ax, label="normal pressure [MPa]")
    for s, colour, label in [(1, "tab:blue", "adhesion"), (2, "tab:red", "slip")]:
        m = state == s
        ax.quiver(X[m], Y[m], px[m], py[m], color=colour, angles="xy", scale_units="xy",
                  scale=np.abs(np.hypot(px, py)).max() / (0.9 * (x[1] - x[0])), width=0.003, label=label)
        if s == 2:
            ax.plot(X[m], Y[m], ".", color=colour, ms=2)
    ax.set_aspect("equal")
    ax.set_xlabel("x (rolling) [mm]")
    ax.set_ylabel("y [mm]")
    ax.set_title(f"creepage ({creep[0]:g}, {creep[1]:g}, {creep[2]:g} rad/m); Fx = {force[0]:.0f} N, "
                 f"Fy = {force[1]:.0f} N, Mz = {force[2]:.2f} N m; {int((state == 1).sum())} adhesion, "
                 f"{int((state == 2).sum())} slip", fontsize=8)
    ax.legend(fontsize=8, loc="upper right")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print("wrote", out)


if __name__ == "__main__":
    main()
