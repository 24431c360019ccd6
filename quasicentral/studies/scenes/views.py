"""Views of a decision: the meaning of the question, the JSON document (pure Python types),
the plain-text report and the plot."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from quasicentral.studies.png import save_png
from quasicentral.studies.scenes.ladder import RUNGS, Decision, Rating
from quasicentral.studies.scenes.reading import NEEDS_DURATION, Scene, printable


def meaning(scene: Scene) -> str:
    """What the asked quantity means for this scene, in a sentence."""
    q = scene.quantity
    if q == "trajectory":
        return "X(t), Y(t): the bob's horizontal displacement from the vertical (m)"
    if q == "angular-momentum":
        return "L(t) = XẎ − YẊ: the vertical angular momentum per unit mass (m²/s)"
    end = ("the bob is back at its turning point on the release side" if scene.planar else
           "its azimuth has turned through 2π")
    if q == "period":
        if scene.drag == "none":
            return f"the period (s): the time until {end}"
        return (f"the duration of the first revolution (s), until {end}; with drag the motion is not "
                "periodic and each revolution lasts a little differently")
    return f"R0 − R1 (m): how much closer to the vertical the bob is when {end}"


def _num(x) -> float | None:
    return float(x) if x is not None and math.isfinite(x) else None


def answer_document(decision: Decision) -> dict:
    scene, value = decision.scene, decision.chosen.value
    if scene.quantity == "trajectory":
        return {"t": decision.times.tolist(), "x": value[0].tolist(), "y": value[1].tolist()}
    if scene.quantity == "angular-momentum":
        return {"t": decision.times.tolist(), "L": value.tolist()}
    return {"value": float(value)}


def document(decision: Decision) -> dict:
    """The decision as JSON-ready data (deterministic except the keys named "seconds")."""
    scene, chosen = decision.scene, decision.chosen

    def rating(r: Rating) -> dict:
        out = {"model": r.model}
        if r.terms:
            out["terms"] = r.terms
        out.update({"estimated_error": _num(r.estimated_error), "a_priori_error": _num(r.a_priori),
                    "confirmed": r.confirmed, "checked_against": r.checked_against, "neglects": r.neglects})
        if not isinstance(r.value, np.ndarray):
            out["value"] = _num(r.value) if r.value is not None else None
        out["seconds"] = r.seconds
        return out

    doc = {"scene": scene.title or Path(scene.source).stem, "source": scene.source, "quantity": scene.quantity,
           "meaning": meaning(scene), "unit": scene.unit, "tolerance": scene.tolerance, "model": chosen.model}
    if chosen.terms:
        doc["terms"] = chosen.terms
    doc.update({"description": RUNGS[chosen.model], "meets_tolerance": decision.meets,
                "estimated_error": _num(chosen.estimated_error), "a_priori_error": _num(chosen.a_priori),
                "checked_against": chosen.checked_against,
                "rejected": [{"model": r.model, **({"terms": r.terms} if r.terms else {}),
                              "estimated_error": _num(r.estimated_error), "a_priori_error": _num(r.a_priori),
                              "neglects": r.neglects} for r in decision.rejected],
                "ladder": [rating(r) for r in decision.ratings],
                "answer": answer_document(decision), "seconds": decision.seconds})
    return plain(doc)


def plain(obj):
    """``obj`` with numpy scalars and arrays turned into Python numbers and lists (JSON-ready)."""
    if isinstance(obj, dict):
        return {str(k): plain(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [plain(v) for v in obj]
    if isinstance(obj, np.ndarray):
        return plain(obj.tolist())
    if isinstance(obj, np.bool_):
        return bool(obj)
    if isinstance(obj, np.integer):
        return int(obj)
    if isinstance(obj, np.floating):
        return float(obj)
    return obj


def _fmt(x: float | None, unit: str) -> str:
    if x is None or math.isnan(x):
        return "none (no answer)"
    return f"{x:.3g} {unit}" if math.isfinite(x) else "unbounded"


def report(decision: Decision) -> str:
    """A plain-text account: the choice, why the cheaper models were rejected, the evidence."""
    s, c, u = decision.scene, decision.chosen, decision.scene.unit
    what = f"{s.quantity} over {s.duration:g} s" if s.duration else s.quantity
    drag = {"none": "no drag", "linear": f"linear drag κ = {s.coefficient:g} 1/s",
            "quadratic": f"quadratic drag β = {s.coefficient:g} 1/m"}[s.drag]
    lines = [f"scene     {s.name}  ({printable(s.source)})",
             f"pendulum  l = {s.length:g} m, g = {s.g:g} m/s^2 (Ω = {s.Omega:.6g} 1/s, T0 = {s.T0:.6g} s); "
             f"R0 = {s.R0:.6g} m (φ0 = {math.degrees(s.phi0):.4g}°), v0 = {s.v0:g} m/s; {drag}",
             f"question  {what}, tolerance {s.tolerance:g} {u}",
             f"          {meaning(s)}"]
    if decision.meets:
        lines.append(f"model     {c.label}: {RUNGS[c.model]}")
    else:
        lines.append(f"model     none meets the tolerance; the best is {c.label}: {RUNGS[c.model]}")
    lines.append(f"          estimated error {_fmt(c.estimated_error, u)} (checked against {c.checked_against}); "
                 f"a priori {_fmt(c.a_priori, u)}")
    if decision.rejected:
        lines.append("rejected")
        for r in decision.rejected:
            lines.append(f"  {r.label:<26} estimated error {_fmt(r.estimated_error, u):<18} > {s.tolerance:g} {u}; "
                         f"neglects {r.neglects} (a priori {_fmt(r.a_priori, u)})")
    lines.append("ladder    (a posteriori: against the next richer rung plus its own error)")
    for r in decision.ratings:
        mark = "*" if r is c else " "
        flag = "" if r.confirmed else "  [a priori NOT confirmed]"
        lines.append(f" {mark} {r.label:<26} {_fmt(r.estimated_error, u):<18} a priori {_fmt(r.a_priori, u):<12}"
                     f" vs {r.checked_against}{flag}")
    if s.quantity == "trajectory":
        x, y = c.value
        lines.append(f"answer    {decision.times.size} points; at t = {s.duration:g} s: x = {x[-1]:.9g} m, "
                     f"y = {y[-1]:.9g} m  (--json for all)")
    elif s.quantity == "angular-momentum":
        lines.append(f"answer    {decision.times.size} points; L(0) = {c.value[0]:.9g}, L({s.duration:g} s) = "
                     f"{c.value[-1]:.9g} m^2/s (per unit mass; --json for all)")
    else:
        lines.append(f"answer    {s.quantity} = {float(c.value):.12g} {u}")
    lines.append(f"time      {decision.seconds:.2f} s")
    return "\n".join(lines)


def plot(decision: Decision, path) -> None:
    """The evidence as a PNG (fixed metadata: byte-identical for the same decision): the answer
    (for curves) and each rung's error against the next richer rung, with the tolerance."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    s, c = decision.scene, decision.chosen
    curves = s.quantity in NEEDS_DURATION
    with matplotlib.rc_context({"svg.hashsalt": "quasicentral", "font.size": 8}):
        fig, axes = plt.subplots(1, 2 if curves else 1, figsize=(10.0 if curves else 5.5, 4.0), dpi=110,
                                 squeeze=False)
        axes = axes[0]
        if curves:
            _plot_answer(axes[0], decision)
            _plot_differences(axes[1], decision)
        else:
            _plot_estimates(axes[0], decision)
        # the title is the user's text: shown as typed, never parsed as mathtext
        fig.suptitle(f"{s.title or Path(s.source).stem}: {s.quantity} → {c.label}", fontsize=9, parse_math=False)
        fig.tight_layout()
        save_png(fig, path)
        plt.close(fig)


