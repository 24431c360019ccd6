"""Issue 29, hostile folders — crashes: input the readers do not expect (TOML nested beyond any
text, tables of the wrong shape, values of the wrong type, ranges that are no ranges, a
placeholder no witness fills, a device or a pipe in the catalog).  Each is one line on stderr
naming the file and line, exit 2 — never a traceback, never "internal error", never a hang.

Each test edits a fresh skeleton and runs ``verify`` on it once, in a subprocess."""

from __future__ import annotations

import os

import pytest

from hostile_support import DEEP, HANG_SECONDS, names_file_and_line, no_crash, one_line_error
from hostile_support import sh, skeleton_template, text  # noqa: F401 - fixtures


# --- TOML nested beyond any text ---------------------------------------------------------------------
@pytest.mark.parametrize("where", ["text.toml", "catalog"])
def test_deeply_nested_toml_array(text, sh, where):
    """a deeply nested TOML array (e.g. `x = ` + "[" * 5000 + "]" * 5000) in text.toml and in a
    catalog file;  (crashes — each: one line naming file and line, exit 2)"""
    rel, anchor = ("text.toml", 'language = "en"') if where == "text.toml" else (text.catalog, 'section = "1"')
    text.replace(rel, anchor, anchor + "\n" + DEEP)
    run = sh.run("verify", "--text", text.root)
    err = one_line_error(run)
    names_file_and_line(err, text.path(rel), text.line_of(rel, "deep = "))


# --- tables and values of the wrong shape -------------------------------------------------------------
def _single_bracket_erratum(text):
    text.replace(text.errata, "[[erratum]]", "[erratum]")
    return text.errata, [text.line_of(text.errata, "[erratum]")]


def _equation_list_of_strings(text):
    text.write("catalog/z.toml", 'section = "2"\nequation = ["x"]\n')
    return "catalog/z.toml", [2]


def _number_as_note(text):
    header = text.line_of(text.errata, "[[erratum]]")
    return text.errata, [text.replace_line(text.errata, 'note = "Eliminating t from (1)', "note = 3"), header]


def _number_as_cause_title(text):
    header = text.line_of(text.errata, "[[cause]]")
    return text.errata, [text.replace_line(text.errata, "title = ", "title = 3"), header]


def _number_as_suspicion(text):
    text.append(text.errata, f'\n[[cleared]]\nid = "{text.id}:1"\nsuspicion = 3\nnote = "the derivation agrees"\n')
    return text.errata, [text.line_of(text.errata, "suspicion = 3"), text.line_of(text.errata, "[[cleared]]")]


SHAPES = {
    "[erratum] with single brackets": _single_bracket_erratum,
    'equation = ["x"]': _equation_list_of_strings,
    "non-string note": _number_as_note,
    "non-string title": _number_as_cause_title,
    "non-string suspicion": _number_as_suspicion,
}


@pytest.mark.parametrize("shape", list(SHAPES))
def test_wrong_toml_shape(text, sh, shape):
    """wrong TOML shapes: `[erratum]` with single brackets, `equation = ["x"]`, a non-string
    `note`/`title`/`suspicion`;  (crashes — each: one line naming file and line, exit 2)

    Here: one shape each (an erratum's note, a cause's title, a cleared suspect's suspicion); the
    line named is the key's, or its table's header's."""
    rel, lines = SHAPES[shape](text)
    run = sh.run("verify", "--text", text.root)
    err = one_line_error(run)
    names_file_and_line(err, text.path(rel), lines)


# --- ranges that are no ranges ---------------------------------------------------------------------------
A_RANGE = 'range = ["-5", "5"]'


def _range_of_a(text, value: str) -> list[int]:
    """Give the symbol a the range ``value``; the lines a message may name (the range's, the
    symbol's header)."""
    line = text.replace_line("text.toml", A_RANGE, f"range = {value}")
    return [line, text.line_of("text.toml", "[symbols.a]")]


