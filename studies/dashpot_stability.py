#!/usr/bin/python3
"""Stability and restitution of the stepper's spring-dashpot on one degree of freedom.

Feeds docs/performance.md, section "Flume, geometry A, Model 3": the time step limits of
the spring-dashpot.

Usage: dashpot_stability.py

The DEM stepper (dem/stepper.cpp) is velocity Verlet whose contact force at x(n+1)
uses the half-step velocity v(n+1/2): a leapfrog with a damper lagged by half a step.
For x'' = -w^2 x - 2 zeta w x' that step is stable only below a limit of w dt that
falls with zeta; this prints the limit for several damping ratios (the largest
eigenvalue modulus of the step's 2x2 matrix), then the restitution coefficient of one
linear normal contact (dashpot may pull, as the scenario default) integrated with the
same step, against the exact exp(-pi zeta / sqrt(1 - zeta^2)).
Figures quoted in docs/performance.md (flume section, 2026-11-27).
"""
import math


def spectral_radius(wdt, zeta):
    # State (x_n, v_{n-1/2}); v_{n+1/2} = v_{n-1/2} + dt (-w^2 x_n - 2 zeta w v_{n-1/2}).
    a = 1.0 - wdt * wdt
    b = wdt * (1.0 - 2.0 * zeta * wdt)
    c = -wdt
    d = 1.0 - 2.0 * zeta * wdt
    # Matrix [[a, b], [c, d]] in units where w = 1 (x scaled by w).
    tr, det = a + d, a * d - b * c
    disc = tr * tr / 4.0 - det
    if disc >= 0.0:
        r = math.sqrt(disc)
        return max(abs(tr / 2.0 + r), abs(tr / 2.0 - r))
    return math.sqrt(det)


def stability_limit(zeta):
    wdt, step = 0.0, 1e-4
    while spectral_radius(wdt + step, zeta) <= 1.0 + 1e-12:
        wdt += step
    return wdt


def restitution(wdt, zeta):
    """Rebound speed over approach speed of one contact, w = 1, approach speed 1."""
    x, v, a = 0.0, -1.0, 0.0  # x < 0: overlap
    for n in range(1, 1_000_000):
        vh = v + 0.5 * wdt * a
        x += wdt * vh
        a = (-x - 2.0 * zeta * vh) if x < 0.0 else 0.0
        v = vh + 0.5 * wdt * a
        if n > 1 and x >= 0.0 and v > 0.0:
            return v
    return float("nan")


def main():
    print("zeta  stable for w dt below")
    for zeta in (0.0, 0.1, 0.3, 0.5, 0.7, 1.0):
        print(f"{zeta:4.1f}  {stability_limit(zeta):.3f}   "
              f"(2 (sqrt(1 + zeta^2) - zeta) = {2 * (math.sqrt(1 + zeta * zeta) - zeta):.3f})")
    zeta = 0.5
    exact = math.exp(-math.pi * zeta / math.sqrt(1 - zeta * zeta))
    print(f"\nrestitution of one contact, zeta = {zeta}: exact {exact:.3f}")
    for wdt in (0.1, 0.2, 0.4, 0.6, 0.8, 1.0, 1.1):
        print(f"  w dt = {wdt:.1f}: {restitution(wdt, zeta):.3f}")


if __name__ == "__main__":
    main()
