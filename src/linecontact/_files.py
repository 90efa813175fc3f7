"""Writing files: only where a regular file belongs, whole or not at all, with the umask's mode.

Every file linecontact writes (a table's ``-o``, a figure, a sweep's blocks and its netCDF
store, the adhesion map's resume rows) goes through :func:`atomic_file`:

- the path is checked first (:func:`regular_target`): a FIFO, a character or block device, a
  socket or a directory at the path is refused with an error naming it, never replaced; a
  symbolic link is written through (the file it points to is replaced, the link stays), so
  ``-o /dev/null`` or a link to a device is refused rather than turned into a regular file;
- the data go to a temporary file in the same directory, renamed over the path only once
  complete; on any failure the temporary file is removed and the path is left as it was;
- the file gets the permissions a plain ``open(path, "w")`` would give it: ``0666`` less
  the umask for a new file, the mode of the regular file it replaces
  (:func:`new_file_mode`).
"""

from __future__ import annotations

import contextlib
import os
import stat
import tempfile
from collections.abc import Iterator
from typing import IO, Any

__all__ = ["atomic_file", "file_kind", "new_file_mode", "regular_target", "umask"]


def umask() -> int:
    """The process's umask, read without changing it where the system says it (Linux)."""
    try:
        with open("/proc/self/status", encoding="ascii") as fh:
            for line in fh:
                if line.startswith("Umask:"):
                    return int(line.split()[1], 8)
    except (OSError, ValueError, IndexError):
        pass
    mask = os.umask(0o022)  # elsewhere: set and restore (not thread-safe, but brief)
    os.umask(mask)
    return mask


def new_file_mode(target: str | os.PathLike[str]) -> int:
    """The permission bits an atomically written ``target`` gets: those of a plain ``open``.

    A temporary file from :func:`tempfile.mkstemp` is ``0600`` whatever the umask; before it
    is renamed over ``target`` it gets the mode a file created with ``open(target, "w")``
    would have: ``0666`` less the umask for a new file (``0644`` under umask ``022``), the
    mode of the file replaced for an existing regular file.
    """
    try:
        st = os.stat(target)
    except OSError:
        st = None
    if st is not None and stat.S_ISREG(st.st_mode):
        return stat.S_IMODE(st.st_mode)
    return 0o666 & ~umask()


def file_kind(mode: int) -> str:
    """What a file of ``st_mode`` ``mode`` is, in words (``"a FIFO (named pipe)"``)."""
    for test, words in (
        (stat.S_ISREG, "a regular file"),
        (stat.S_ISDIR, "a directory"),
        (stat.S_ISFIFO, "a FIFO (named pipe)"),
        (stat.S_ISCHR, "a character device"),
        (stat.S_ISBLK, "a block device"),
        (stat.S_ISSOCK, "a socket"),
    ):
        if test(mode):
            return words
    return "not a regular file"


def regular_target(path: str | os.PathLike[str], name: str = "the output") -> str:
    """The path to replace when writing ``path``: a regular file or a new name.

    A symbolic link is followed (written through: the file it points to is replaced, the link
    stays). Anything that is not a regular file -- a directory, a FIFO, a device, a socket --
    is refused.

    Parameters
    ----------
    path : str or path-like
        Where the caller asked to write.
    name : str
        How the caller names the path in messages (``"-o/--output"``, ``"output"``).

    Returns
    -------
    str
        The path to replace (``path`` itself, or the end of its chain of links).

    Raises
    ------
    ValueError
        If ``path`` (or what its link points to) exists and is not a regular file.
    """
    given = os.fspath(path)
    real = os.path.realpath(given) if os.path.islink(given) else given
    try:
        st = os.stat(real)
    except FileNotFoundError:
        return real
    except OSError:
        return real  # no permission to look: opening the temporary file will say so
    if not stat.S_ISREG(st.st_mode):
        through = f" (a link to {real!r})" if real != given else ""
        raise ValueError(
            f"{name} {given!r}{through} is {file_kind(st.st_mode)}, not a regular file: "
            "linecontact writes only regular files and never replaces anything else (give "
            "the path of a file)"
        )
    return real


@contextlib.contextmanager
def atomic_file(
    path: str | os.PathLike[str],
    mode: str = "wb",
    *,
    name: str = "the output",
    durable: bool = True,
    **open_kwargs: Any,
) -> Iterator[IO[Any]]:
    """A file object for ``path`` whose contents appear there only once complete.

    Parameters
    ----------
    path : str or path-like
        The file to write (checked by :func:`regular_target`).
    mode : str
        ``"wb"`` or ``"w"``.
    name : str
        How the caller names the path in messages.
    durable : bool
        Flush the file to the disk before it is renamed (``fsync``), so that a power failure
        leaves the old file or the whole new one. ``False`` where the reader checks the file
        whole anyway (a sweep's kept blocks: a torn one is computed again).
    **open_kwargs
        Passed to :func:`os.fdopen` (``encoding``, ``newline``).

    Yields
    ------
    file object
        Writing to a temporary file beside ``path``, renamed over it when the block ends.

    Raises
    ------
    ValueError
        If ``path`` is not a regular file (or a new name).
    OSError
        If the file cannot be written (its ``filename`` the path); the temporary file is
        removed.
    """
    target = regular_target(path, name)
    directory = os.path.dirname(os.path.abspath(target))
    base = os.path.basename(target)
    fd, tmp = tempfile.mkstemp(prefix=f".{base}.", suffix=".part", dir=directory)
    try:
        with os.fdopen(fd, mode, **open_kwargs) as fh:
            yield fh
            fh.flush()
            if durable:
                os.fsync(fh.fileno())
        os.chmod(tmp, new_file_mode(target))  # mkstemp made it 0600
        os.replace(tmp, target)
    except BaseException as exc:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        if isinstance(exc, OSError) and exc.filename is None and exc.errno is not None:
            # a failed write (a full disk) says which file it was writing
            raise OSError(exc.errno, exc.strerror, target) from exc
        raise
