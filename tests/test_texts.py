"""A text is a folder: a user's text verifies, reports and mutates without touching the package;
a user's mistake in it gets one clear line and exit 2 (or an inconclusive verdict with a reason)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from quasicentral import cli
from quasicentral.engine import run
from quasicentral.engine.checker import Options
from quasicentral.engine.workspace import Workspace



@pytest.fixture(autouse=True)
def _isolated(tmp_path, monkeypatch):
    monkeypatch.setenv("QUASICENTRAL_CACHE", str(tmp_path / "cache"))
    yield



def _run(argv, capsys):
    code = cli.main(argv)
    out, err = capsys.readouterr()
    return code, out, err


def test_new_text_verifies_at_once(tmp_path, capsys):
    code, out, _ = _run(["new-text", str(tmp_path / "mine")], capsys)
    assert code == 0 and "text.toml" in out
    code, out, err = _run(["verify", "--text", str(tmp_path / "mine"), "--json"], capsys)
    assert code == 0, err
    doc = json.loads(out)
    assert {r["text"] for r in doc["equations"]} == {"mine"}
    assert [r["status"] for r in doc["equations"]] == ["verified", "erratum"]
    erratum = doc["equations"][1]
    assert erratum["witness"]["certified"] and erratum["witness"]["parameters"]


def test_new_text_refuses_a_folder_in_use(tmp_path, capsys):
    (tmp_path / "busy").mkdir()
    (tmp_path / "busy" / "notes.txt").write_text("mine")
    code, _, err = _run(["new-text", str(tmp_path / "busy")], capsys)
    assert code == 2 and "not empty" in err and err.count("\n") == 1



def test_a_symbol_named_D_hides_the_derivative_shorthand(tmp_path, capsys):
    """D for a diffusion coefficient (m²/s): any name a physicist writes is the text's; the
    notation's D(f) shorthand is hidden in that text, whose derivatives are written Derivative.
    An entry's name_cs heads it in the Czech report (a Czech newcomer's names never reached it)."""
    root = tmp_path / "diffusion"
    (root / "catalog").mkdir(parents=True)
    (root / "text.toml").write_text('''id = "diffusion"
title = "Diffusion"
authors = ["A. Lecturer"]
year = 2026
language = "en"
check = "identity"

[symbols.D]
meaning = "the diffusion coefficient"
latex = 'D'
dimension = "m^2/s"
assumptions = ["positive"]
range = ["1/2", "2"]

[symbols.t]
meaning = "the time"
latex = 't'
dimension = "s"
assumptions = ["positive"]
range = ["1/2", "2"]
''')
    (root / "catalog" / "01.toml").write_text('''section = "1"
title = "Spreading"

[[equation]]
id = "diffusion:1"
name = "the growth of the variance"
name_cs = "růst rozptylu"
latex = '\\frac{d}{dt}\\,2Dt^2 = 4Dt'
printed = \'\'\'Eq(Derivative(2*D*t**2, t), 4*D*t)\'\'\'

[[equation]]
id = "diffusion:2"
name = "the variance, mistyped"
latex = '\\frac{d}{dt}\\,2Dt^2 = 2Dt'
printed = \'\'\'Eq(Derivative(2*D*t**2, t), 2*D*t)\'\'\'
''')
    code, out, err = _run(["verify", "--text", str(root), "--json"], capsys)
    assert code == 1, err
    rows = {r["id"]: r for r in json.loads(out)["equations"]}
    assert rows["diffusion:1"]["status"] == "verified" and rows["diffusion:2"]["verdict"] == "refuted", rows
    # name_cs is the Czech report's heading; without one an entry is headed by its number
    code, _, err = _run(["report", "--text", str(root), "--lang", "cs", "--out", str(tmp_path / "out")], capsys)
    tex = (tmp_path / "out" / "diffusion-report-cs.tex").read_text()
    assert code == 0 and "růst rozptylu" in tex and "the growth" not in tex, err

def test_a_third_text_verifies_with_its_own_symbols(kepler, capsys):
    """G, M, e, a, p, T and θ are the text's own; u(θ), r(θ) are functions of θ, and u'' reaches
    the numeric and certified stages."""
    code, out, err = _run(["verify", "--text", str(kepler), "--json"], capsys)
    assert code == 0, err
    rows = {r["id"]: r for r in json.loads(out)["equations"]}
    assert rows["kepler:1"]["status"] == "verified" and rows["kepler:1"]["method"] == "symbolic"
    for eid in ("kepler:2", "kepler:3"):
        assert rows[eid]["status"] == "erratum"
        w = rows[eid]["witness"]
        assert w["certified"] and set(w["parameters"]) <= {"theta", "G", "M", "h", "e", "T"}
    code, out, _ = _run(["errata", "--text", str(kepler), "--json"], capsys)
    assert code == 0 and [r["kind"] for r in json.loads(out)["errata"]] == ["sign", "exponent"]


def test_a_refuted_function_of_theta_is_certified(kepler, capsys):
    """A typo in Binet's equation (u'' − u): the second derivative in θ reaches the balls."""
    cat = kepler / "catalog" / "orbit.toml"
    cat.write_text(cat.read_text().replace("printed = '''Eq(D(u, 2) + u, G*M/h**2)'''",
                                           "printed = '''Eq(D(u, 2) - u, G*M/h**2)'''"))
    code, out, _ = _run(["verify", "--text", str(kepler), "--id", "kepler:1", "--json"], capsys)
    row = json.loads(out)["equations"][0]
    assert code == 1 and row["verdict"] == "refuted" and row["witness"]["certified"]


