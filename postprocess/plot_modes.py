#!/usr/bin/python3
"""The wheel's FE modes of `rollnoise modes`: deformed sections and the point receptance at a
tread position.

  /usr/bin/python3 postprocess/plot_modes.py OUT.h5 [--s 0.0] [--modes 8] [--prefix PREFIX]

PREFIX_sections.png: the first --modes modes with n >= 2 (from /modes/mesh/shape), each the section
(r, z) undeformed (grey) and deformed by (U_r, U_z) scaled to 8 % of the section's height, titled
with family, n, nodal circles and frequency. PREFIX_receptance.png: the point receptance at tread
position s (m, /modes/tread/s) of the modes with n >= 2, cos set (z = -U_r, lateral y = U_z) and sin
set (longitudinal x = U_theta), unit modal masses and /modes/damping:
  H_jj(f) = sum_k phi_jk^2 / ((2 pi f_k)^2 - (2 pi f)^2 + 2 i zeta_k (2 pi f_k)(2 pi f))  [m/N]
(docs/models.md Sec. 3.4, the wheel at rest; the rigid wheelset, n = 0, 1, is not included).
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rollnoise_h5 as rh  # noqa: E402


def tread_shape_at(s_grid, shape, s):
    """(modes, 3) shapes at s, linear between the tread samples."""
    if s < s_grid[0] or s > s_grid[-1]:
        rh.fail(f"--s {s}: outside the tread ({s_grid[0]:.4f} .. {s_grid[-1]:.4f} m)")
    return np.array([[np.interp(s, s_grid, shape[k, :, c]) for c in range(3)] for k in range(shape.shape[0])])


def draw_sections(nodes, triangles, section, labels, out):
    count = len(labels)
    cols = min(4, max(count, 1))
    rows = (count + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(3.0 * cols, 3.6 * rows), squeeze=False)
    r, z = nodes[:, 0], nodes[:, 1]
    corners = triangles[:, :3]
    height = r.max() - r.min()
    for ax in axes.flat:
        ax.set_axis_off()
    for ax, u, label in zip(axes.flat, section, labels):
        scale = 0.08 * height / max(np.abs(u[:, [0, 2]]).max(), 1e-300)
        ax.triplot(z * 1e3, r * 1e3, corners, color="0.8", lw=0.3)
        ax.triplot((z + scale * u[:, 2]) * 1e3, (r + scale * u[:, 0]) * 1e3, corners, color="C0", lw=0.4)
        ax.set_aspect("equal")
        ax.set_title(label, fontsize=8)
    fig.suptitle("deformed sections (z [mm] across, r [mm] up)")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("file")
    ap.add_argument("--s", type=float, default=0.0, help="tread position of the receptance (m)")
    ap.add_argument("--modes", type=int, default=8, help="number of deformed sections drawn")
    ap.add_argument("--prefix", default=None, help="output prefix (default FILE without .h5)")
    args = ap.parse_args()
    prefix = args.prefix or args.file.rsplit(".", 1)[0]
    with rh.open_output(args.file, "/modes/frequency", "/modes/tread/shape", "/modes/mesh/shape",
                        command="rollnoise modes") as f:
        freq = rh.values(f, "/modes/frequency")
        n = rh.values(f, "/modes/n")
        circles = rh.values(f, "/modes/nodal_circles")
        family = [rh.text(v) for v in rh.values(f, "/modes/family")]
        zeta = rh.values(f, "/modes/damping")
        s_grid = rh.values(f, "/modes/tread/s")
        tread = rh.values(f, "/modes/tread/shape")
        nodes = rh.values(f, "/modes/mesh/nodes")
        triangles = rh.values(f, "/modes/mesh/triangles")
        keep = np.flatnonzero(n >= 2)
        shown = keep[np.argsort(freq[keep], kind="stable")][: max(args.modes, 0)]
        section = np.array([f["/modes/mesh/shape"][k] for k in shown])
    labels = [f"{family[k]} n={n[k]}, {circles[k]} circ., {freq[k]:.0f} Hz" for k in shown]
    draw_sections(nodes, triangles, section, labels, prefix + "_sections.png")

    u = tread_shape_at(s_grid, tread[keep], args.s)  # (modes, 3): U_r, U_theta, U_z
    fk, zk = freq[keep], zeta[keep]
    f_axis = np.geomspace(100.0, max(fk.max() * 1.1, 200.0), 2000)
    w, wk = 2 * np.pi * f_axis[:, None], 2 * np.pi * fk[None, :]
    R = 1.0 / (wk**2 - w**2 + 2j * zk[None, :] * wk * w)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for c, name in [(0, "vertical (-U_r)"), (2, "lateral (U_z)"), (1, "longitudinal (U_theta, sin set)")]:
        ax.loglog(f_axis, np.abs(R @ (u[:, c] ** 2)), label=name)
    ax.set_xlabel("f [Hz]")
    ax.set_ylabel("|H| [m/N]")
    ax.set_title(f"{args.file}: point receptance at s = {1e3 * args.s:.1f} mm, modes n >= 2", fontsize=9)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(prefix + "_receptance.png", dpi=110)
    print("wrote", prefix + "_sections.png", "and", prefix + "_receptance.png")


if __name__ == "__main__":
    rh.run(main)
