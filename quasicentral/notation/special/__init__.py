"""Special functions of DLMF chapters 19 (elliptic integrals) and 22 (Jacobian elliptic
functions), with the theta functions of chapter 20 that chapter 22 is built on and Weierstrass's
℘, ζ, σ of chapter 23.

Every function is a sympy ``Function`` subclass in DLMF's notation and conventions — the
**modulus** k throughout (mpmath, python-flint and sympy's ``elliptic_k`` … take m = k²),
principal branches, Cauchy principal values where DLMF says so — with

* ``cls.mp(*args)``: the mpmath value at the caller's working precision (guard bits inside a
  local ``workprec``; the global precision is never set);
* ``cls.ball(*args, analytic=False)``: a python-flint ``acb`` ball at ``flint.ctx.prec`` (or
  ``ball = None`` where there is no rigorous route); with ``analytic=True`` a non-finite ball
  wherever the argument ball may touch a branch cut (for ``acb.integral``);
* ``fdiff`` with DLMF's derivatives, ``_latex`` in DLMF's notation, ``evalf`` through ``mp``.

:data:`FUNCTIONS` maps each name to its class (read-only).
"""

from types import MappingProxyType

from quasicentral.notation.special.bulirsch import BulirschCel, BulirschEl1, BulirschEl2, BulirschEl3
from quasicentral.notation.special.carlson import (
    CarlsonR, CarlsonRC, CarlsonRD, CarlsonRF, CarlsonRG, CarlsonRJ,
)
from quasicentral.notation.special.jacobi import (
    JacobiAM, JacobiArcCD, JacobiArcCN, JacobiArcCS, JacobiArcDC, JacobiArcDN, JacobiArcDS,
    JacobiArcNC, JacobiArcND, JacobiArcNS, JacobiArcSC, JacobiArcSD, JacobiArcSN, JacobiCD,
    JacobiCN, JacobiCS, JacobiDC, JacobiDN, JacobiDS, JacobiEpsilon, JacobiNC, JacobiND, JacobiNS,
    JacobiSC, JacobiSD, JacobiSN, JacobiZ,
)
from quasicentral.notation.special.legendre import (
    EllipticD, EllipticE, EllipticF, EllipticK, EllipticPi,
)
from quasicentral.notation.special.legendre_derived import (
    AGM, EllipticEp, EllipticKp, HeumanLambda, JacobiZeta,
)
from quasicentral.notation.special.theta import (
    EllipticNome, JacobiTheta1, JacobiTheta2, JacobiTheta3, JacobiTheta4,
)
from quasicentral.notation.special.weierstrass import WeierstrassP, WeierstrassSigma, WeierstrassZeta

FUNCTIONS = MappingProxyType({cls.__name__: cls for cls in (
    # chapter 19
    EllipticK, EllipticE, EllipticF, EllipticD, EllipticPi, EllipticKp, EllipticEp,
    CarlsonRF, CarlsonRD, CarlsonRJ, CarlsonRC, CarlsonRG, CarlsonR,
    BulirschCel, BulirschEl1, BulirschEl2, BulirschEl3,
    AGM, JacobiZeta, HeumanLambda,
    # chapter 22 (and the theta functions of chapter 20 it is written in)
    JacobiSN, JacobiCN, JacobiDN, JacobiNS, JacobiNC, JacobiND,
    JacobiSC, JacobiSD, JacobiCS, JacobiCD, JacobiDS, JacobiDC,
    JacobiAM, JacobiEpsilon, JacobiZ,
    JacobiArcSN, JacobiArcCN, JacobiArcDN, JacobiArcNS, JacobiArcNC, JacobiArcND,
    JacobiArcSC, JacobiArcSD, JacobiArcCS, JacobiArcCD, JacobiArcDS, JacobiArcDC,
    JacobiTheta1, JacobiTheta2, JacobiTheta3, JacobiTheta4, EllipticNome,
    # chapter 23, which chapters 19 and 22 use (half-periods ω₁, ω₃)
    WeierstrassP, WeierstrassZeta, WeierstrassSigma,
)})

__all__ = sorted(FUNCTIONS) + ["FUNCTIONS"]