def test_shipped_and_user_texts_together(kepler, capsys, monkeypatch, verdict_cache):
    monkeypatch.setenv("QUASICENTRAL_CACHE", str(verdict_cache))  # the shipped verdicts: read back
    code, out, err = _run(["verify", "--text", str(kepler), "--text", "pendulum", "--json"], capsys)
    assert code == 0, err  # every erratum recorded
    texts = {r["id"].split(":")[0] for r in json.loads(out)["equations"]}
    assert texts == {"kepler", "pendulum"}, texts


def test_the_latex_parser_check_is_kept_per_text(kepler, capsys, monkeypatch, tmp_path):
    """catalog keeps each entry's parser answer in the cache: a second run reads every one
    back (the same document); an edited text is parsed anew, a damaged record too."""
    monkeypatch.setenv("QUASICENTRAL_CACHE", str(tmp_path / "cache"))
    code, first, err = _run(["catalog", "--text", str(kepler), "--json"], capsys)
    assert code == 0, err
    code, _, err = _run(["catalog", "--text", str(kepler)], capsys)
    assert code == 0 and err.strip().endswith("(parsed: 0, read from the cache: 3)"), err
    code, again, _ = _run(["catalog", "--text", str(kepler), "--json"], capsys)
    assert again == first
    kept = sorted((tmp_path / "cache" / "latex-parser").glob("*.json"))
    assert len(kept) == 3
    kept[0].write_text("{not json")
    code, _, err = _run(["catalog", "--text", str(kepler)], capsys)
    assert err.strip().endswith("(parsed: 1, read from the cache: 2)"), err
    _edit(kepler / "catalog" / "orbit.toml", 'number = "2"', 'number = "2 "')
    code, _, err = _run(["catalog", "--text", str(kepler)], capsys)
    assert code == 0 and err.strip().endswith("(parsed: 3, read from the cache: 0)"), err


def _edit(path: Path, old: str, new: str) -> None:
    text = path.read_text()
    assert old in text
    path.write_text(text.replace(old, new))


