"""The command-line contract: names, JSON keys, exit codes, one-line errors."""

import json
import subprocess
import sys
import xml.etree.ElementTree as ET

import pytest

from quasicentral.cli import main


def run(*args):
    proc = subprocess.run([sys.executable, "-m", "quasicentral.cli", *args], capture_output=True, text=True)
    return proc.returncode, proc.stdout, proc.stderr


@pytest.mark.parametrize("args", [
    ["verify", "--source", "nosuch"],
    ["verify", "--dps", "0"],
    ["verify", "--dps", "-5"],
    ["verify", "--dps", "3"],
    ["verify", "--dps", "100000"],
    ["verify", "--dps", "nan"],
    ["verify", "--bogus"],
    ["verify", "--id", "brepta1953:999"],
    ["verify", "--source", "pendulum", "--id", "brepta1953:4"],
    ["verify", "--junit", ""],
    ["mutate", "--per-entry", "0"],
    ["nosuchcommand"],
    [],
])
def test_bad_usage_is_one_line_exit_2(args):
    code, out, err = run(*args)
    assert code == 2
    assert err.strip().count("\n") == 0 and err.startswith("quasicentral: error:"), err
    assert "Traceback" not in err


def test_verify_json_contract(outcomes, capsys, monkeypatch):
    code = main(["verify", "--source", "brepta1953", "--json", "--id", "brepta1953:4", "--id", "brepta1953:1"])
    doc = json.loads(capsys.readouterr().out)
    assert code == 0
    assert [r["id"] for r in doc["equations"]] == ["brepta1953:1", "brepta1953:4"]
    for r in doc["equations"]:
        for key in ("id", "source", "number", "name", "section", "verdict", "method", "printed_latex", "erratum"):
            assert key in r
        assert r["verdict"] in ("verified", "refuted", "inconclusive")
    assert doc["summary"]["ok"] is True


def test_errata_json_contract(outcomes, capsys):
    code = main(["errata", "--json"])
    doc = json.loads(capsys.readouterr().out)
    assert code == 0
    assert doc["errata"], "the toolkit finds errata in these texts"
    for r in doc["errata"]:
        for key in ("id", "source", "number", "name", "kind", "printed_latex", "corrected_latex", "witness", "note"):
            assert key in r
        for key in ("parameters", "printed", "corrected", "digits", "certified"):
            assert key in r["witness"]
    for r in doc["cleared"]:
        assert r["note"] and r["evidence"]


def test_junit_report(outcomes, tmp_path, capsys):
    target = tmp_path / "out" / "verify.xml"
    code = main(["verify", "--junit", str(target), "--source", "pendulum"])
    capsys.readouterr()
    assert code == 0
    root = ET.parse(target).getroot()
    cases = root.findall(".//testcase")
    assert cases and all(c.get("name").startswith("pendulum:") for c in cases)


def test_unwritable_junit_path_is_a_one_line_error(outcomes, tmp_path, capsys):
    blocker = tmp_path / "file"
    blocker.write_text("keep me")
    code = main(["verify", "--source", "pendulum", "--junit", str(blocker / "x.xml")])
    err = capsys.readouterr().err
    assert code == 2 and "cannot write" in err
    assert blocker.read_text() == "keep me"


def test_verify_is_deterministic(outcomes, capsys):
    main(["verify", "--json", "--source", "pendulum"])
    first = capsys.readouterr().out
    main(["verify", "--json", "--source", "pendulum"])
    assert capsys.readouterr().out == first


def test_timing_line_says_what_it_times(tmp_path, monkeypatch, capsys):
    monkeypatch.setenv("QUASICENTRAL_CACHE", str(tmp_path))
    assert main(["verify", "--id", "brepta1953:1"]) == 0
    assert "verify: checked 1 entry in" in capsys.readouterr().err
    assert main(["verify", "--id", "brepta1953:1"]) == 0
    err = capsys.readouterr().err
    assert err.startswith("verify: 1 entry read back in") and "a cached run" in err, err
    assert main(["verify", "--id", "brepta1953:1", "--json"]) == 0
    assert capsys.readouterr().err == ""  # --json: quiet
    for f in tmp_path.glob("runs/*.json"):  # the whole run forgotten: each verdict read from the cache
        f.unlink()
    assert main(["verify", "--id", "brepta1953:1"]) == 0
    err = capsys.readouterr().err
    assert err.startswith("verify: checked 1 entry in") and "(computed: 0, read from the cache: 1)" in err, err


def test_a_warm_run_is_read_back_whole_and_checked(tmp_path, monkeypatch, capsys):
    """A run whose code, texts and options are unchanged is read back without sympy: the same
    output, exit code and JUnit report.  A per-entry verdict edited since, or a record of the
    wrong shape, sends the run through the checked cache again."""
    monkeypatch.setenv("QUASICENTRAL_CACHE", str(tmp_path))
    args = ["verify", "--id", "pendulum:equation-of-motion", "--jobs", "1", "--json"]
    assert main(args + ["--junit", str(tmp_path / "a.xml")]) == 0
    first = capsys.readouterr().out
    assert main(args + ["--junit", str(tmp_path / "b.xml")]) == 0
    assert capsys.readouterr().out == first
    assert (tmp_path / "b.xml").read_bytes() == (tmp_path / "a.xml").read_bytes()
    assert len(list(tmp_path.glob("runs/*.json"))) == 1
    # a per-entry verdict edited to say "verified": not read back, the checked cache recomputes it
    (verdict,) = tmp_path.glob("*.json")
    d = json.loads(verdict.read_text())
    d["outcome"]["status"] = "verified"
    verdict.write_text(json.dumps(d))
    assert main(args) == 0
    out, err = capsys.readouterr()
    assert json.loads(out)["equations"][0]["status"] == "erratum"
    assert "contradicts the errata registry" in err
    # a record of the wrong shape: one line, and the run recomputed
    (record,) = [r for r in tmp_path.glob("runs/*.json") if '"junit": null' in r.read_text()]
    for junk in (b'{"stdout": 3}', b"\x9f\x00 not text", b"[1, 2]"):
        record.write_bytes(junk)
        assert main(args) == 0
        out, err = capsys.readouterr()
        assert out == first and len(err.strip().splitlines()) == 1 and "wrong shape" in err and str(record) in err
    # the options are part of the key: the table is not the JSON
    assert main(args[:-1]) == 0
    assert not capsys.readouterr().out.startswith("{")


def test_version_flag(capsys):
    with pytest.raises(SystemExit) as info:
        main(["--version"])
    assert info.value.code == 0 and capsys.readouterr().out.startswith("quasicentral ")
