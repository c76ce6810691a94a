#!/usr/bin/python3
"""G10 (BENCHMARKS.md) at oblique incidence: what the absorbing base reflects.

prm/G10-absorbing-oblique.prm drives a plane P pulse (half-sine velocity V
for t_p) through the top and both sides of an elastic block onto its
absorbing base at the angle theta from the base's normal. For each angle
the block is sized so that, at the End time T,
 - the pulse has passed the base up to x = x2 (T = (x2 sin theta + D cos
   theta) / c_p + t_p + 0.01 s);
 - in the window x1 < x < x2 (2 m wide) the reflected P and S waves come
   from the base itself, not from the shadow of its left end (x1 > D tan
   theta + 2 m), and have not reached the top (D cos theta > 2 m sin theta
   + c_p (t_p + 0.01 s) + 2 m cos theta);
 - the pulse has not reached the base's right end (so the right side, which
   moves with the incident wave, meets nothing else).
Two runs per angle: A (the block, base absorbing) and B (the same block
with the ground continued D / 2 + 2 m deeper, whose base sends nothing into
the window by T). The kinetic and strain energy of the points in the
window above y = 0 at T is, in A, the reflected waves plus the grid's
dispersion wake, in B the wake alone. Their difference over the incident
pulse's energy in the window, rho c_p V^2 t_p / (2 cos theta) per unit
length along the base, is compared with Lysmer-Kuhlemeyer theory's Q
(doc/scripts/lysmer_reflection.py).

Writes doc/data/G10-oblique.dat and doc/figures/G10-oblique.png.
Usage: doc/scripts/g10_oblique.py [path to mpm-otm] [angles in degrees]
(default: build-release/mpm-otm, the angles 30 45 60; 75 needs a block
121 m x 29 m, 0.9 billion point-steps per run).
"""
import glob
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

import lysmer_reflection

root = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
rho, young, nu = 2000.0, 1e7, 0.3
c_p, c_s = 82.0413, 43.8529
V, t_p, delay, margin, width, h = 0.01, 0.05, 0.01, 2.0, 2.0, 0.25


def geometry(theta_degrees):
    """Depth D, window x1..x2, width W, End time T and B's extra depth."""
    theta = math.radians(theta_degrees)
    s, c = math.sin(theta), math.cos(theta)
    depth = math.ceil((width * s + c_p * (t_p + delay)) / c + margin)
    x1 = math.ceil(depth * math.tan(theta) + margin)
    x2 = x1 + width
    block = math.ceil(x2 + c_p * (t_p + delay) / s + margin)
    end = (x2 * s + depth * c) / c_p + t_p + delay
    extra = math.ceil(depth / 2 + margin)
    return depth, x1, x2, block, end, extra


def velocity_expression(theta_degrees, depth):
    """The incident plane wave's velocity, two muparser expressions."""
    theta = math.radians(theta_degrees)
    phase = "(t - %.10g*x - %.10g*(%g - y))" % (
        math.sin(theta) / c_p,
        math.cos(theta) / c_p,
        depth,
    )
    pulse = "%s > 0 && %s < %g ? %%.10g * sin(pi * %s / %g) : 0" % (
        phase,
        phase,
        t_p,
        phase,
        t_p,
    )
    return "%s; %s" % (
        pulse % (V * math.sin(theta)),
        pulse % (-V * math.cos(theta)),
    )