MISTAKES = {
    "toml syntax": (lambda k: _edit(k / "catalog" / "orbit.toml", 'number = "2"', 'number = "2'),
                    "orbit.toml:"),
    "unknown symbol": (lambda k: _edit(k / "catalog" / "orbit.toml", "Eq(r, p/(1 - e*cos(theta)))",
                                       "Eq(r, q/(1 - e*cos(theta)))"), "unknown name q"),
    "duplicate id": (lambda k: _edit(k / "catalog" / "orbit.toml", 'id = "kepler:3"', 'id = "kepler:2"'),
                     "duplicate id"),
    "derivation without entry": (lambda k: _edit(k / "orbit.py", '@derives("kepler:3"', '@derives("kepler:9"'),
                                 "not in the catalog"),
    "entry without derivation": (lambda k: _edit(k / "orbit.py", '@derives("kepler:3", unknowns=(T**2,))\n', ""),
                                 "has no derivation"),
    "module raises": (lambda k: _edit(k / "orbit.py", "S = symbols_of(__file__)", "S = symbols_of(__file__)\n1 / 0"),
                      "orbit.py:9: ZeroDivisionError"),
    "undeclared in the module": (lambda k: _edit(k / "orbit.py", 'S("theta G M h e p a T u r")',
                                                 'S("theta G M h e p a T u r w")'), "no symbol 'w'"),
    "bad symbol table": (lambda k: _edit(k / "text.toml", 'dimension = "L^2/T"', 'dimension = "bananas"'),
                         "text.toml:"),
    "bad errata kind": (lambda k: _edit(k / "errata" / "orbit.toml", 'kind = "sign"', 'kind = "typo"'),
                        "unknown kind"),
    "no text.toml": (lambda k: (k / "text.toml").unlink(), "text.toml: missing"),
}


@pytest.mark.parametrize("mistake", sorted(MISTAKES))
@pytest.mark.parametrize("command", ["verify", "mutate"])
def test_a_users_mistake_is_one_line_and_exit_2(mistake, command, kepler, capsys):
    spoil, expected = MISTAKES[mistake]
    spoil(kepler)
    code, _, err = _run([command, "--text", str(kepler)], capsys)
    assert code == 2, err
    assert err.count("\n") == 1 and "internal error" not in err and "Traceback" not in err
    assert expected in err


def test_a_derivation_that_raises_while_checked_is_inconclusive(kepler, capsys):
    _edit(kepler / "orbit.py", "    b = a * sp.sqrt(1 - e**2)", "    b = a * sp.sqrt(1 - e**2) / 0 * undefined_name")
    code, out, err = _run(["verify", "--text", str(kepler), "--json"], capsys)
    row = {r["id"]: r for r in json.loads(out)["equations"]}["kepler:3"]
    assert code == 1 and row["status"] == "unexpected" and row["verdict"] == "inconclusive"
    assert "derivation failed: NameError" in row["detail"]


def test_the_cache_follows_the_texts_files(kepler, tmp_path, capsys):
    """Editing a user's derivation invalidates its verdicts, and only those: the other text's
    (a new text's skeleton) are read back."""
    other = tmp_path / "other"
    assert _run(["new-text", str(other)], capsys)[0] == 0
    assert _run(["verify", "--text", str(kepler), "--text", str(other)], capsys)[0] == 0
    _edit(kepler / "orbit.py", "return sp.Eq(T**2, sp.simplify(period**2))",
          "return sp.Eq(T**2, sp.simplify(2 * period**2))")
    seen = []
    ws = Workspace()
    selected = ws.resolve([str(kepler), str(other)])
    outcomes = run.run(ws, [e for t in selected for e in t.entries.values()], Options(), progress=seen.append)
    assert seen[0].cached == len(ws.text("other").entries) == 2  # the other text's verdicts stand
    assert seen[0].total == len(outcomes) > 2
    by_id = {o.id: o for o in outcomes}
    assert not by_id["kepler:3"].ok  # the edited derivation no longer supports the correction


