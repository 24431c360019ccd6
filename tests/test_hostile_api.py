"""Issue 29, hostile folders — the notebook API: ``qc.load_text``, ``text.verify`` and
``text.report`` refuse what they cannot use with one documented exception type,
``quasicentral.InputError`` (a ``ValueError``), in Python's words (no command-line option
names); they never read a name relative to the working directory that was not given so, and
never iterate a string as if it were a list of ids.

These run in the test process, on a fresh skeleton each (its own id, its own cache); the texts
they load are forgotten afterwards."""

from __future__ import annotations

import pytest

from hostile_support import DEEP, copy_text, input_error_type, names_file_and_line
from hostile_support import skeleton_template, text  # noqa: F401 - fixtures


@pytest.fixture(autouse=True)
def private(tmp_path, monkeypatch):
    """A cache of the test's own; every text loaded from the test's folder forgotten afterwards."""
    import quasicentral as qc

    monkeypatch.setenv("QUASICENTRAL_CACHE", str(tmp_path / "cache"))
    yield
    ws = qc.workspace()
    for t in [t for t in ws.texts if str(t.root).startswith(str(tmp_path.resolve()))]:
        ws.forget(t)


def _no_option_names(message: str) -> None:
    assert "--" not in message, f"a command-line option in the API's message: {message!r}"


def attempt(call):
    """``(result, None)``, or ``(None, the exception)`` the call raised."""
    try:
        return call(), None
    except Exception as exc:  # noqa: BLE001 - what it raises is the question
        return None, exc


def refused(exc: BaseException | None) -> str:
    """``exc`` is the API's refusal: a ``quasicentral.InputError`` in Python's words; its message.
    (What the message says is checked first, so that a refusal of the wrong type still shows it.)"""
    assert exc is not None, "not refused"
    _no_option_names(str(exc))
    InputError = input_error_type()
    assert isinstance(exc, InputError), f"{type(exc).__name__} instead of InputError: {exc}"
    return str(exc)


def test_load_text_of_bytes_is_never_relative_to_the_working_directory(text, skeleton_template, tmp_path,
                                                                      monkeypatch):
    """Notebook API: `qc.load_text(b"/path")` (bytes: refused or decoded, never cwd-relative),
    messages that do not mention `--text`, `text.verify(ids="ct:1")` (a string: treated as one id
    or refused, never iterated by characters), `verify(dps="30")` and `dps=30.5` refused with
    InputError, `text.report(out, lang="xx")` InputError.

    Here: `qc.load_text(b"/path")`.  A decoy text sits where the bytes' repr, `b'/path'`, leads
    from the working directory."""
    import quasicentral as qc

    cwd = tmp_path / "cwd"
    cwd.mkdir()
    decoy = cwd / repr(str(text.root).encode())  # "b'/tmp/.../hxxxx'"
    decoy.parent.mkdir(parents=True)
    copy_text(skeleton_template, decoy, "decoy" + text.id)
    monkeypatch.chdir(cwd)
    got, exc = attempt(lambda: qc.load_text(str(text.root).encode()))
    if got is None:
        refused(exc)
        return
    assert got.id == text.id and got.text.root == text.root.resolve(), f"loaded {got.text.root}"


@pytest.mark.parametrize("name", ["", "no-such-text-anywhere", "missing/folder"])
def test_load_text_messages_do_not_mention_options(name, tmp_path, monkeypatch):
    """Notebook API: `qc.load_text(b"/path")` (bytes: refused or decoded, never cwd-relative),
    messages that do not mention `--text`, `text.verify(ids="ct:1")` (a string: treated as one id
    or refused, never iterated by characters), `verify(dps="30")` and `dps=30.5` refused with
    InputError, `text.report(out, lang="xx")` InputError.

    Here: messages that do not mention `--text` — a name that is no text (empty, no such shipped
    text, no such folder) is an InputError in Python's words."""
    import quasicentral as qc

    monkeypatch.chdir(tmp_path)
    _, exc = attempt(lambda: qc.load_text(name))
    assert exc is not None
    assert "--text" not in str(exc), str(exc)
    refused(exc)


def test_verify_with_one_id_as_a_string(text):
    """Notebook API: `qc.load_text(b"/path")` (bytes: refused or decoded, never cwd-relative),
    messages that do not mention `--text`, `text.verify(ids="ct:1")` (a string: treated as one id
    or refused, never iterated by characters), `verify(dps="30")` and `dps=30.5` refused with
    InputError, `text.report(out, lang="xx")` InputError.

    Here: `text.verify(ids="ID:1")`."""
    import quasicentral as qc

    loaded = qc.load_text(text.root)
    eid = f"{text.id}:1"
    results, exc = attempt(lambda: loaded.verify(ids=eid))
    if results is None:
        refused(exc)
        return
    assert [r.entry.id for r in results] == [eid]
    assert results[eid].status.value == "verified"


@pytest.mark.parametrize("dps", ["30", 30.5], ids=["dps='30'", "dps=30.5"])
def test_verify_refuses_a_precision_that_is_not_a_whole_number(text, dps):
    """Notebook API: `qc.load_text(b"/path")` (bytes: refused or decoded, never cwd-relative),
    messages that do not mention `--text`, `text.verify(ids="ct:1")` (a string: treated as one id
    or refused, never iterated by characters), `verify(dps="30")` and `dps=30.5` refused with
    InputError, `text.report(out, lang="xx")` InputError.

    Here: `verify(dps="30")` and `dps=30.5`."""
    import quasicentral as qc

    loaded = qc.load_text(text.root)
    results, exc = attempt(lambda: loaded.verify(dps=dps))
    assert results is None, f"verified at dps={dps!r}"
    refused(exc)


def test_report_refuses_an_unknown_language(text, tmp_path):
    """Notebook API: `qc.load_text(b"/path")` (bytes: refused or decoded, never cwd-relative),
    messages that do not mention `--text`, `text.verify(ids="ct:1")` (a string: treated as one id
    or refused, never iterated by characters), `verify(dps="30")` and `dps=30.5` refused with
    InputError, `text.report(out, lang="xx")` InputError.

    Here: `text.report(out, lang="xx")`, and nothing written."""
    import quasicentral as qc

    loaded = qc.load_text(text.root)
    out = tmp_path / "out"
    paths, exc = attempt(lambda: loaded.report(out, lang="xx"))
    assert paths is None, f"a report in language 'xx': {paths}"
    assert not out.exists() or not any(out.iterdir()), sorted(p.name for p in out.iterdir())
    assert "xx" in refused(exc)


def test_a_malformed_folder_raises_input_error_naming_file_and_line(text):
    """The Python API (`import quasicentral as qc; qc.load_text(...)`, `text.verify(...)`,
    `text.report(...)`) raises one documented exception type, `quasicentral.InputError` (a
    `ValueError` subclass), with the same message in Python's words (no command-line option
    names).

    Here (the contract itself, beside the reproductions): the deeply nested array of text.toml,
    through `load_text`, names the file and line as the command does."""
    import quasicentral as qc

    text.replace("text.toml", 'language = "en"', 'language = "en"\n' + DEEP)
    _, exc = attempt(lambda: qc.load_text(text.root))
    assert exc is not None
    names_file_and_line(str(exc), text.path("text.toml"), text.line_of("text.toml", "deep = "))
    refused(exc)
