"""The peaks of Planck's spectrum: where the derivative's numerator vanishes."""

import sympy as sp

from quasicentral.engine.registry import derives
from quasicentral.engine.texts import symbols_of

S = symbols_of(__file__)
x, k, t = S("x k t")


@derives("wien:1", mode="condition")
def peak_in_frequency():
    """d/dx x^3/(e^x - 1) = 0: its numerator 3x^2(e^x - 1) - x^3 e^x vanishes at the peak."""
    return sp.numer(sp.together(sp.diff(x**3 / (sp.exp(x) - 1), x)))


@derives("wien:2", mode="condition")
def peak_in_wavelength():
    """d/dx x^5/(e^x - 1) = 0 (the spectrum per wavelength): 5x^4(e^x - 1) - x^5 e^x = 0."""
    return sp.numer(sp.together(sp.diff(x**5 / (sp.exp(x) - 1), x)))


@derives("wien:3", "wien:4", mode="expression")
def peak_by_lambert():
    """(x - 5)e^x + 5 = 0 with x = 5 + w: w e^w = -5 e^{-5}, so w = W(-5 e^{-5})."""
    return 5 + sp.LambertW(-5 * sp.exp(-5))


@derives("wien:5", mode="substitute")
def planck_integral():
    """Γ(4)ζ(4) = 6·π⁴/90: the printed equation holds as it stands (nothing to substitute)."""
    return {}


@derives("wien:6", mode="substitute")
def no_drag():
    """(1 - e^{-kt})/k → t as k → 0: the printed limit holds as it stands."""
    return {}


@derives("wien:7", mode="substitute")
def logarithm():
    """d/dt ln(1 + kt)/k = 1/(1 + kt): 1/k is a time, kt a number."""
    return {}
