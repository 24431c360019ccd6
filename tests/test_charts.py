"""Stability maps: in every region where a method fails, the project's default stays accurate
(proved here at points in the region) while the naive route beside it fails; and the charts'
contract: CSV with a machine header, PNG rendered from the CSV alone, byte-identical."""

import math
import shutil
import subprocess
import sys
from pathlib import Path

import mpmath
import numpy as np
import pytest

from quasicentral.studies import charts as C

from quasicentral.models import motion

from quasicentral.models import period

from quasicentral.models import quadratic

from quasicentral.models import reference as R

OMEGA = math.sqrt(10.0)


# --- k² → 1, amplitude → π ------------------------------------------------------------------------
@pytest.mark.parametrize("delta", [1e-3, 1e-8, 1e-12, 1e-15])
def test_period_near_pi_default_accurate_naive_not(delta):
    ref = float(period.period_ratio_mp(delta=delta, dps=40))
    assert abs(float(period.period_ratio(delta=delta)) - ref) <= 4e-16 * ref
    naive = float(C.naive_period(math.pi - delta))
    if delta <= 1e-8:
        assert abs(naive - ref) > 1e-10 * ref  # m = sin²(φ0/2) has lost the digits that matter


# --- k² → 0 (u → v0) -----------------------------------------------------------------------------------
@pytest.mark.parametrize("m", [1e-6, 1e-10, 1e-14, 1e-17])
def test_k_minus_e_over_m_default_accurate_naive_not(m):
    with mpmath.workdps(40):
        ref = float((mpmath.ellipk(m) - mpmath.ellipe(m)) / m)
    assert abs(float(C.default_k_minus_e(m)) - ref) <= 1e-15 * ref
    assert abs(float(C.naive_k_minus_e(m)) - ref) > 1e-12 * ref


@pytest.mark.parametrize("k2", [1e-12, 1e-13, 1e-15])
def test_first_order_as_u_approaches_v0_default_accurate_printed_form_not(k2):
    R0, beta = 0.1, 0.5
    v0 = R0 * OMEGA * math.sqrt(1 - k2)
    th = np.linspace(0.3, math.pi - 0.3, 5)
    t = th / OMEGA
    with mpmath.workdps(40):
        xr, yr = quadratic.first_order([mpmath.mpf(a) for a in t], mpmath.mpf(R0), mpmath.mpf(v0), mpmath.mpf(OMEGA),
                                       mpmath.mpf(beta), ops=quadratic.MP)
    xr, yr = np.array(xr, dtype=float), np.array(yr, dtype=float)
    x, y = quadratic.first_order(t, R0, v0, OMEGA, beta)
    assert max(np.max(np.abs(x - xr)), np.max(np.abs(y - yr))) < 1e-15
    with np.errstate(all="ignore"):
        xz, yz = C.zeta_form(t, R0, v0, OMEGA, beta)
    err = max(np.max(np.abs(xz - xr)), np.max(np.abs(yz - yr)))
    assert not err < 1e-9  # NaN counts as failure too


def test_printed_form_is_right_where_it_applies():
    """The ζ-form (28)–(30) with k² well away from 0 agrees with the default on 0 ≤ Ωt ≤ π."""
    t = np.linspace(0, math.pi, 9) / OMEGA
    x, y = quadratic.first_order(t, 0.1, 0.2, OMEGA, 0.5)
    xz, yz = C.zeta_form(t, 0.1, 0.2, OMEGA, 0.5)
    assert np.max(np.abs(x - xz)) < 1e-14 and np.max(np.abs(y - yz)) < 1e-14


