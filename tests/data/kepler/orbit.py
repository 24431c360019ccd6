"""The Kepler orbit: Binet's equation, its solution, and the period from the areal rate."""

import sympy as sp

from quasicentral.engine.registry import derived, derives
from quasicentral.engine.texts import symbols_of

S = symbols_of(__file__)
theta, G, M, h, e, p, a, T, u, r = S("theta G M h e p a T u r")


@derives("kepler:1", mode="substitute")
def binet():
    """u'' + u = GM/h²: checked on the conic u = (GM/h²)(1 + e cos θ), the general solution
    with the periapsis at θ = 0."""
    return {u: G * M / h**2 * (1 + e * sp.cos(theta))}


@derives("kepler:2", uses=("kepler:1",), unknowns=(r,))
def orbit():
    """r = 1/u = p/(1 + e cos θ) with p = h²/(GM)."""
    return sp.Eq(r, sp.simplify(1 / derived("kepler:1")[u]).subs(h**2, p * G * M))


@derives("kepler:3", unknowns=(T**2,))
def third_law():
    """T = πab/(h/2) with b = a√(1 − e²) and h² = GMa(1 − e²): T² = 4π²a³/(GM)."""
    b = a * sp.sqrt(1 - e**2)
    period = 2 * sp.pi * a * b / sp.sqrt(G * M * a * (1 - e**2))
    return sp.Eq(T**2, sp.simplify(period**2))
