"""The charts' data files: CSV with a ``# key: value`` header, written and read back, and
checked before anything is drawn (a bad file is one :class:`ChartError` naming file and line)."""

from __future__ import annotations

import csv
import io
import math
from dataclasses import dataclass
from pathlib import Path

from quasicentral import files

MAX_BYTES = 64 << 20  # a chart's CSV is at most 64 MiB


class ChartError(ValueError):
    """A chart that cannot be measured or drawn, or a data file that cannot be read."""


def _fmt(v) -> str:
    if isinstance(v, float):
        return repr(v)
    return str(v)


def write_csv(path: Path, rows: list[dict], header: dict) -> None:
    """Rows with a ``# key: value`` header (machine, versions, what was measured)."""
    buf = io.StringIO()
    for k, v in header.items():
        buf.write(f"# {k}: {v}\n")
    cols = list(rows[0].keys()) if rows else []
    for r in rows:
        for k in r:
            if k not in cols:
                cols.append(k)
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(cols)
    for r in rows:
        w.writerow([_fmt(r.get(c, "")) for c in cols])
    files.write_text(path, buf.getvalue())  # a temporary file and a rename, never through a link


@dataclass(frozen=True)
class Table:
    """A CSV read back: the header, the rows (strings) and each row's line in the file."""

    header: dict
    rows: list
    lines: list


def read_table(path: Path) -> Table:
    """(header, rows, lines) of a CSV written by :func:`write_csv`; numbers stay strings."""
    path = Path(path)
    try:
        with open(path, "rb") as fh:
            data = fh.read(MAX_BYTES + 1)
    except OSError as exc:
        raise ChartError(f"{path}: cannot read: {exc.strerror or exc}") from None
    if len(data) > MAX_BYTES:
        raise ChartError(f"{path}: larger than {MAX_BYTES >> 20} MiB, not chart data")
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError:
        raise ChartError(f"{path}: not UTF-8 text (binary content?), not chart data") from None
    if "\0" in text:
        raise ChartError(f"{path}: contains NUL bytes, not chart data")
    header, body, numbers = {}, [], []
    for no, line in enumerate(text.splitlines(), 1):
        if line.startswith("# "):
            k, _, v = line[2:].partition(": ")
            header[k] = v
        elif line.strip():
            body.append(line)
            numbers.append(no)
    try:
        rows = list(csv.DictReader(io.StringIO("\n".join(body) + "\n")))
    except csv.Error as exc:
        raise ChartError(f"{path}: not CSV: {exc}") from None
    return Table(header, rows, numbers[1:])


def read_csv(path: Path) -> tuple[dict, list[dict]]:
    """(header, rows) of a CSV written by :func:`write_csv`; numbers stay strings."""
    t = read_table(path)
    return t.header, t.rows


#: the columns each kind of chart needs, and which of them are numbers
COLUMNS = {
    "workprecision": (("case", "method", "family"), ("seconds", "error")),
    "stability": (("method", "role"), ("x", "error")),
    "validity": (("model", "against", "drag_law"), ("amplitude", "drag", "periods", "error")),
}


def kind_of(header: dict) -> str:
    chart = header.get("chart", "")
    return next((k for k in COLUMNS if chart == k or chart.startswith(k + "-")), "")


def check(path: Path, table: Table) -> str:
    """The chart's kind, after checking the header, the columns and every number; a problem is
    a ChartError naming the file (and the line)."""
    kind = kind_of(table.header)
    if not kind:
        raise ChartError(f"{path}: unknown chart kind {table.header.get('chart', '')!r} in its header "
                         f"(# chart: …)")
    if not table.rows:
        raise ChartError(f"{path}: no data rows")
    words, nums = COLUMNS[kind]
    missing = [c for c in words + nums if c not in table.rows[0]]
    if missing:
        raise ChartError(f"{path}: missing column(s) {', '.join(missing)}")
    for row, line in zip(table.rows, table.lines):
        for c in words:
            if row.get(c) is None:
                raise ChartError(f"{path}:{line}: the row is too short (no {c})")
        for c in nums:
            cell = row.get(c)
            if cell is None:
                raise ChartError(f"{path}:{line}: the row is too short (no {c})")
            if cell == "" and c == "error" and kind == "stability":
                continue  # a method without a value at this point
            try:
                val = float(cell)
            except ValueError:
                raise ChartError(f"{path}:{line}: {c} must be a number, not {cell[:40]!r}") from None
            if c != "error" and not math.isfinite(val):
                raise ChartError(f"{path}:{line}: {c} must be finite, not {cell!r}")
    return kind