# --- the printed ζ-form beyond Ωt = π ---------------------------------------------------------------
@pytest.mark.parametrize("theta", [1.5 * math.pi, 4.2 * math.pi, 9.5 * math.pi])
def test_beyond_pi_default_accurate_printed_form_not(theta):
    R0, v0, beta = 0.1, 0.2, 0.5
    t = theta / OMEGA
    with mpmath.workdps(40):
        xr, yr = quadratic.first_order([mpmath.mpf(t)], mpmath.mpf(R0), mpmath.mpf(v0), mpmath.mpf(OMEGA),
                                       mpmath.mpf(beta), ops=quadratic.MP)
    x, y = quadratic.first_order([t], R0, v0, OMEGA, beta)
    assert abs(x[0] - float(xr[0])) < 1e-15 and abs(y[0] - float(yr[0])) < 1e-15
    xz, yz = C.zeta_form([t], R0, v0, OMEGA, beta)
    assert max(abs(xz[0] - float(xr[0])), abs(yz[0] - float(yr[0]))) > 1e-3 * R0


# --- κ → Ω ----------------------------------------------------------------------------------------
@pytest.mark.parametrize("eps", [-1e-9, -1e-14, 0.0, 1e-14, 1e-9])
def test_kappa_near_omega_default_accurate_naive_not(eps):
    kappa = OMEGA * (1 + eps)
    t = np.linspace(0.2, 6, 7)
    with mpmath.workdps(40):
        xr, yr = motion.linear([mpmath.mpf(a) for a in t], mpmath.mpf(0.1), mpmath.mpf(0.1), mpmath.mpf(OMEGA),
                               mpmath.mpf(kappa), ops=motion.MP)
    xr, yr = np.array(xr, dtype=float), np.array(yr, dtype=float)
    x, y = motion.linear(t, 0.1, 0.1, OMEGA, kappa)
    assert max(np.max(np.abs(x - xr)), np.max(np.abs(y - yr))) < 1e-15
    if 0 <= eps < 1e-10:  # real roots λ± nearly equal: e^(λ+t) − e^(λ−t) cancels, and 0/0 at κ = Ω
        xn, yn = C.naive_linear(t, 0.1, 0.1, OMEGA, kappa)
        err = max(np.max(np.abs(xn - xr)), np.max(np.abs(yn - yr)))
        assert not err < 1e-13  # NaN counts as failure too


# --- βR0·Ωt no longer small -------------------------------------------------------------------------
def test_large_beta_r0_omega_t_default_accurate_first_order_not():
    R0, v0, beta = 0.1, 0.2, 3.0  # βR0 = 0.3: βR0·Ωt ≈ 6 after 3 periods
    t = np.linspace(0.5, 3 * 2 * math.pi / OMEGA, 7)
    ref = R.solve("quadratic", {"R0": R0, "v0": v0, "omega2": OMEGA**2, "beta": beta}, t, tol=1e-13)
    x, y = motion.trajectory("quadratic", t, R0, v0, OMEGA**2, beta=beta)
    assert np.max(np.hypot(x - ref.x, y - ref.y)) < 1e-11 * R0
    x1, y1 = quadratic.first_order(t, R0, v0, OMEGA, beta)
    assert np.max(np.hypot(x1 - ref.x, y1 - ref.y)) > 0.1 * R0


# --- long times ----------------------------------------------------------------------------------
def test_long_times_default_accurate_naive_not():
    kappa = 1e-4
    t = np.array([1e4]) * 2 * math.pi / OMEGA
    with mpmath.workdps(40):
        xr, yr = motion.linear([mpmath.mpf(t[0])], mpmath.mpf(0.1), mpmath.mpf(0.1), mpmath.mpf(OMEGA),
                               mpmath.mpf(kappa), ops=motion.MP)
    x, y = motion.linear(t, 0.1, 0.1, OMEGA, kappa)
    err = max(abs(x[0] - float(xr[0])), abs(y[0] - float(yr[0])))
    xn, yn = C.naive_phase_linear(t, 0.1, 0.1, OMEGA, kappa)
    errn = max(abs(xn[0] - float(xr[0])), abs(yn[0] - float(yr[0])))
    assert err < 1e-16 and errn > 10 * err


