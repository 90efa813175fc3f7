"""The subcommands of the operations, built from their declarations (:mod:`linecontact.operations`).

Each declared parameter becomes one option (its flag, its kind and count, its choices,
default and help, its section); its old spellings deprecated aliases; the declared entries
one help entry each. A run reads the parsed values into the operation's
:class:`~linecontact.operations.Inputs`, computes, and writes the records as asked.
"""

from __future__ import annotations

import argparse
import importlib
import sys
from collections.abc import Callable, Iterator, Mapping
from typing import Any

from ..operations import Inputs, Operation
from ..operations import get as _get
from ._options import (
    add_command,
    add_output_options,
    deprecated_alias,
    emit,
    finish,
    show_together,
    write_failure,
)

__all__ = ["add", "inputs_of", "register", "run"]

_TYPES = {"number": float, "integer": int, "text": None}
_NARGS = {"one": None, "several": "+", "triple": 3}


def register(sub: Any, name: str) -> None:
    """Add the subcommand of the operation ``name`` to the subparsers ``sub``."""
    add(sub, _get(name), run)


def add(sub: Any, op: Operation, func: Callable[[argparse.Namespace], int]) -> None:
    """Add the subcommand of ``op`` to the subparsers ``sub``, run by ``func``."""
    p = add_command(sub, op.name, op.summary, op.description, op.examples)
    sections: dict[str, Any] = {}
    for q in op.parameters:
        if q.group and q.group not in sections:
            sections[q.group] = p.add_argument_group(q.group)
        g = sections[q.group] if q.group else p
        if q.positional:
            p.usage = f"%(prog)s [options] [{q.metavar} ...]"
            g.add_argument(q.name, nargs="*", metavar=q.metavar, help=q.help)
            continue
        kw: dict[str, Any] = {"dest": q.name, "help": q.help}
        if q.kind == "switch":
            kw.update(action="store_true", default=q.default)
        else:
            kw.update(type=_TYPES[q.kind], nargs=_NARGS[q.many], default=q.default)
            if q.metavar is not None:
                kw["metavar"] = q.metavar
            if q.choices is not None:
                kw["choices"] = q.choices
        g.add_argument(q.option, **kw)
        for old in q.aliases:
            deprecated_alias(p, old, q.option, g)
    for e in op.entries:
        show_together(p, *(op.parameter(n).option for n in e.names), help=e.help)
    add_output_options(p, image_alias=op.image_formats)
    if op.format_help:
        p._option_string_actions["--format"].help = op.format_help
    p.set_defaults(func=func)


class _Flags(Mapping[str, str]):
    """The flags of the library's names of parameters in a call (``said_as``), kept live."""

    def __init__(self, op: Operation, said_as: dict[str, str]) -> None:
        self._op, self._said = op, said_as

    def __getitem__(self, key: str) -> str:
        said = self._said[key]  # a parameter's name, or words of flags ("--a / --b")
        return said if said.startswith("--") else self._op.parameter(said).option

    def __iter__(self) -> Iterator[str]:
        return iter(self._said)

    def __len__(self) -> int:
        return len(self._said)


def _draw(op: Operation, inputs: Inputs) -> None:
    """The figure the computation left (``inputs.drawing``) into ``--plot FILE``."""
    drawing = getattr(inputs, "drawing", None)
    path = getattr(inputs, "plot", None)
    if not (op.figures and drawing and path):
        return
    name, positional, keywords = drawing
    module = importlib.import_module(f"linecontact.figures.{op.figures}")
    try:
        getattr(module, name)(*positional, path, **keywords)
    except OSError as exc:
        raise write_failure(f"--plot {path!r}", exc) from None


def inputs_of(args: argparse.Namespace, op: Operation) -> Inputs:
    """The typed values of the parsed ``args`` of ``op``'s subcommand.

    The library's names of parameters are said as their flags in its messages (as the
    computation names them, while it runs: a warning is said when it is raised).
    """
    words = args.argv if args.argv is not None else sys.argv[1:]
    values = {q.name: getattr(args, q.name, q.default) for q in op.parameters}
    inputs = Inputs(op, values, words=words)
    args._api_flags = _Flags(op, inputs.said_as)
    return inputs


def run(args: argparse.Namespace) -> int:
    """Compute the operation ``args.command`` with the parsed values; write its records."""
    op = _get(args.command)
    inputs = inputs_of(args, op)
    table = op.run(inputs)
    _draw(op, inputs)  # before the records are written, as a failed figure is an error
    emit(args, table, checked=True)
    return finish(table, op.good) if op.good else 0
