# SPDX-License-Identifier: MIT
"""Closed-form, slip-line and upper-bound references for drawing and extrusion
through wedge (conical) dies, as used by bench/validation.py (docs/validation.md
states the sources and the derivations). Stresses are in units of the shear
yield stress k (σ_0 = √3 k, von Mises); angles are die semi-angles in radians.
"""
import math

SQRT3 = math.sqrt(3.0)


def hill_special_reduction(alpha):
    """Reduction r = 2 sin α / (1 + 2 sin α) whose frictionless slip-line field
    is one centred fan (Hill 1950, ch. VII)."""
    return 2 * math.sin(alpha) / (1 + 2 * math.sin(alpha))


def hill_wedge_stress(alpha):
    """Plane strain, frictionless wedge die at the special reduction: the drawing
    stress (on the exit) and the extrusion pressure (on the entry) are both
    2k (1 + α) r."""
    return 2 * (1 + alpha) * hill_special_reduction(alpha)


def plane_ideal(r):
    """Homogeneous (ideal) work, plane strain: 2k ln(1/(1 − r)); a lower bound."""
    return 2 * math.log(1 / (1 - r))


def _incomplete_elliptic_e(phi, m, n=2000):
    """E(φ | m) = ∫₀^φ √(1 − m sin² θ) dθ by composite Simpson (n even)."""
    h = phi / n
    total = 0.0
    for i in range(n + 1):
        weight = 1 if i in (0, n) else (4 if i % 2 else 2)
        total += weight * math.sqrt(1 - m * math.sin(i * h) ** 2)
    return total * h / 3


def plane_radial_upper_bound(alpha, r, m=0.0):
    """Upper bound of the plane-strain drawing stress (or extrusion pressure) for
    the radial sink flow u_ρ = −C cos θ / ρ between two circular velocity
    discontinuities centred on the die apex (the plane-strain counterpart of
    Avitzur's conical-die field); m is a constant friction factor (τ = m k)."""
    strain = math.log(1 / (1 - r))
    internal = _incomplete_elliptic_e(alpha, 0.75) / math.sin(alpha) * strain
    return 2 * (internal + math.tan(alpha / 2) + 0.5 * m * strain / math.tan(alpha))


def plane_sachs(alpha, r, mu):
    """Slab (Sachs) drawing stress, plane strain, Coulomb μ: 2k (1+B)/B (1 − (1−r)^B), B = μ cot α."""
    if mu == 0:
        return plane_ideal(r)
    b = mu / math.tan(alpha)
    return 2 * (1 + b) / b * (1 - (1 - r) ** b)


def axisymmetric_ideal(r):
    """Homogeneous work, axisymmetric: σ_0 ln(1/(1 − r)), r the area reduction."""
    return SQRT3 * math.log(1 / (1 - r))


def avitzur_f(alpha):
    """Avitzur's f(α) of the spherical-flow field (→ 1 as α → 0)."""
    s2 = math.sin(alpha) ** 2
    c = math.sqrt(11.0 / 12.0)
    root = math.sqrt(1 - 11.0 / 12.0 * s2)
    return (1 - math.cos(alpha) * root
            + 1 / math.sqrt(11.0 * 12.0) * math.log((1 + c) / (c * math.cos(alpha) + root))) / s2


def avitzur_upper_bound(alpha, r, m=0.0, land_over_radius=0.0):
    """Avitzur's upper bound of the wire-drawing stress (and of the rod extrusion
    pressure) through a conical die without back tension:
    σ/σ_0 = 2 f(α) ln(R_0/R_f) + (2/√3)[α/sin²α − cot α + m (cot α ln(R_0/R_f) + L/R_f)]."""
    log_radius = 0.5 * math.log(1 / (1 - r))
    bracket = (alpha / math.sin(alpha) ** 2 - 1 / math.tan(alpha)
               + m * (log_radius / math.tan(alpha) + land_over_radius))
    return SQRT3 * (2 * avitzur_f(alpha) * log_radius + 2 / SQRT3 * bracket)


def axisymmetric_sachs(alpha, r, mu):
    """Sachs's wire-drawing stress, Coulomb μ: σ_0 (1+B)/B (1 − (1 − r)^B), B = μ cot α."""
    if mu == 0:
        return axisymmetric_ideal(r)
    b = mu / math.tan(alpha)
    return SQRT3 * (1 + b) / b * (1 - (1 - r) ** b)
