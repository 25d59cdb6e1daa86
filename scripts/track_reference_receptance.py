#!/usr/bin/python3
"""An independent reference for the rail's vertical point receptance on a ballasted track.

Usage: scripts/track_reference_receptance.py [TRACK.toml] [--h5 OUT.h5 ...] [--position X]

A Timoshenko beam (numpy only, written from the equations, none of rollnoise's code) on the
two-layer support of the track file: rail pad k_p(1 + i eta_p), sleeper mass m_s, ballast
k_b(1 + i eta_b) per rail seat (Grassie, Gregory, Harrison & Johnson, J. Mech. Eng. Sci. 24, 1982;
Thompson, Railway Noise and Vibration, 2009, Ch. 3). Printed in dB re 1 m/N, 50 Hz - 2 kHz:

- continuous: the seats smeared, s = K(omega)/L; the point receptance of the infinite beam by the
  residues of the four roots of the dispersion quartic, found by numpy.roots;
- discrete: receptance superposition on the free beam (Heckl 1995; Wu & Thompson 1999) over
  2 x 200 + 1 seats solved densely, the load at --position from a seat (default mid-span).

--lateral: the lateral receptance at the running surface's centre with the rail's torsion (the
beam has none): the lateral Timoshenko beam on the smeared lateral seats plus e^2 times the point
receptance of a St-Venant-Vlasov torsion beam, GJ k^2 + E I_w k^4 + k_theta - rho I_p omega^2 = 0
(Timoshenko & Goodier 1970; Vlasov), on the rotational stiffness of the seats, k_theta = (K_z b^2/12
+ K_y d^2) / L (the vertical pad across the foot's width b, the lateral pad at the foot's bottom d
below the shear centre); e the height of the running surface above the shear centre. The section
constants are those of the waveguide's UIC60 mesh (docs/models.md Sec. 2.6: J = 2.03e-6 m^4,
I_w = 1.61e-8 m^6, shear centre 36.3 mm below the centroid, 81.2 mm above the foot). Lateral and
torsional motions are taken uncoupled (the coupling through the lateral pad's offset is left out).

With --h5, each file's /receptance/rail (the z-z entry of `rollnoise receptance`) is printed beside
it on the same frequencies (interpolated in log f). docs/models.md, "Beam and waveguide: where they
differ and why", uses it as the third model.
"""
import argparse
import os
import sys
import tomllib

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))


def seat_stiffness(sup, w):
    kp = sup["pad_stiffness"] * (1 + 1j * sup["pad_loss_factor"])
    kb = sup["ballast_stiffness"] * (1 + 1j * sup["ballast_loss_factor"])
    below = kb - sup["sleeper_mass"] * w * w
    return kp * below / (kp + below)


def timoshenko_roots(rail, vert, w, s):
    """The four roots k of det [[kGA k^2 + s - m w^2, -i k kGA], [i k kGA, EI k^2 + kGA - rI w^2]]."""
    d = 1 + 1j * rail["loss_factor"]
    EI = rail["youngs_modulus"] * vert["second_moment"] * d
    kGA = vert["shear_coefficient"] * rail["shear_modulus"] * rail["area"] * d
    m = rail["mass_per_length"]
    rI = m * vert["second_moment"] / rail["area"]
    q = s - m * w * w
    coeffs = [EI * kGA, 0, q * EI - kGA * rI * w * w, 0, q * (kGA - rI * w * w)]
    return np.roots(coeffs), EI, kGA, rI, m, q


def green(rail, vert, w, s, x):
    """w(x) per F at 0 and w(x) per M at 0 of the infinite beam on foundation s (N/m^2)."""
    k, EI, kGA, rI, m, q = timoshenko_roots(rail, vert, w, s)
    a = EI * kGA
    lower = k[np.argsort(k.imag)][:2]  # the two roots with Im k < 0 (damped: never on the axis)
    x = np.atleast_1d(np.asarray(x, dtype=float))
    gF = np.zeros(x.shape, complex)
    gM = np.zeros(x.shape, complex)
    for kj in lower:
        dP = 4 * a * kj**3 + 2 * (q * EI - kGA * rI * w * w) * kj  # P'(k)
        e = np.exp(-1j * kj * np.abs(x))
        gF += -1j * (EI * kj**2 + kGA - rI * w * w) * e / dP
        gM += -1j * (1j * kj * kGA) * e / dP * np.sign(x)
    return gF, gM


def continuous(track, f):
    rail, vert, sup = track["rail"], track["rail"]["vertical"], track["support"]["vertical"]
    w = 2 * np.pi * f
    s = seat_stiffness(sup, w) / track["sleeper_spacing"]
    return green(rail, vert, w, s, 0.0)[0][0]


