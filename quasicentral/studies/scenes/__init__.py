"""Scenes: a situation and the accuracy it needs → the cheapest model that meets that accuracy.

A scene (a TOML file, see ``scenes/`` at the repository root) describes a pendulum, its start,
the medium and a question — a quantity and the largest acceptable absolute error in the
answer's unit.  The toolkit climbs a *ladder* of models, from cheapest to richest:

=========================  ====================================================================
``ellipse``                small swings, no drag: the ellipse (13), [Brepta1953] §3
``linear``                 small swings, linear drag R = 2κmv, closed form (19)/(21), §4
``quadratic-first-order``  small swings, quadratic drag R = mβv², first order in β, (28)–(30)
``quadratic``              small swings, quadratic drag, (26)–(27) integrated numerically
``spherical``              the full nonlinear spherical pendulum with drag, integrated numerically
``period-series``          planar swing without drag: the period by the series (66), N terms
``period-exact``           planar swing without drag: the exact period T0·2K(k²)/π, (60)–(61)
=========================  ====================================================================

Only the rungs that model the scene's medium are on its ladder (the ellipse, which neglects
any drag, is always the first rung).  For every rung the toolkit gives two error estimates:

* **a priori**: the orders of the terms the rung neglects, evaluated for the scene (drag:
  O(κT), O(βA·ΩT); second order in β: O((βA)²(ΩT)²); finite swings: O(ε²), O(ε²ΩT) with
  ε = A/l, the phase drift (a² + b²)/16l² and the apsidal precession 3ab/8l² per radian of
  Ωt; integration: O(rtol·ΩT)).  These are orders of magnitude with O(1) constants.
* **a posteriori**: the rung's answer is compared with the next richer rung's answer on a
  sample of the scene (32 points per period over the duration, or the first revolution), and
  the richer rung's own estimate is added (triangle inequality):
  err_i = |answer_i − answer_{i+1}| + err_{i+1}, or, when smaller, the same bound through the
  richest rung, |answer_i − answer_richest| + err_richest.  The difference to the next richer
  rung measures exactly what the rung neglects: it *confirms* the a-priori order when it is
  within ten times that estimate (plus the richer rung's own error).  The richest rung is checked by its own
  integration at two tolerances (rtol and 100·rtol); the exact period against mpmath.

The a posteriori estimate decides (it is measured on this very scene); the a priori estimate
is reported beside it and flagged when the measurement exceeds it tenfold.  The cheapest rung
whose estimate is within the tolerance answers; if none is, the decision says so.

What the quantities mean (the bob starts at X = R0, Y = 0 with the horizontal velocity v0
along +Y; positions are horizontal displacements; L is per unit mass):

* ``trajectory`` — X(t), Y(t) on [0, duration]; the error is the largest distance (m).
* ``period`` — the time of the first revolution: the azimuth turns through 2π (Y crosses zero
  upwards); for a planar swing (v0 = 0) the next turning point on the release side.  Without
  drag and for a planar swing this is the period of (60); with drag the motion is not
  periodic and the "period" is the duration of that first revolution: 2π/ω for linear drag
  (ω² = Ω² − κ², exactly), 2π/Ω to first order in β (the paper's remark before (31)).
* ``decay-per-revolution`` — R0 − R1, R1 the distance from the vertical at the end of that
  first revolution; (33) R1 = R0(1 − πβR0) in first order for the conical start R0Ω = v0.
  In the full model R1 also moves with the apsidal precession (it is what one observes).
* ``angular-momentum`` — L(t) = XẎ − YẊ on [0, duration] (m²/s).  Law (4) L = L0 e^{−2κt}
  is exact for linear drag even for the full pendulum (the drag is tangent, L̇ = −2κL), so
  the closed form answers it exactly; for quadratic drag (5) L = L0 e^{−βs} is exact but the
  path s depends on the model: the first-order rung takes s from the ideal ellipse.

Layout: :mod:`.reading` (the TOML file, units with pint, the checks naming key and line),
:mod:`.rungs` (each rung's answer), :mod:`.ladder` (a priori orders and the decision),
:mod:`.views` (JSON document, text report, plot).

Cost is the richness of the model, not CPU time (in double precision ``ellipkm1`` is as fast
as the series; the series is what one evaluates by hand).

>>> scene = parse('''
... [pendulum]
... length = 1.0
... g = 9.81
... [start]
... displacement = 0.01
... speed = 0.0
... [medium]
... drag = "none"
... [question]
... quantity = "period"
... tolerance = 1e-3
... ''')
>>> d = decide(scene)
>>> d.chosen.model, round(d.chosen.value, 6)
('ellipse', 2.006067)
"""

from __future__ import annotations

from quasicentral.studies.scenes.ladder import RUNGS, Decision, Rating, a_priori, decide, ladder
from quasicentral.studies.scenes.reading import (
    DRAGS, NEEDS_DURATION, QUANTITIES, Scene, SceneError, key_lines, load, parse, printable, quantity_value,
)
from quasicentral.studies.scenes.rungs import answer, distance, ellipse_path, first_revolution, sample_times, scale
from quasicentral.studies.scenes.views import answer_document, document, meaning, plain, plot, report

__all__ = ["RUNGS", "Decision", "Rating", "a_priori", "decide", "ladder", "DRAGS", "NEEDS_DURATION", "QUANTITIES",
           "Scene", "SceneError", "key_lines", "load", "parse", "printable", "quantity_value", "answer", "distance",
           "ellipse_path", "first_revolution", "sample_times", "scale", "answer_document", "document", "meaning",
           "plain", "plot", "report"]