@pytest.mark.parametrize("value", ['["0", "oo"]', '["-oo", "oo"]'])
def test_an_infinite_range_is_sampled_or_refused(text, sh, value):
    """ranges `["0", "oo"]`, `["-oo", "oo"]` (either sampled correctly — then verify passes — or
    refused naming the range), `["0", "1/0"]`, `["0", "0/0"]`;  (crashes — each: one line naming
    file and line, exit 2)

    Here: the infinite ones, as the range of the symbol a."""
    lines = _range_of_a(text, value)
    run = sh.run("verify", "--text", text.root, seconds=HANG_SECONDS)
    no_crash(run)
    if run.code == 0:
        return
    err = one_line_error(run, "range")
    names_file_and_line(err, text.path("text.toml"), lines)


@pytest.mark.parametrize("value", ['["0", "1/0"]', '["0", "0/0"]'])
def test_an_undefined_range_end_is_refused(text, sh, value):
    """ranges `["0", "oo"]`, `["-oo", "oo"]` (either sampled correctly — then verify passes — or
    refused naming the range), `["0", "1/0"]`, `["0", "0/0"]`;  (crashes — each: one line naming
    file and line, exit 2)

    Here: the undefined ones (zoo, nan), as the range of the symbol a: refused naming the range."""
    lines = _range_of_a(text, value)
    run = sh.run("verify", "--text", text.root, seconds=HANG_SECONDS)
    err = one_line_error(run, "range")
    names_file_and_line(err, text.path("text.toml"), lines)


def test_a_range_that_refers_to_itself(text, sh):
    """a range that refers to itself, and two mutual ranges;  (crashes — each: one line naming
    file and line, exit 2)

    Here: the first — a's range ["-5", "a"]."""
    lines = _range_of_a(text, '["-5", "a"]')
    run = sh.run("verify", "--text", text.root, seconds=HANG_SECONDS)
    err = one_line_error(run, "range")
    names_file_and_line(err, text.path("text.toml"), lines)


def test_two_mutual_ranges(text, sh):
    """a range that refers to itself, and two mutual ranges;  (crashes — each: one line naming
    file and line, exit 2)

    Here: the second — a's range refers to v0, v0's to a."""
    lines = _range_of_a(text, '["-5", "v0"]')
    lines.append(text.replace_line("text.toml", 'range = ["-3", "3"]', 'range = ["-3", "a"]'))
    lines.append(text.line_of("text.toml", "[symbols.v0]"))
    run = sh.run("verify", "--text", text.root, seconds=HANG_SECONDS)
    err = one_line_error(run, "range")
    names_file_and_line(err, text.path("text.toml"), lines)


# --- a placeholder no witness fills ---------------------------------------------------------------------
def test_unknown_witness_parameter_in_a_note(text, sh):
    """`{witness.parameters.nosuch}` in an erratum note (refused at load, naming the file and
    line);  (crashes — each: one line naming file and line, exit 2)"""
    line = text.replace_line(text.errata, 'note = "Eliminating t from (1)',
                             'note = "The factor 2 is lost at nosuch = {witness.parameters.nosuch}."')
    run = sh.run("verify", "--text", text.root)
    err = one_line_error(run, "nosuch")
    names_file_and_line(err, text.path(text.errata), [line, text.line_of(text.errata, "[[erratum]]")])


# --- a device, a pipe ----------------------------------------------------------------------------------------
def test_a_catalog_file_linked_to_dev_zero(text, sh):
    """a symlink in `catalog/` to `/dev/zero`; a FIFO as `catalog/z.toml` (must not hang: refused
    as a special file).  (crashes — each: one line naming file and line, exit 2)

    Here: the first — catalog/z.toml -> /dev/zero, which a reader would read for ever (a file
    with no line: the message names the file)."""
    link = text.path("catalog/z.toml")
    link.symlink_to("/dev/zero")
    run = sh.run("verify", "--text", text.root, seconds=HANG_SECONDS)
    one_line_error(run, "z.toml")


def test_a_fifo_in_the_catalog(text, sh):
    """a symlink in `catalog/` to `/dev/zero`; a FIFO as `catalog/z.toml` (must not hang: refused
    as a special file).  (crashes — each: one line naming file and line, exit 2)

    Here: the second — a FIFO nobody writes to, which a reader would wait on for ever."""
    os.mkfifo(text.path("catalog/z.toml"))
    run = sh.run("verify", "--text", text.root, seconds=15)
    one_line_error(run, "z.toml")