# --- the charts' contract ---------------------------------------------------------------------------
def test_csv_round_trip_with_machine_header(tmp_path):
    rows = [{"map": "m", "x": 1e-3, "method": "a", "role": "default", "error": 1e-16},
            {"map": "m", "x": 1e-2, "method": "a", "role": "default", "error": 2e-16}]
    path = tmp_path / "c.csv"
    C.write_csv(path, rows, dict(C.machine(), chart="stability-m", title="t"))
    header, back = C.read_csv(path)
    for key in ("machine", "processor", "cores", "python", "numpy", "scipy", "mpmath", "python-flint", "heyoka"):
        assert key in header
    assert [float(r["error"]) for r in back] == [1e-16, 2e-16]


def test_quick_build_renders_from_csv_deterministically(tmp_path):
    paths = C.build(tmp_path, quick=True, only=["stability-kappa-to-omega", "stability-long-times"])
    assert [p.name for p in paths] == ["stability-kappa-to-omega.csv", "stability-kappa-to-omega.png",
                                       "stability-long-times.csv", "stability-long-times.png"]
    header, rows = C.read_csv(tmp_path / "stability-kappa-to-omega.csv")
    assert header["chart"] == "stability-kappa-to-omega" and header["mode"] == "quick"
    default = [float(r["error"]) for r in rows if r["role"] == "default"]
    naive = [float(r["error"]) for r in rows if r["role"] == "naive"]
    assert max(default) < 1e-14 and (np.nanmax(naive) > 1e-11 and np.isnan(naive).any())
    first = (tmp_path / "stability-kappa-to-omega.png").read_bytes()
    C.render_all(tmp_path)  # from the CSVs only
    assert (tmp_path / "stability-kappa-to-omega.png").read_bytes() == first


def test_committed_measurements_render_and_cover_ten_decades():
    from pathlib import Path

    folder = Path(C.__file__).parent / "data" / "measurements"
    csvs = sorted(folder.glob("workprecision-*.csv"))
    if not csvs:
        pytest.skip("no committed measurements")
    for path in csvs:
        header, rows = C.read_csv(path)
        assert header["mode"] == "full" and "processor" in header
        errs = [float(r["error"]) for r in rows if 0 < float(r["error"]) < 1]
        assert math.log10(max(errs)) - math.log10(min(errs)) >= 10, path.name


def test_cli_bad_usage_is_one_line_exit_2():
    proc = subprocess.run([sys.executable, "-m", "quasicentral.cli", "charts", "--only", "nosuch"], capture_output=True,
                          text=True)
    assert proc.returncode == 2
    assert proc.stderr.startswith("quasicentral: error:") and proc.stderr.strip().count("\n") == 0


@pytest.mark.parametrize("args", [["charts", "--render-only", "--out", "/nonexistent/x"], ["charts", "--bogus"],
                                  ["charts", "--render-only", "--quick"]])
def test_cli_bad_usage_in_process(args, capsys):
    from quasicentral.cli import main

    assert main(args) == 2
    err = capsys.readouterr().err
    assert err.startswith("quasicentral: error:") and err.strip().count("\n") == 0


@pytest.mark.slow
def test_quick_build_of_every_chart(tmp_path):
    paths = C.build(tmp_path, quick=True)
    assert len(paths) == 2 * len(C.CHARTS)