def test_report_builds_only_the_texts_named(kepler, tmp_path, capsys):
    out_dir = tmp_path / "out"
    code, out, err = _run(["report", "--text", str(kepler), "--out", str(out_dir)], capsys)
    assert code == 0, err
    names = sorted(p.name for p in out_dir.glob("*.tex"))
    assert names == ["kepler-report-en.tex", "versions.tex"]
    tex = (out_dir / "kepler-report-en.tex").read_text()
    assert r"\theta" in tex and "varphi" not in tex  # θ prints as declared
    assert "Brepta" not in tex and not (out_dir / "figures").exists()


def test_mutate_on_a_users_text(kepler, capsys):
    """Mutation testing works on any text's symbols (θ, G, M …): no internal error."""
    code, out, err = _run(["mutate", "--text", str(kepler), "--json", "--jobs", "1"], capsys)
    assert code in (0, 1) and "internal error" not in err, err
    res = json.loads(out)
    assert res["entries"] == 1 and res["mutants"] > 5 and res["false_alarms"] == 0
    assert res["recall"] == 1.0, res["undetected"]


def test_a_quantity_defined_only_as_a_root(tmp_path, capsys):
    """"x₁ is the first zero of J₁" (a newcomer's Approx(x1, 3.8317) was refused: x1 had no
    value) and "u solves tan u = a·u in (π, 3π/2)", a root that moves with a: declared with
    ``solves`` and a range (the bracket), each is the root there, its printed rounding checked
    and its derivative in a the implicit function theorem's.  A bracket with two roots is refused."""
    root = tmp_path / "roots"
    (root / "catalog").mkdir(parents=True)
    head = '''id = "roots"
title = "Roots"
authors = ["A. Lecturer"]
year = 2026
language = "en"
check = "identity"

[symbols.x1]
meaning = "the first zero of J1"
latex = 'j_{1,1}'
solves = "besselj(1, x1)"
range = ["3", "%s"]

[symbols.a]
meaning = "a slope"
latex = 'a'
assumptions = ["positive"]
range = ["2", "5"]

[symbols.u]
meaning = "the root of tan u = a u between pi and 3 pi/2"
latex = 'u'
solves = "sin(u) - a*u*cos(u)"
range = ["pi + 1/100", "3*pi/2 - 1/100"]
'''
    (root / "text.toml").write_text(head % "9/2")
    entries = [("1", "Approx(x1, 3.8317)"), ("2", "Approx(x1, 3.8371)"), ("3", "Eq(tan(u), a*u)"),
               ("4", "Eq(Derivative(u, a), u/(a**2*u**2 + 1 - a))"), ("5", "Eq(Derivative(u, a), u/(a**2*u**2 + 1))")]
    (root / "catalog" / "01.toml").write_text('section = "1"\n' + "".join(
        f'\n[[equation]]\nid = "roots:{i}"\nname = "entry {i}"\nlatex = \'x\'\nprinted = \'\'\'{p}\'\'\'\n'
        for i, p in entries))
    code, out, err = _run(["verify", "--text", str(root), "--json"], capsys)
    rows = {r["id"]: r for r in json.loads(out)["equations"]}
    assert code == 1, err
    assert [rows[f"roots:{i}"]["verdict"] for i, _ in entries] == [
        "verified", "refuted", "verified", "verified", "refuted"], rows
    assert "3.83170597" in rows["roots:2"]["detail"], rows["roots:2"]
    # a bracket [3, 8] holds two zeros of J1 (3.83 and 7.02): the quantity is not defined by it
    (root / "text.toml").write_text(head % "8")
    code, out, err = _run(["verify", "--text", str(root), "--json"], capsys)
    rows = {r["id"]: r for r in json.loads(out)["equations"]}
    assert rows["roots:1"]["verdict"] == "inconclusive" and "several roots" in rows["roots:1"]["detail"], rows