def discrete(track, f, position, n_each=200):
    rail, vert, sup = track["rail"], track["rail"]["vertical"], track["support"]["vertical"]
    w = 2 * np.pi * f
    L = track["sleeper_spacing"]
    xn = L * np.arange(-n_each, n_each + 1)
    K = seat_stiffness(sup, w)
    A = green(rail, vert, w, 0.0, (xn[:, None] - xn[None, :]).ravel())[0].reshape(len(xn), -1)
    b = green(rail, vert, w, 0.0, xn - position)[0]
    # supports' forces R_n = -K w(x_n): (A + I/K) R = -b
    R = np.linalg.solve(A + np.eye(len(xn)) / K, -b)
    return green(rail, vert, w, 0.0, 0.0)[0][0] + b @ R


UIC60_MESH = {"J": 2.03e-6, "Iw": 1.61e-8, "shear_centre_z": 0.0812 - 0.0363, "height": 0.172,
              "foot_width": 0.150, "Iyy": 3.002e-5, "Izz": 5.126e-6, "A": 7.46e-3}


def torsion_point(track, f, sec=UIC60_MESH):
    """theta / T at the load of the torsion beam on the seats' rotational stiffness (rad/(N m))."""
    rail = track["rail"]
    w = 2 * np.pi * f
    d = 1 + 1j * rail["loss_factor"]
    GJ = rail["shear_modulus"] * sec["J"] * d
    EIw = rail["youngs_modulus"] * sec["Iw"] * d
    rho = rail["mass_per_length"] / rail["area"]
    Ip = sec["Iyy"] + sec["Izz"] + sec["A"] * (0.0812 - sec["shear_centre_z"]) ** 2
    sv, sl = track["support"]["vertical"], track["support"]["lateral"]
    k_theta = (seat_stiffness(sv, w) * sec["foot_width"] ** 2 / 12
               + seat_stiffness(sl, w) * sec["shear_centre_z"] ** 2) / track["sleeper_spacing"]
    q = k_theta - rho * Ip * w * w
    k = np.roots([EIw, 0, GJ, 0, q])
    lower = k[np.argsort(k.imag)][:2]
    return sum(-1j / (4 * EIw * kj**3 + 2 * GJ * kj) for kj in lower)


def lateral_with_torsion(track, f, sec=UIC60_MESH):
    rail, lat, sup = track["rail"], track["rail"]["lateral"], track["support"]["lateral"]
    w = 2 * np.pi * f
    beam = green(rail, lat, w, seat_stiffness(sup, w) / track["sleeper_spacing"], 0.0)[0][0]
    e = sec["height"] - sec["shear_centre_z"]
    return beam, beam + e * e * torsion_point(track, f, sec)


def h5_zz(path):
    import h5py

    with h5py.File(path, "r") as h:
        return h["receptance/frequency"][()], h["receptance/rail"][()][:, 0, 0]


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("track", nargs="?", default=os.path.join(HERE, "..", "models", "track",
                                                           "uic60_ballasted.toml"))
    p.add_argument("--h5", nargs="*", default=[])
    p.add_argument("--position", type=float, default=None, help="m from a seat (default L/2)")
    p.add_argument("--lateral", action="store_true",
                   help="the lateral receptance at the head with torsion (continuous support)")
    a = p.parse_args()
    with open(a.track, "rb") as fh:
        track = tomllib.load(fh)
    x = track["sleeper_spacing"] / 2 if a.position is None else a.position
    if a.lateral:
        print(f"{'f (Hz)':>7} {'lateral beam':>13} {'+ torsion':>10}")
        for f in [100, 125, 160, 200, 250, 315, 400, 500, 630, 800, 1000]:
            b, bt = lateral_with_torsion(track, f)
            print(f"{f:7.0f} {20 * np.log10(abs(b)):13.2f} {20 * np.log10(abs(bt)):10.2f}")
        return 0
    freqs = [50, 100, 160, 200, 250, 300, 315, 350, 400, 450, 500, 630, 800, 1000, 1250, 1600, 2000]
    files = [h5_zz(h) for h in a.h5]
    head = f"{'f (Hz)':>7} {'continuous':>11} {'discrete':>9}" + "".join(
        f" {os.path.basename(h)[:18]:>18}" for h in a.h5)
    print(head)
    for f in freqs:
        row = f"{f:7.0f} {20 * np.log10(abs(continuous(track, f))):11.2f} " \
              f"{20 * np.log10(abs(discrete(track, f, x))):9.2f}"
        for fr, r in files:
            if fr[0] <= f <= fr[-1]:
                v = np.interp(np.log(f), np.log(fr), 20 * np.log10(np.abs(r)))
                row += f" {v:18.2f}"
            else:
                row += f" {'':>18}"
        print(row)
    return 0


if __name__ == "__main__":
    sys.exit(main())
