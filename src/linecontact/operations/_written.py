"""The Python lines of a computation, written from the library calls it makes.

An operation's computation calls the library through :func:`made`: the call is made and
written down, on the call's :class:`~linecontact.operations.Inputs`, as the line a user
would type (``cyl = lc.Cylinder.from_materials(5e-08, ...)``, ``result = cyl.pull_off()``).
:func:`python` joins them into a script: what the calculator's pages show under "the same
elsewhere", so that the lines are those that computed the page's numbers, never a second
spelling of them.

Only the SI layer's calls are written (the pages' inputs are SI): a computation on the
nondimensional groups writes nothing.
"""

from __future__ import annotations

import dataclasses
import inspect
import math
import sys
from collections.abc import Callable
from typing import Any

import numpy as np

__all__ = ["made", "note", "python"]


def made(args: Any, name: str, call: Callable[..., Any], *pos: Any, **kw: Any) -> Any:
    """``call(*pos, **kw)``, written down on ``args`` as ``name = <the call>`` once made.

    Parameters
    ----------
    args : Inputs
        The operation's call: its ``python`` list takes the line.
    name : str
        The variable the line assigns (``"cyl"`` for the body, ``"result"``).
    call : callable
        A bound method of a value an earlier line named (``cyl.pull_off``), or a function
        or class method of the library (``Cylinder.from_materials``).
    *pos, **kw
        Its arguments, as the call takes them; a keyword at its default is not written.
    """
    owner = getattr(call, "__self__", None)
    on = ""
    if owner is not None and not isinstance(owner, type):  # a method of a value made before
        on = next((c.name for c in reversed(args.python) if c.made is owner), "cyl")
    result = call(*pos, **kw)
    args.python.append(_Call(name, call, pos, kw, on=on, made=result))  # written when asked
    return result


def note(args: Any, comment: str) -> None:
    """A comment at the end of the last line written on ``args`` (``# the presets' ...``)."""
    args.python[-1] = dataclasses.replace(args.python[-1], comment=comment)


def python(args: Any) -> str:
    """The script of the lines written on ``args``: empty where none was."""
    calls = list(getattr(args, "python", []))
    if not calls:
        return ""
    return "\n".join(["import linecontact as lc", *map(str, calls), "print(result)"])


@dataclasses.dataclass(frozen=True)
class _Call:
    """A call made: the variable it assigns, the callable, its arguments and a comment."""

    name: str
    call: Callable[..., Any]
    pos: tuple[Any, ...]
    kw: dict[str, Any]
    on: str = ""  # the variable whose method it is ("" for a function or a class's)
    made: Any = dataclasses.field(default=None, repr=False, compare=False)
    comment: str = ""

    def __str__(self) -> str:
        callee = f"{self.on}.{self.call.__name__}" if self.on else _callee(self.call)
        line = f"{self.name} = {callee}({_arguments(self.call, self.pos, self.kw)})"
        return f"{line}  # {self.comment}" if self.comment else line


def _callee(call: Callable[..., Any]) -> str:
    """A function's or a class method's name from the package (``lc.Cylinder.from_modulus``)."""
    owner = getattr(call, "__self__", None)
    return _name(owner if owner is not None else call) + (
        f".{call.__name__}" if owner is not None else ""
    )


def _name(obj: Any) -> str:
    """``lc.X`` for a public name of the package, else ``lc.module.X``."""
    # the package itself (always loaded under its subpackages): read, not imported, as
    # nothing below the front door imports it
    package = sys.modules[__name__.partition(".")[0]]
    name = obj.__qualname__
    if getattr(package, name, None) is obj:
        return f"lc.{name}"
    module = obj.__module__.removeprefix("linecontact.")
    return f"lc.{module}.{name}"


def _arguments(call: Callable[..., Any], pos: tuple[Any, ...], kw: dict[str, Any]) -> str:
    try:
        params = inspect.signature(call).parameters
    except (TypeError, ValueError):  # pragma: no cover - every call written has one
        params = {}  # type: ignore[assignment]
    shown = {
        k: v
        for k, v in kw.items()
        if k not in params
        or params[k].default is inspect.Parameter.empty
        or not _same(v, params[k].default)
    }
    words = [_value(v) for v in pos] + [f"{k}={_value(v)}" for k, v in shown.items()]
    return ", ".join(words)


def _same(value: Any, default: Any) -> bool:
    if value is None or default is None:
        return value is default
    if isinstance(value, np.ndarray) or isinstance(default, np.ndarray):
        return False
    try:
        return bool(value == default) and type(value) is type(default)
    except (TypeError, ValueError):  # pragma: no cover - a value that compares oddly
        return False


def _value(v: Any) -> str:
    """``v`` as Python source that gives it back exactly."""
    if v is None or isinstance(v, bool | str):
        return repr(v)
    if isinstance(v, np.ndarray):
        return _value(v.tolist())
    if isinstance(v, np.generic):
        return _value(v.item())
    if isinstance(v, float):
        return _float(v) if math.isfinite(v) else f"float({str(v)!r})"
    if isinstance(v, int):
        return repr(v)
    if isinstance(v, list | tuple):
        inner = ", ".join(_value(x) for x in v)
        return f"[{inner}]" if isinstance(v, list) else f"({inner}{',' if len(v) == 1 else ''})"
    if isinstance(v, type):
        return _name(v)
    if dataclasses.is_dataclass(v):
        fields = ", ".join(
            f"{f.name}={_value(getattr(v, f.name))}" for f in dataclasses.fields(v) if f.init
        )
        return f"{_name(type(v))}({fields})"
    raise TypeError(f"no Python line for a value of type {type(v).__name__}")


def _float(x: float) -> str:
    """The shortest text that gives ``x`` back, as a person writes it (``5e-8``, ``1.24e11``)."""
    plain = repr(x)
    if "e" not in plain and len(plain) <= 8:  # 0.36, 100.0, 123456.0
        return plain
    for digits in range(1, 18):
        text = f"{x:.{digits}g}"
        if float(text) == x:
            break
    mantissa, _, exponent = text.partition("e")
    text = f"{mantissa}e{int(exponent)}" if exponent else text
    if "e" not in text and "." not in text:
        text += ".0"
    return min(text, plain, key=len)
