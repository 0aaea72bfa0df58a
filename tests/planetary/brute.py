"""Independent re-implementations for the tests: geometry and tooth phases, no gcd formula, no
vectorised search. Used to check the solver condition by condition."""
from __future__ import annotations

import math
from fractions import Fraction

# scheme → (row1, row2) mesh kinds, written out again here on purpose
KINDS = {"single-row": ("external", "internal"), "two-row-ext-int": ("external", "internal"),
         "two-row-ext-ext": ("external", "external"), "two-row-int-int": ("internal", "internal")}


def four(scheme, z):
    return (z[0], z[1], z[1], z[2]) if scheme == "single-row" else tuple(z)


def radii(scheme, z, m=1.0):
    """Pitch radii and the planet-axis distance from each row (must agree when coaxial)."""
    z1, z2, z2p, z3 = four(scheme, z)
    r1, r2, r2p, r3 = (m * v / 2 for v in (z1, z2, z2p, z3))
    k1, k2 = KINDS[scheme]
    a_row1 = r1 + r2 if k1 == "external" else r1 - r2
    a_row2 = r3 + r2p if k2 == "external" else r3 - r2p
    return a_row1, a_row2


def coaxial(scheme, z):
    a1, a2 = radii(scheme, z)
    return a1 == a2 and a1 > 0


def adjacency_geometric(scheme, z, k, ha=1.0):
    """Distance between neighbouring planet axes on a circle of radius a is larger than the tip
    diameter of the larger planet crown: |P0 − P1| > m·(z_p + 2ha)."""
    if k == 1:
        return True
    z1, z2, z2p, z3 = four(scheme, z)
    a = radii(scheme, z)[0]
    p0 = (a, 0.0)
    p1 = (a * math.cos(2 * math.pi / k), a * math.sin(2 * math.pi / k))
    dist = math.hypot(p1[0] - p0[0], p1[1] - p0[1])
    tip = max(z2, z2p) + 2 * ha
    if abs(dist - tip) < 1e-9:      # touching tips are rejected
        return False
    return dist > tip


def _mesh_ok(kind, zw, zp, theta, psi, c):
    """Phase of the mesh in turns: external  zw·θ + zp·(θ + ½ − ψ), internal  zw·θ − zp·(θ − ψ);
    it must equal its value c in the reference assembly modulo whole teeth."""
    if kind == "external":
        ph = zw * theta + zp * (theta + Fraction(1, 2) - psi)
    else:
        ph = zw * theta - zp * (theta - psi)
    return (ph - c).denominator == 1


def assembly_by_phases(scheme, z, k):
    """A second planet fits at θ = 1/K turn (central wheels fixed, planets identical): try every
    planet rotation ψ that meshes row 2 (ψ0 + j/z2′) and test row 1 directly."""
    z1, z2, z2p, z3 = four(scheme, z)
    k1, k2 = KINDS[scheme]
    c1 = Fraction(z2, 2) if k1 == "external" else Fraction(0)
    c2 = Fraction(z2p, 2) if k2 == "external" else Fraction(0)
    theta = Fraction(1, k)
    # one ψ0 that meshes row 2: solve the row-2 phase for ψ
    if k2 == "external":
        psi0 = (z3 * theta + z2p * (theta + Fraction(1, 2)) - c2) / z2p
    else:
        psi0 = (c2 - z3 * theta + z2p * theta) / z2p
    assert _mesh_ok(k2, z3, z2p, theta, psi0, c2)
    if scheme == "single-row":       # one crown: the same teeth mesh both wheels
        pass
    for j in range(z2p):
        psi = psi0 + Fraction(j, z2p)
        if _mesh_ok(k1, z1, z2, theta, psi, c1):
            return True
    return False


def willis(scheme, z):
    z1, z2, z2p, z3 = four(scheme, z)
    k1, k2 = KINDS[scheme]
    s = (-1 if k1 == "external" else 1) * (-1 if k2 == "external" else 1)
    return 1 - s * Fraction(z2 * z3, z1 * z2p)


def undercut_ok(scheme, z, ext=17, inn=85, dif=8):
    z1, z2, z2p, z3 = four(scheme, z)
    k1, k2 = KINDS[scheme]
    ok = z2 >= ext and z2p >= ext
    ok &= (z1 >= inn and z1 - z2 >= dif) if k1 == "internal" else z1 >= ext
    ok &= (z3 >= inn and z3 - z2p >= dif) if k2 == "internal" else z3 >= ext
    return ok


def envelope(scheme, z):
    z1, z2, z2p, z3 = four(scheme, z)
    a = radii(scheme, z)[0]
    return max(z1, z3, 2 * a + max(z2, z2p))


def all_coaxial_sets(scheme, bound, ext, inn, dif):
    """Every coaxial, undercut-free set with all z ≤ bound, by plain loops."""
    out = []
    two = scheme != "single-row"
    rng = range(1, bound + 1)
    for z1 in rng:
        for z2 in rng:
            for z2p in (rng if two else (z2,)):
                a2 = z1 + z2 if KINDS[scheme][0] == "external" else z1 - z2
                for z3 in {a2 - z2p, a2 + z2p}:      # try both, keep what coaxial() accepts
                    if not 1 <= z3 <= bound:
                        continue
                    z = (z1, z2, z2p, z3) if two else (z1, z2, z3)
                    if coaxial(scheme, z) and undercut_ok(scheme, z, ext, inn, dif):
                        out.append(z)
    return out