def _plot_answer(ax, decision: Decision) -> None:
    s, c, rich = decision.scene, decision.chosen, decision.richest.value
    if s.quantity == "trajectory":
        ax.plot(rich[0] * 1e3, rich[1] * 1e3, "k--", lw=0.6, label=f"{decision.richest.label} (richest)")
        ax.plot(c.value[0] * 1e3, c.value[1] * 1e3, lw=0.9, label=f"{c.label} (chosen)")
        ax.set_xlabel("x [mm]")
        ax.set_ylabel("y [mm]")
        ax.set_aspect("equal", adjustable="datalim")
    else:
        ax.plot(decision.times, rich, "k--", lw=0.6, label=f"{decision.richest.label} (richest)")
        ax.plot(decision.times, c.value, lw=0.9, label=f"{c.label} (chosen)")
        ax.set_xlabel("t [s]")
        ax.set_ylabel("L [m²/s]")
    ax.legend(fontsize=7)
    ax.grid(True, lw=0.3)


def _plot_differences(ax, decision: Decision) -> None:
    s, c = decision.scene, decision.chosen
    for lower, upper in zip(decision.ratings, decision.ratings[1:]):
        if s.quantity == "trajectory":
            d = np.hypot(lower.value[0] - upper.value[0], lower.value[1] - upper.value[1])
        else:
            d = np.abs(lower.value - upper.value)
        ax.semilogy(decision.times, np.where(d > 0, d, np.nan), lw=0.8 if lower is not c else 1.4,
                    label=f"{lower.label} − {upper.label}")
    ax.axhline(s.tolerance, color="r", lw=0.8, ls=":", label="tolerance")
    ax.axhline(decision.richest.estimated_error, color="k", lw=0.6, ls="--",
               label=f"{decision.richest.label}: own error")
    low, high = ax.get_ylim()
    ax.set_ylim(max(low, 1e-6 * min(s.tolerance, decision.richest.estimated_error)), high)
    ax.set_xlabel("t [s]")
    ax.set_ylabel(f"difference [{s.unit}]")
    ax.legend(fontsize=7)
    ax.grid(True, lw=0.3)


def _plot_estimates(ax, decision: Decision) -> None:
    s, c = decision.scene, decision.chosen
    labels = [r.label for r in decision.ratings]
    errs = [r.estimated_error if math.isfinite(r.estimated_error) else np.nan for r in decision.ratings]
    colors = ["tab:green" if r is c and decision.meets else "tab:gray" for r in decision.ratings]
    ax.bar(range(len(labels)), errs, color=colors, log=True)
    ax.scatter(range(len(labels)), [r.a_priori for r in decision.ratings], marker="_", s=200, color="k",
               label="a priori", zorder=3)
    ax.axhline(s.tolerance, color="r", lw=0.8, ls=":", label="tolerance")
    ax.set_xticks(range(len(labels)), labels, rotation=20, fontsize=7)
    ax.set_ylabel(f"estimated error [{s.unit}]")
    ax.legend(fontsize=7)
    ax.grid(True, lw=0.3, axis="y")
