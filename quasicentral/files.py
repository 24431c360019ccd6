"""Writing files that users keep: atomically, and never through a symbolic link.

Every file the toolkit writes goes through this module.  A file is written to a fresh temporary
file in its own directory (created with ``O_CREAT | O_EXCL``, so it can neither follow nor reuse
an existing name) and then renamed over the target, so a failure never leaves a half-written
file and a reader never sees one.  A target, or a directory created below an output directory,
that is a symbolic link is refused with :class:`UnsafePath` (an ``OSError``): writing through it
would change a file somewhere else (``DIR/figures -> /etc``).  The output directory the user
names itself may be a link (the user chose it); what the toolkit creates below it may not.
"""

from __future__ import annotations

import errno
import os
import stat
import tempfile
from pathlib import Path
from typing import Callable


class UnsafePath(OSError):
    """A path the toolkit refuses to write through (a symbolic link, or outside the output
    directory)."""

    def __init__(self, path: Path, why: str):
        super().__init__(errno.ELOOP, why, str(path))
        self.path = Path(path)
        self.why = why

    def __str__(self) -> str:
        return f"{self.path}: {self.why}"


def _refuse_link(path: Path) -> None:
    try:
        st = os.lstat(path)
    except FileNotFoundError:
        return
    if stat.S_ISLNK(st.st_mode):
        raise UnsafePath(path, "is a symbolic link; refusing to write through it (remove the link)")


def _refuse_special(path: Path) -> None:
    """A file target must be absent or a regular file: renaming over a device, a pipe or a
    socket (``--junit /dev/null`` as root) would replace it."""
    _refuse_link(path)
    try:
        st = os.lstat(path)
    except FileNotFoundError:
        return
    if not stat.S_ISREG(st.st_mode):
        kind = "a directory" if stat.S_ISDIR(st.st_mode) else "not a regular file"
        raise UnsafePath(path, f"is {kind}; refusing to replace it")


def inside(root: Path, relative: str | Path) -> Path:
    """``root / relative``, refused unless it stays inside ``root`` (no ``..``, not absolute)
    and no existing component below ``root`` is a symbolic link."""
    rel = Path(relative)
    if rel.is_absolute() or ".." in rel.parts:
        raise UnsafePath(rel, f"is not inside {root}")
    path = Path(root)
    for part in rel.parts:
        path = path / part
        _refuse_link(path)
    return path


def ensure_dir(path: Path) -> Path:
    """Create the directory ``path`` (and its parents) unless it exists; refuse when ``path``
    is a symbolic link or exists as something other than a directory."""
    path = Path(path)
    _refuse_link(path)
    path.mkdir(parents=True, exist_ok=True)
    _refuse_link(path)  # lost a race to a link created meanwhile
    return path


def output_dir(path: Path) -> Path:
    """The output directory the user named (``--out DIR``), created if needed.  It may itself be
    a symbolic link to a directory (the user chose it); everything below it is checked."""
    path = Path(path)
    path.mkdir(parents=True, exist_ok=True)
    if not path.is_dir():
        raise NotADirectoryError(errno.ENOTDIR, "not a directory", str(path))
    return path


def write_atomic(path: Path, fill: Callable[[Path], None]) -> None:
    """Let ``fill`` write a unique temporary file beside ``path``, then rename it over ``path``.
    On any failure the temporary file is removed and ``path`` is left as it was.  Refuses a
    ``path`` that is a symbolic link (the rename would replace the link, not its target, but a
    link there means someone expects the target to change: say so instead)."""
    path = Path(path)
    _refuse_special(path)
    fd, name = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    tmp = Path(name)
    try:
        made = os.fstat(fd)
        fill(tmp)
        now = os.lstat(tmp)
        if not stat.S_ISREG(now.st_mode) or (now.st_dev, now.st_ino) != (made.st_dev, made.st_ino):
            raise UnsafePath(tmp, "was replaced while it was written; refusing to rename it into place")
        os.fchmod(fd, 0o644)
        _refuse_link(path)
        os.replace(tmp, path)  # replaces the directory entry: never follows a link
    finally:
        os.close(fd)
        if os.path.lexists(tmp):
            tmp.unlink()


def write_bytes(path: Path, data: bytes) -> None:
    """Write ``data`` to ``path`` atomically, through the temporary file's own descriptor (the
    temporary name is never reopened)."""
    path = Path(path)
    _refuse_special(path)
    fd, name = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    tmp = Path(name)
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
            fh.flush()
            os.fchmod(fh.fileno(), 0o644)
        _refuse_link(path)
        os.replace(tmp, path)
    finally:
        if os.path.lexists(tmp):
            tmp.unlink()


def write_text(path: Path, text: str) -> None:
    write_bytes(path, text.encode("utf-8"))


def check_writable(directory: Path) -> None:
    """Raise ``OSError`` when ``directory`` cannot be created or written to, before anything
    is written: creates and removes a uniquely named probe (``O_EXCL``: an existing file or
    link of that name is never opened)."""
    directory = output_dir(directory)
    fd, name = tempfile.mkstemp(prefix=".quasicentral-write-test.", suffix=".tmp", dir=directory)
    os.close(fd)
    os.unlink(name)


def _private(st: os.stat_result) -> bool:
    """Owned by this user and writable by nobody else."""
    return st.st_uid == os.getuid() and not st.st_mode & (stat.S_IWGRP | stat.S_IWOTH)


def read_private(directory: Path, name: str) -> bytes | None:
    """The bytes of ``directory/name`` where the folder and the file are this user's and nobody
    else may write them, the file is a regular one and neither is a symbolic link; else None.
    What a cache keeps (a pickle runs code when loaded, a figure goes into a report) is read only
    so: a record another user could have planted is never used."""
    try:
        folder = os.open(directory, os.O_RDONLY | os.O_DIRECTORY | os.O_NOFOLLOW)
    except OSError:
        return None
    try:
        if not _private(os.fstat(folder)):
            return None
        fd = os.open(name, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK, dir_fd=folder)
    except OSError:
        return None
    finally:
        os.close(folder)
    with os.fdopen(fd, "rb") as fh:
        st = os.fstat(fh.fileno())
        if not (stat.S_ISREG(st.st_mode) and _private(st)):
            return None
        try:
            return fh.read()
        except OSError:
            return None