# --- issue 16: --render-only on bad data is one line naming the file (and line), exit 2 -----------------
@pytest.mark.parametrize("content,words", [
    (b"# chart: stability-long-times\nmap,x,method,role,error\nlong-times,abc,m,default,1e-3\n", "a.csv:3: x"),
    (b"# chart: stability-long-times\nmap,x,method,role,error\n", "a.csv: no data rows"),
    (bytes(range(256)) * 8, "a.csv: not UTF-8"),
    (b"# chart: pie\nx\n1\n", "a.csv: unknown chart kind"),
    (b"# chart: workprecision-period\ncase,method,family,seconds\nc,m,f,1\n", "missing column"),
    (b"# chart: validity\nmodel,against,drag_law,amplitude,drag,periods,error\nm,a,kappa,0.1,inf,1,0.1\n",
     "a.csv:3: drag must be finite"),
    (b"# chart: workprecision-period\ncase,method,family,seconds,error\nc,m,f\n", "a.csv:3: the row is too short"),
])
def test_render_only_refuses_bad_data(tmp_path, content, words):
    (tmp_path / "a.csv").write_bytes(content)
    proc = subprocess.run([sys.executable, "-m", "quasicentral.cli", "charts", "--render-only", "--out", str(tmp_path)],
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 2 and proc.stdout == ""
    assert proc.stderr.count("\n") == 1 and proc.stderr.startswith("quasicentral: error:") and words in proc.stderr, \
        proc.stderr
    assert not (tmp_path / "a.png").exists()


def test_chart_specs_are_typed_and_the_csv_header_unchanged():
    spec = C.STABILITY["period-near-pi"]
    assert spec.log_x is True and spec.invert_x is True
    assert spec.header() == {"title": spec.title, "xlabel": spec.xlabel, "ylabel": spec.ylabel, "xscale": "log",
                             "invert_x": "yes"}
    assert C.CHARTS[0] == "workprecision-period" and C.CHARTS[-1] == "validity" and len(C.CHARTS) == 13


@pytest.mark.parametrize("transparent", [False, True])
def test_a_png_drops_its_alpha_channel_only_where_every_pixel_is_opaque(tmp_path, transparent):
    """An opaque figure is written as RGB (pdfTeX copies such a PNG into a PDF as it is); one
    with transparent pixels keeps them; either is byte-identical when written again."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from PIL import Image

    from quasicentral.studies.png import save_png

    written = []
    for name in ("a.png", "b.png"):
        fig, ax = plt.subplots(figsize=(2, 2), dpi=50)
        ax.plot([0, 1], [1, 0])
        if transparent:
            fig.patch.set_alpha(0.0)
        save_png(fig, tmp_path / name)
        plt.close(fig)
        written.append((tmp_path / name).read_bytes())
    assert written[0] == written[1]
    image = Image.open(tmp_path / "a.png")
    assert image.mode == ("RGBA" if transparent else "RGB")
    assert round(image.info["dpi"][0]) == 50
    if not transparent:
        reference = tmp_path / "reference.png"
        fig, ax = plt.subplots(figsize=(2, 2), dpi=50)
        ax.plot([0, 1], [1, 0])
        fig.savefig(reference, format="png")
        plt.close(fig)
        assert np.array_equal(np.asarray(Image.open(reference).convert("RGB")), np.asarray(image))


def test_render_only_never_writes_through_a_symbolic_link(tmp_path, capsys):
    """A PNG that is a link to another file is refused (one line naming it, exit 2), its target
    left as it was; without the link the PNG is written through a temporary file."""
    from quasicentral.cli import main

    name = "stability-k2-to-0"
    shutil.copy(Path(C.__file__).parent.parent.parent / "data" / "measurements" / f"{name}.csv", tmp_path)
    target = tmp_path.parent / f"{tmp_path.name}-target.txt"
    target.write_text("keep")
    (tmp_path / f"{name}.png").symlink_to(target)
    assert main(["charts", "--render-only", "--out", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and f"{name}.png" in err and "symbolic link" in err, err
    assert target.read_text() == "keep"
    (tmp_path / f"{name}.png").unlink()
    assert main(["charts", "--render-only", "--out", str(tmp_path)]) == 0
    png = tmp_path / f"{name}.png"
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and not png.is_symlink()
    assert sorted(p.name for p in tmp_path.iterdir()) == [f"{name}.csv", f"{name}.png"]
