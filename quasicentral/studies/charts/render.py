"""Drawing a chart's PNG from its CSV file only (never recomputing), with fixed sizes and
metadata: byte-identical for the same CSV."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from quasicentral.studies.charts.data import ChartError, check, read_table
from quasicentral.studies.charts.maps import beta_fit
from quasicentral.studies.png import save_png

YES = "yes"  # how a true flag is written in a CSV header (invert_x)


_STYLE = {"closed form, double": ("o", "-"), "mpmath": ("s", "-"), "balls": ("D", "-"), "series": ("v", "-"),
          "quadrature": ("^", "-"), "ODE": ("x", "--"), "ODE, Taylor": ("+", "--")}
FLOOR = 1e-125  # errors below are drawn at the floor (the references carry 130–140 digits)
NONFINITE = 1e2  # where a stability map draws the points at which a method returned inf or NaN


def render(csv_path: Path, png_path: Path) -> None:
    """Draw the PNG for one CSV (the kind is read from its header)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    table = read_table(csv_path)
    kind = check(Path(csv_path), table)
    header, rows = table.header, table.rows
    draw = {"workprecision": _render_workprecision, "stability": _render_stability, "validity": _render_validity}[kind]
    with matplotlib.rc_context({"font.size": 8, "svg.hashsalt": "quasicentral", "path.simplify": False}):
        try:
            fig = draw(plt, header, rows)
        except (ValueError, TypeError, KeyError) as exc:  # data that passed the checks but cannot be drawn
            plt.close("all")
            raise ChartError(f"{csv_path}: cannot be drawn: {exc}") from None
        foot = f"measured on {header.get('processor', '?')} ({header.get('cores', '?')} cores), " \
               f"Python {header.get('python', '?')}, numpy {header.get('numpy', '?')}, scipy {header.get('scipy', '?')}, " \
               f"mpmath {header.get('mpmath', '?')}, python-flint {header.get('python-flint', '?')}, " \
               f"heyoka {header.get('heyoka', '?')}"
        fig.text(0.005, 0.003, foot, fontsize=5.5, color="0.35")
        save_png(fig, png_path)
        plt.close(fig)


def _render_workprecision(plt, header, rows):
    cases = list(dict.fromkeys(r["case"] for r in rows))
    fig, axes = plt.subplots(1, len(cases), figsize=(5.2 * len(cases), 5.6), dpi=110, squeeze=False)
    for ax, case in zip(axes[0], cases):
        sub = [r for r in rows if r["case"] == case]
        methods = list(dict.fromkeys(r["method"] for r in sub))
        for j, meth in enumerate(methods):
            pts = [r for r in sub if r["method"] == meth]
            fam = pts[0]["family"]
            mk, ls = _STYLE.get(fam, ("o", "-"))
            err = [max(float(r["error"]), FLOOR) for r in pts]
            sec = [float(r["seconds"]) for r in pts]
            ax.plot(err, sec, marker=mk, ls=ls if len(pts) > 1 else "none", lw=0.8, ms=3.5,
                    color=plt.cm.tab10(j % 10), label=meth)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.invert_xaxis()
        ax.set_xlabel("max relative error (→ more accurate)")
        ax.set_ylabel("seconds per evaluation")
        ax.set_title(case, fontsize=7.5)
        ax.grid(True, which="major", lw=0.3)
        ax.legend(fontsize=5.5, loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=2, frameon=False)
    fig.suptitle(header.get("title", ""), fontsize=9)
    fig.tight_layout(rect=(0, 0.02, 1, 0.97))
    return fig