def run(exe, work, name, theta_degrees, deeper):
    """Run A (deeper = 0) or B; return the particles of the last CSV."""
    depth, x1, x2, block, end, extra = geometry(theta_degrees)
    bottom = -extra if deeper else 0
    text = open(os.path.join(root, "prm", "G10-absorbing-oblique.prm")).read()
    text += """
subsection Time
  set End time = %.10g
end
subsection Mesh
  set Lower corner = 0, %g
  set Upper corner = %g, %g
  set Subdivisions = %d, %d
end
subsection Boundary wave
  set Velocity = %s
end
subsection Output
  set Directory = %s
  set Format    = none
  set Interval  = 100000
  set Overwrite = true
end
""" % (
        end,
        bottom,
        block,
        depth,
        round(block / h),
        round((depth - bottom) / h),
        velocity_expression(theta_degrees, depth),
        name,
    )
    prm = os.path.join(work, name + ".prm")
    open(prm, "w").write(text)
    with open(os.path.join(work, name + ".log"), "w") as log:
        subprocess.run([exe, prm], cwd=work, stdout=log, stderr=log, check=True)
    last = sorted(glob.glob(os.path.join(work, name, "particles-*.csv")))[-1]
    return np.genfromtxt(last, delimiter=",", names=True)


def window_energy(points, x1, x2):
    """Kinetic plus strain energy of the points in x1 < X < x2, Y > 0."""
    inside = (points["X"] > x1) & (points["X"] < x2) & (points["Y"] > 0)
    p = points[inside]
    kinetic = 0.5 * p["mass"] * (p["vx"] ** 2 + p["vy"] ** 2)
    trace = p["sxx"] + p["syy"] + p["szz"]
    squares = p["sxx"] ** 2 + p["syy"] ** 2 + p["szz"] ** 2 + 2 * p["sxy"] ** 2
    strain = 0.5 * p["volume"] * ((1 + nu) * squares - nu * trace**2) / young
    return np.sum(kinetic + strain)


def main():
    exe = os.path.abspath(
        sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build-release", "mpm-otm")
    )
    angles = [float(a) for a in sys.argv[2:]] or [30, 45, 60]
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for theta in angles:
            depth, x1, x2, block, end, extra = geometry(theta)
            incident = rho * c_p * V**2 * t_p / (2 * math.cos(math.radians(theta))) * width
            absorbing = window_energy(run(exe, work, "a%g" % theta, theta, False), x1, x2)
            deeper = window_energy(run(exe, work, "b%g" % theta, theta, True), x1, x2)
            _, _, flux, per_length = lysmer_reflection.reflection(nu, theta)
            rows.append(
                (theta, depth, block, x1, x2, end, incident, absorbing, deeper,
                 (absorbing - deeper) / incident, per_length, flux)
            )
            print("%g deg: window energy %.4e (A), %.4e (B), incident %.4e: "
                  "Q = %.4e, theory %.4e" % (theta, absorbing, deeper, incident,
                                              rows[-1][9], per_length), flush=True)
    with open(os.path.join(root, "doc", "data", "G10-oblique.dat"), "w") as out:
        out.write("# G10 at oblique incidence (doc/scripts/g10_oblique.py): linear MPM, "
                  "0.25 m cells, 2 x 2 points per cell, dt = 1e-3\n")
        out.write("# theta(deg) D(m) W(m) x1(m) x2(m) T(s) incident_in_window(J/m) "
                  "window_A(J/m) window_B(J/m) Q_measured Q_theory R_theory\n")
        for row in rows:
            out.write("%g %g %g %g %g %.4f %.5e %.5e %.5e %.4e %.4e %.4e\n" % row)
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    theory = np.linspace(0, 80, 161)
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.semilogy(theory, [lysmer_reflection.reflection(nu, a)[3] for a in theory],
                label="Lysmer-Kuhlemeyer theory, Q")
    ax.semilogy(theory, [lysmer_reflection.reflection(nu, a)[2] for a in theory], "--",
                label="theory, R (energy flux)")
    measured = [(r[0], r[9]) for r in rows]
    ax.semilogy([m[0] for m in measured if m[1] > 0], [m[1] for m in measured if m[1] > 0],
                "o", label="linear MPM, 0.25 m cells (A - B)")
    ax.set_xlabel("angle of incidence (deg)")
    ax.set_ylabel("reflected / incident energy")
    ax.set_ylim(1e-5, 1)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(root, "doc", "figures", "G10-oblique.png"), dpi=120)
    print("wrote doc/data/G10-oblique.dat and doc/figures/G10-oblique.png")


if __name__ == "__main__":
    main()
