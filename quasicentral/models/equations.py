"""The equations of motion, each written once, in any arithmetic: ``lib`` is :mod:`math`,
:mod:`mpmath` or heyoka (symbolic, compiled once); the same function serves scipy's DOP853,
mpmath's Taylor integrator and heyoka's.

Systems (state: horizontal position and velocity; with ``extras`` also the arc length s and
the energy per mass D dissipated by the drag):

* ``LINEAR`` — small swings, linear drag, [Brepta1953] (16)–(17): ẍ = −Ω²x − 2κẋ, ÿ = −Ω²y − 2κẏ;
  parameters (Ω², 2κ);
* ``QUADRATIC`` — small swings, quadratic drag (26)–(27): ẍ = −Ω²x − βẋv, ÿ = −Ω²y − βẏv,
  v = √(ẋ² + ẏ²); parameters (Ω², β);
* ``QUADRATIC_PLANAR`` — (26) along a line, ẍ = −Ω²x − σβẋ², σ = sign ẋ fixed on a stretch
  between turning points (analytic there); parameters (Ω², β, σ), σ None: taken from ẋ;
* ``SPHERICAL_LINEAR`` / ``SPHERICAL_QUADRATIC`` — the full pendulum (6)–(7) in horizontal
  coordinates: Ẍ = −γẊ − X(v² + gZ)/l², Ÿ = −γẎ − Y(v² + gZ)/l², Z = √(l² − X² − Y²),
  γ = 2κ or βv; parameters (l, g, 2κ or β);
* ``SPHERICAL_QUADRATIC_PLANAR`` — the full planar swing with σ as above; parameters (l, g, β, σ).

>>> f = rhs(System.LINEAR, (10.0, 0.8), math)
>>> f(0.0, [0.1, 0.0, 0.0, 0.1])
[0.0, 0.1, -1.0, -0.08000000000000002]
"""

from __future__ import annotations

import math
from enum import Enum


class System(str, Enum):
    """A system of first-order equations (the value names it in caches and messages)."""

    LINEAR = "linear"
    QUADRATIC = "quadratic"
    QUADRATIC_PLANAR = "quadratic-planar"
    SPHERICAL_LINEAR = "spherical-linear"
    SPHERICAL_QUADRATIC = "spherical-quadratic"
    SPHERICAL_QUADRATIC_PLANAR = "spherical-quadratic-planar"

    @property
    def planar(self) -> bool:
        return self.value.endswith("planar")

    @property
    def n_parameters(self) -> int:
        return {System.LINEAR: 2, System.QUADRATIC: 2, System.QUADRATIC_PLANAR: 3, System.SPHERICAL_LINEAR: 3,
                System.SPHERICAL_QUADRATIC: 3, System.SPHERICAL_QUADRATIC_PLANAR: 4}[self]

    def dimension(self, extras: bool = False) -> int:
        return (2 if self.planar else 4) + (2 if extras else 0)


def rhs(kind: System, pars, lib=math, extras: bool = False):
    """f(t, s) for the state of ``kind`` (plus s, D when ``extras``); ``pars`` as
    :meth:`reference.Problem.pars` (with σ appended for planar kinds); ``lib`` is math, mpmath
    or heyoka."""
    return _SYSTEMS[System(kind)](pars, lib.sqrt, extras)


def _linear(pars, sqrt, extras):
    w2, g2 = pars

    def f(_t, s):
        x, y, u, w = s[0], s[1], s[2], s[3]
        out = [u, w, -w2 * x - g2 * u, -w2 * y - g2 * w]
        if extras:
            v2 = u * u + w * w
            out += [sqrt(v2), g2 * v2]
        return out

    return f


def _quadratic(pars, sqrt, extras):
    w2, b = pars

    def f(_t, s):
        x, y, u, w = s[0], s[1], s[2], s[3]
        sp = sqrt(u * u + w * w)
        out = [u, w, -w2 * x - b * u * sp, -w2 * y - b * w * sp]
        if extras:
            out += [sp, b * sp * sp * sp]
        return out

    return f


def _quadratic_planar(pars, sqrt, extras):
    w2, b, sig0 = pars  # σ = sign ẋ given (None: taken from ẋ, the kinked law itself)

    def f(_t, s):
        x, u = s[0], s[1]
        sig = sig0 if sig0 is not None else math.copysign(1.0, u)
        out = [u, -w2 * x - sig * b * u * u]
        if extras:
            out += [sig * u, sig * b * u * u * u]
        return out

    return f


def _spherical(quad: bool):
    def make(pars, sqrt, extras):
        ln, g, drag = pars
        l2 = ln * ln

        def f(_t, s):
            X, Y, U, W = s[0], s[1], s[2], s[3]
            Z = sqrt(l2 - X * X - Y * Y)
            Zd = -(X * U + Y * W) / Z
            v2 = U * U + W * W + Zd * Zd
            sp = sqrt(v2)
            gam = drag * sp if quad else drag
            c = (v2 + g * Z) / l2
            out = [U, W, -gam * U - X * c, -gam * W - Y * c]
            if extras:
                out += [sp, gam * v2]
            return out

        return f

    return make


def _spherical_planar(pars, sqrt, extras):
    ln, g, b, sig0 = pars
    l2 = ln * ln

    def f(_t, s):
        X, U = s[0], s[1]
        sig = sig0 if sig0 is not None else math.copysign(1.0, U)
        Z = sqrt(l2 - X * X)
        sp = sig * U * ln / Z  # the speed, analytic on a stretch of constant σ
        v2 = sp * sp
        out = [U, -b * sp * U - X * (v2 + g * Z) / l2]
        if extras:
            out += [sp, b * sp * v2]
        return out

    return f


_SYSTEMS = {System.LINEAR: _linear, System.QUADRATIC: _quadratic, System.QUADRATIC_PLANAR: _quadratic_planar,
            System.SPHERICAL_LINEAR: _spherical(False), System.SPHERICAL_QUADRATIC: _spherical(True),
            System.SPHERICAL_QUADRATIC_PLANAR: _spherical_planar}
