"""What makes a number: the code that computed it, named by a digest.

A stored result that is reused later (a sweep's blocks, the adhesion map's rows) is reused
only by the same code: the digest covers the text of every module of the package (so an
edited kernel, a patched checkout or another build of the same version all differ), the
version, and the versions of Python, NumPy and SciPy that the numbers go through.
"""

from __future__ import annotations

import functools
import hashlib
import pathlib
import platform

__all__ = ["code_digest", "code_identity"]


@functools.lru_cache(maxsize=1)
def code_identity() -> dict[str, str]:
    """The version, the digest of the package's modules and the numerical stack's versions.

    Returns
    -------
    dict of str to str
        ``version``, ``code`` (SHA-256 of the package's ``*.py`` files, each with its path),
        ``python``, ``numpy``, ``scipy``.
    """
    import numpy
    import scipy

    from ._version import __version__

    root = pathlib.Path(__file__).resolve().parent
    h = hashlib.sha256()
    for f in sorted(root.rglob("*.py")):
        h.update(f.relative_to(root).as_posix().encode() + b"\0")
        try:
            h.update(f.read_bytes())
        except OSError:
            h.update(b"?")
        h.update(b"\0")
    return {
        "version": __version__,
        "code": h.hexdigest(),
        "python": platform.python_version(),
        "numpy": numpy.__version__,
        "scipy": scipy.__version__,
    }


def code_digest() -> str:
    """One digest of :func:`code_identity` (a key part for stored results)."""
    ident = code_identity()
    text = "\0".join(f"{k}={ident[k]}" for k in sorted(ident))
    return hashlib.sha256(text.encode()).hexdigest()
