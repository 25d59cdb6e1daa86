#!/usr/bin/python3
"""Dispersion curves of the waveguide rail from `rollnoise receptance` with track.model = "waveguide".

  /usr/bin/python3 postprocess/plot_rail_waves.py OUT.h5 [-o fig.png]

/receptance/rail_waves/frequency [nk][branches] (Hz) against /receptance/rail_waves/wavenumber
[nk] (rad/m): the lowest natural frequencies of the supported, undamped rail section at each real
wavenumber (docs/models.md Sec. 2.6, Eq. W2; the support at its static stiffness). A branch's
frequency at k = 0 is its cut-on frequency (marked). Each line joins the j-th lowest frequency
at every k, so where two waves cross the lines veer instead (sorted, not tracked by wave type).
"""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import rollnoise_h5 as rh  # noqa: E402


def main():
    path, out = rh.file_and_output(__doc__, "_rail_waves.png")
    with rh.open_output(path, "/receptance/rail_waves/frequency",
                        command='rollnoise receptance (with track.model = "waveguide")') as f:
        k = rh.values(f, "/receptance/rail_waves/wavenumber")
        freq = rh.values(f, "/receptance/rail_waves/frequency")
    if freq.ndim != 2 or freq.shape[0] != k.shape[0]:
        rh.fail(f"{path}: /receptance/rail_waves/frequency is not [nk][branches] with nk = {k.shape[0]}")
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for j in range(freq.shape[1]):
        ax.plot(k, freq[:, j] / 1e3, "-", lw=1)
        ax.plot([k[0]], [freq[0, j] / 1e3], "k.", ms=4)
    ax.set_xlabel("wavenumber k [rad/m]")
    ax.set_ylabel("frequency [kHz]")
    ax.set_ylim(0, min(8.0, freq.max() / 1e3))
    ax.set_xlim(k[0], k[-1])
    ax.grid(alpha=0.3)
    ax.set_title(f"{path}: waveguide rail, {freq.shape[1]} lowest branches", fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print("wrote", out)


if __name__ == "__main__":
    rh.run(main)
