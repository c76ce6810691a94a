#!/usr/bin/python3
"""Reflection of a plane P wave at a Lysmer-Kuhlemeyer (viscous) boundary.

An elastic half-space y > 0 (plane strain, Poisson's ratio nu) ends at the
boundary y = 0, where dashpots exert the traction -rho c_p v_n n - rho c_s v_t
(outward normal n = (0, -1)). A plane P wave arrives at the angle theta from
the normal; the boundary sends back a P wave at theta and an S wave at phi,
sin(phi) / c_s = sin(theta) / c_p. With the incident velocity amplitude 1,
the reflected amplitudes A_p and A_s solve the two components of the
boundary's traction balance (all terms share the phase f'(t - x sin(theta) /
c_p), so for dashpots the ratios do not depend on the pulse's shape).

Printed per angle: A_p, A_s, the reflected fraction of the energy flux
through the boundary, R = A_p^2 + A_s^2 c_s cos(phi) / (c_p cos(theta)), and
the ratio G10's oblique runs measure, the reflected energy per unit length
along the boundary over the incident's, Q = A_p^2 + A_s^2 c_s cos(theta) /
(c_p cos(phi)) (a band of a plane pulse holds its energy per unit area of
front over the cosine of the front's angle to the boundary per unit
length along it).

Usage: doc/scripts/lysmer_reflection.py [nu] [angles in degrees ...]
(default: nu = 0.3, the angles 0 15 30 45 60 75).
"""
import sys

import numpy as np


def reflection(nu, theta_degrees):
    """A_p, A_s, R and Q at the angle theta (degrees) for Poisson's ratio nu."""
    # Units: rho = 1, mu = 1.
    mu = 1.0
    lam = 2.0 * mu * nu / (1.0 - 2.0 * nu)
    c_p = np.sqrt(lam + 2.0 * mu)
    c_s = np.sqrt(mu)
    theta = np.radians(theta_degrees)
    phi = np.arcsin(np.sin(theta) * c_s / c_p)
    normal = np.array([0.0, -1.0])

    def traction_mismatch(direction, polarisation, speed):
        """The wave's sigma n minus the dashpots' traction, per amplitude."""
        # u = a e f(t - d.x / c): grad u = -a e (x) d f' / c, v = a e f'.
        grad = -np.outer(polarisation, direction) / speed
        strain = 0.5 * (grad + grad.T)
        stress = lam * np.trace(strain) * np.eye(2) + 2.0 * mu * strain
        velocity = polarisation
        v_n = velocity @ normal
        dashpot = -c_p * v_n * normal - c_s * (velocity - v_n * normal)
        return stress @ normal - dashpot

    incident = np.array([np.sin(theta), -np.cos(theta)])
    reflected_p = np.array([np.sin(theta), np.cos(theta)])
    reflected_s = np.array([np.sin(phi), np.cos(phi)])
    s_polarisation = np.array([np.cos(phi), -np.sin(phi)])
    matrix = np.column_stack(
        [
            traction_mismatch(reflected_p, reflected_p, c_p),
            traction_mismatch(reflected_s, s_polarisation, c_s),
        ]
    )
    a_p, a_s = np.linalg.solve(matrix, -traction_mismatch(incident, incident, c_p))
    flux = a_p**2 + a_s**2 * c_s * np.cos(phi) / (c_p * np.cos(theta))
    per_length = a_p**2 + a_s**2 * c_s * np.cos(theta) / (c_p * np.cos(phi))
    return a_p, a_s, flux, per_length


def main():
    nu = float(sys.argv[1]) if len(sys.argv) > 1 else 0.3
    angles = [float(a) for a in sys.argv[2:]] or [0, 15, 30, 45, 60, 75]
    print("# Lysmer-Kuhlemeyer boundary, plane P wave, nu = %g" % nu)
    print("# theta(deg)  A_p  A_s  R(energy flux)  Q(energy per length)")
    for theta in angles:
        a_p, a_s, flux, per_length = reflection(nu, theta)
        print("%5.1f %+.5f %+.5f %.4e %.4e" % (theta, a_p, a_s, flux, per_length))


if __name__ == "__main__":
    main()