def _render_stability(plt, header, rows):
    fig, ax = plt.subplots(figsize=(6.4, 4.6), dpi=110)
    methods = list(dict.fromkeys(r["method"] for r in rows))
    for j, meth in enumerate(methods):
        pts = [r for r in rows if r["method"] == meth]
        role = pts[0]["role"]
        xs = [float(r["x"]) for r in pts]
        es = [max(float(r["error"]), 1e-18) if r["error"] else float("nan") for r in pts]
        ls = "-" if role.startswith("default") else ("--" if role == "naive" else ":")
        color = plt.cm.tab10(j % 10)
        ax.plot(xs, [e if math.isfinite(e) else float("nan") for e in es], ls=ls, marker="o", ms=2.5,
                lw=1.2 if role == "default" else 0.9, color=color, label=f"{meth} [{role}]")
        bad = [x for x, e in zip(xs, es) if not math.isfinite(e)]
        if bad:  # inf or NaN returned: drawn as crosses on the top edge
            ax.plot(bad, [NONFINITE] * len(bad), ls="none", marker="x", ms=4, color=color)
    if any(not math.isfinite(float(r["error"])) for r in rows if r["error"]):
        ax.axhline(NONFINITE, color="0.5", lw=0.5, ls=":")
        ax.text(0.01, 0.995, "× : inf or NaN returned", transform=ax.transAxes, fontsize=6, va="top")
    ax.set_yscale("log")
    if header.get("xscale", "log") == "log":
        ax.set_xscale("log")
    if header.get("invert_x") == YES:
        ax.invert_xaxis()
    ax.set_xlabel(header.get("xlabel", "x"))
    ax.set_ylabel(header.get("ylabel", "error"))
    for level in (1e-2, 1e-3, 1e-6, 1e-12):
        ax.axhline(level, color="0.8", lw=0.5, zorder=0)
    ax.set_title(header.get("title", ""), fontsize=8)
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=5.5)
    fig.tight_layout(rect=(0, 0.03, 1, 1))
    return fig


def _render_validity(plt, header, rows):
    panels = list(dict.fromkeys((r["model"], r["against"]) for r in rows if r["against"] == "spherical"))
    periods = sorted({int(r["periods"]) for r in rows})
    fig, axes = plt.subplots(len(periods), len(panels) + 1, figsize=(4.0 * (len(panels) + 1), 3.5 * len(periods)),
                             dpi=100, squeeze=False)
    levels = [-6, -3, -2]
    for i, n in enumerate(periods):
        for j, (model, against) in enumerate(panels):
            ax = axes[i][j]
            sub = [r for r in rows if r["model"] == model and r["against"] == against and int(r["periods"]) == n]
            amps = sorted({float(r["amplitude"]) for r in sub})
            drags = sorted({float(r["drag"]) for r in sub})
            grid = np.full((len(drags), len(amps)), np.nan)
            for r in sub:
                grid[drags.index(float(r["drag"])), amps.index(float(r["amplitude"]))] = math.log10(
                    max(float(r["error"]), 1e-16))
            A, D = np.meshgrid(amps, drags)
            cf = ax.contourf(A, D, grid, levels=np.arange(-10, 1, 1), cmap="viridis", extend="both")
            cs = ax.contour(A, D, grid, levels=levels, colors=["w", "orange", "red"], linewidths=1.0)
            ax.clabel(cs, fmt={-6: "1e-6", -3: "0.1 %", -2: "1 %"}, fontsize=6)
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlabel("amplitude R0 / l")
            ax.set_ylabel("drag κ/Ω" if sub and sub[0]["drag_law"] == "kappa" else "drag βR0")
            ax.set_title(f"{model} vs full pendulum, {n} period{'s' if n > 1 else ''}", fontsize=7)
            fig.colorbar(cf, ax=ax, label="log10 error / R0")
        ax = axes[i][-1]
        sub = [r for r in rows if r["against"] == "small-swing" and int(r["periods"]) == n]
        xs = [float(r["drag"]) for r in sub]
        ys = [max(float(r["error"]), 1e-18) for r in sub]
        ax.loglog(xs, ys, "o-", ms=3, label="first order vs (26)–(27)")
        c, p = beta_fit(rows, n)
        if math.isfinite(c):
            xf = np.geomspace(min(xs), max(xs), 50)
            ax.loglog(xf, c * xf**p, "k--", lw=0.8, label=f"fit {c:.3g}·(βR0)^{p:.2f}")
        for level in (1e-2, 1e-3, 1e-6):
            ax.axhline(level, color="0.7", lw=0.5)
        ax.set_xlabel("βR0")
        ax.set_ylabel("max error / R0")
        ax.set_title(f"first order in β alone, {n} period{'s' if n > 1 else ''}", fontsize=7)
        ax.legend(fontsize=6)
        ax.grid(True, lw=0.3)
    fig.suptitle(header.get("title", ""), fontsize=9)
    fig.tight_layout(rect=(0, 0.02, 1, 0.97))
    return fig
