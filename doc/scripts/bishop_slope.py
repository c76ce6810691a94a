#!/usr/bin/python3
"""Bishop's simplified method for the slope of G5 (BENCHMARKS.md).

The reference of doc/benchmarks.md, G5: a dry slope, crest y = 15 for
x <= 15, face from (15, 15) to (30, 5), toe y = 5 for x >= 30, rigid base
y = 0; unit weight gamma = 19 kN/m3, friction angle phi, cohesion c. For a
circular slip surface through an entry point A on the crest or face and an
exit point B on the face or toe, with centre above the chord, Bishop's
simplified method (moment equilibrium about the centre, interslice shear
neglected) gives

    F = sum_i [c b_i + W_i tan(phi)] / m_i  /  sum_i W_i sin(alpha_i),
    m_i = cos(alpha_i) + sin(alpha_i) tan(phi) / F,

solved by fixed-point iteration, over slices of width b_i with weight W_i
and base inclination alpha_i (positive where the base falls towards the
toe). The search takes A and B every 0.5 m and the radius from half the
chord in geometric steps, keeps circles above the base, drops circles with
m_i < 0.2 on a slice (the known breakdown of the method where the base
rises steeply at the exit), and returns the smallest F and its circle.

Usage:
  bishop_slope.py factor C PHI          smallest F for cohesion C (Pa)
  bishop_slope.py critical-cohesion PHI the cohesion with F = 1 (bisection)
  bishop_slope.py layered C1 PHI1 C2 PHI2 Y
                                        smallest F of a slope of two layers
                                        of the same unit weight: C1, PHI1
                                        above y = Y, C2, PHI2 below (each
                                        slice takes the strength of the
                                        layer its base lies in)
Each prints the value and the critical circle (centre x, y and radius).
"""

import sys

import numpy as np

GAMMA = 19e3


def surface(x):
    """Height of the ground surface at x."""
    return np.where(x <= 15., 15., np.where(x >= 30., 5., 15. - (x - 15.) / 1.5))


def circles(step=0.5):
    """The searched circles: entry x, exit x, centres (xc, yc) and radii."""
    entries, exits, centres, radii = [], [], [], []
    for xa in np.arange(0., 30.001, step):
        ya = float(surface(xa))
        for xb in np.arange(xa + 1., 45.001, step):
            yb = float(surface(xb))
            chord = np.hypot(xb - xa, yb - ya)
            mid = np.array([(xa + xb) / 2., (ya + yb) / 2.])
            # Unit normal of the chord, pointing up.
            normal = np.array([-(yb - ya), xb - xa]) / chord
            if normal[1] < 0:
                normal = -normal
            for factor in np.geomspace(0.5001, 20., 30):
                radius = factor * chord
                offset = np.sqrt(radius ** 2 - (chord / 2.) ** 2)
                centre = mid + offset * normal
                if centre[1] - radius < 0.:  # below the rigid base
                    continue
                entries.append(xa)
                exits.append(xb)
                centres.append(centre)
                radii.append(radius)
    return (np.array(entries), np.array(exits), np.array(centres),
            np.array(radii))


def factors(c, phi, search, slices=50, layers=None):
    """Bishop's F of each circle of @p search (inf where not admissible).
    With @p layers = (c2, phi2, y), slices whose base lies below y take
    c2 and phi2 instead."""
    entries, exits, centres, radii = search
    xc, yc, r = centres[:, 0:1], centres[:, 1:2], radii[:, None]
    width = ((exits - entries) / slices)[:, None]
    mid = entries[:, None] + (np.arange(slices)[None, :] + 0.5) * width
    root = np.sqrt(np.maximum(r ** 2 - (mid - xc) ** 2, 1e-12))
    base = yc - root
    tan_phi = np.tan(np.radians(phi))
    if layers is not None:
        below = base < layers[2]
        c = np.where(below, layers[0], c)
        tan_phi = np.where(below, np.tan(np.radians(layers[1])), tan_phi)
    weight = GAMMA * np.maximum(surface(mid) - base, 0.) * width
    alpha = np.arctan((xc - mid) / root)
    driving = np.sum(weight * np.sin(alpha), axis=1)
    F = np.ones(len(radii))
    valid = driving > 0.
    for _ in range(60):
        m = np.cos(alpha) + np.sin(alpha) * tan_phi / F[:, None]
        valid &= np.all(m >= 0.2, axis=1)
        m = np.maximum(m, 0.2)
        F = np.sum((c * width + weight * tan_phi) / m, axis=1) / \
            np.where(driving > 0., driving, 1.)
    return np.where(valid, F, np.inf)


def smallest(c, phi, search, layers=None):
    F = factors(c, phi, search, layers=layers)
    k = int(np.argmin(F))
    return F[k], search[2][k], search[3][k]


def main():
    search = circles()
    if sys.argv[1] == "factor":
        c, phi = float(sys.argv[2]), float(sys.argv[3])
        F, centre, radius = smallest(c, phi, search)
        print("F = %.4f; critical circle: centre %.3f %.3f, radius %.3f"
              % (F, centre[0], centre[1], radius))
    elif sys.argv[1] == "layered":
        c1, phi1, c2, phi2, y = (float(v) for v in sys.argv[2:7])
        F, centre, radius = smallest(c1, phi1, search, layers=(c2, phi2, y))
        print("F = %.4f; critical circle: centre %.3f %.3f, radius %.3f"
              % (F, centre[0], centre[1], radius))
    else:
        phi = float(sys.argv[2])
        low, high = 0., 10e3
        for _ in range(17):
            c = (low + high) / 2.
            F, centre, radius = smallest(c, phi, search)
            if F < 1.:
                low = c
            else:
                high = c
        print("critical cohesion %.1f Pa (F = %.4f); critical circle: centre "
              "%.3f %.3f, radius %.3f" % (c, F, centre[0], centre[1], radius))


if __name__ == "__main__":
    main()
