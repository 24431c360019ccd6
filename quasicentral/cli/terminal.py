"""The terminal: the command's standard output and error, progress bars and warnings.

A reader that stops early (``quasicentral verify | head -2``) is not an error: the output stops
quietly and the exit code is still the command's own.  Progress is drawn on stderr with tqdm
only when stderr is a terminal, the environment variable ``CI`` is not set and ``--json`` is not
given.  What a text contributes to a line (an id, a title, a message) has its control
characters escaped (:func:`safe`): a folder cannot send escape sequences to the terminal.
"""

from __future__ import annotations

import io
import os
import sys


def safe(text: str) -> str:
    """``text`` with control characters (escape sequences, carriage returns, …) shown as
    ``\\x1b`` style escapes; newlines and tabs are kept."""
    if all(ch.isprintable() or ch in "\n\t" for ch in text):
        return text
    return "".join(ch if ch.isprintable() or ch in "\n\t" else ch.encode("unicode_escape").decode("ascii")
                   for ch in text)


def warn(message: str) -> None:
    print(f"quasicentral: warning: {safe(message)}", file=sys.stderr)


def error(message: str) -> None:
    """One line on stderr (a message of several lines is joined)."""
    print(f"quasicentral: error: {safe(' '.join(message.split(chr(10))))}", file=sys.stderr)


class QuietPipe:
    """``sys.stdout`` while a command runs: once the reader has closed the pipe, the rest of the
    output goes to /dev/null and the command finishes with its own exit code."""

    def __init__(self, stream):
        self._stream = stream
        self.broken = False

    def close_quietly(self) -> None:
        self.broken = True
        try:  # the interpreter flushes the real stdout at exit: point its descriptor at /dev/null
            fd = self._stream.fileno()
            null = os.open(os.devnull, os.O_WRONLY)
            os.dup2(null, fd)
            os.close(null)
        except (OSError, ValueError, AttributeError, io.UnsupportedOperation):
            pass

    def write(self, text: str) -> int:
        if not self.broken:
            try:
                return self._stream.write(text)
            except BrokenPipeError:
                self.close_quietly()
        return len(text)

    def flush(self) -> None:
        if not self.broken:
            try:
                self._stream.flush()
            except BrokenPipeError:
                self.close_quietly()

    def __getattr__(self, name):
        return getattr(self._stream, name)


def show_progress(args=None, stream=None, environ=None) -> bool:
    """Whether to draw a progress bar: stderr is a terminal, ``CI`` is not set (to anything but
    "", "0" or "false") and ``--json`` was not asked for."""
    stream = sys.stderr if stream is None else stream
    environ = os.environ if environ is None else environ
    if args is not None and getattr(args, "json", False):
        return False
    if environ.get("CI", "").strip().lower() not in ("", "0", "false", "no"):
        return False
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError, OSError):
        return False


class ProgressBar:
    """The callback the CLI hands to library functions: draws a tqdm bar on stderr when
    :func:`show_progress` says so, and always keeps the last record (for the timing line)."""

    mininterval = 0.2  # seconds between redraws

    def __init__(self, args, label: str, stream=None, enabled: bool | None = None):
        self.stream = sys.stderr if stream is None else stream
        self.enabled = show_progress(args, self.stream) if enabled is None else enabled
        self.label = label
        self.last = None
        self._bar = None
        self._phase = None

    def __call__(self, rec) -> None:
        self.last = rec
        if not self.enabled:
            return
        from tqdm import tqdm

        if self._bar is None or rec.phase != self._phase:
            self.close()
            self._phase = rec.phase
            size = self._size()
            self._bar = tqdm(total=rec.total, initial=rec.done, desc=self.label, unit=f" {rec.phase or 'items'}",
                             file=self.stream, dynamic_ncols=size is None, ncols=size and size[0],
                             nrows=size and size[1], leave=False, mininterval=self.mininterval,
                             bar_format="{desc}: {n_fmt}/{total_fmt}{unit} {bar} [{elapsed}<{remaining}{postfix}]")
        self._bar.total = rec.total
        if rec.current:
            done = "read from the cache" if rec.current == "cache" else f"last done: {rec.current}"
            self._bar.set_postfix_str(done, refresh=False)
        if rec.done > self._bar.n:
            self._bar.update(rec.done - self._bar.n)
        else:
            self._bar.refresh()

    def _size(self) -> tuple[int, int] | None:
        """None to follow the terminal's size; 80 × 24 when it reports none (a pty without a size)."""
        try:
            size = os.get_terminal_size(self.stream.fileno())
        except (OSError, ValueError, AttributeError, io.UnsupportedOperation):
            return 80, 24
        return None if size.columns > 0 and size.lines > 0 else (80, 24)

    def close(self) -> None:
        if self._bar is not None:
            self._bar.close()
            self._bar = None

    def __enter__(self):
        return self

    def __exit__(self, *exc) -> None:
        self.close()


def entries_text(n: int) -> str:
    return f"{n} entr{'y' if n == 1 else 'ies'}"


def timing(args, text: str) -> None:
    """The line that says what was timed (stderr; not with --json)."""
    if not getattr(args, "json", False):
        print(text, file=sys.stderr)


