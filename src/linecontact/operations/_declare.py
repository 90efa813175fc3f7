"""What an operation is: its parameters, declared once, and one call with typed values.

A :class:`Parameter` says everything every shell needs of one input: its name (the Python
keyword; the flag ``--name`` with ``-`` for ``_``, the HTTP field, the sweep's dimension and
the page's query key), its kind and how many values it takes, its SI unit, its choices and
default, a line of help, the help section it stands in and its old spellings (aliases,
resolved at the door). An :class:`Operation` is a name, a title, its parameters and the
function that computes it from :class:`Inputs` (the typed values of one call) into a
:class:`~linecontact.output.Table`, the records every shell writes.

No shell parses another one's text: the command line builds its parser from the
declarations, the HTTP API and the sweeps call :func:`call` with typed values.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any, Literal

from ..errors import ParameterError
from ..output import Table
from ._widths import check_widths

__all__ = ["Entry", "Inputs", "Operation", "Parameter", "call", "command_words"]

Kind = Literal["number", "integer", "text", "switch"]
Many = Literal["one", "several", "triple"]


@dataclass(frozen=True)
class Parameter:
    """One input of an operation, declared once for every shell.

    Attributes
    ----------
    name : str
        The Python keyword (and the HTTP field, the sweep's dimension, the page's key).
    help : str
        One line of help.
    kind : {"number", "integer", "text", "switch"}
        A float, an integer, a word, or a switch (given or not).
    many : {"one", "several", "triple"}
        One value, one or more, or exactly three (a range ``START STOP NUM``).
    unit : str
        The SI unit of a value (``"m"``, ``"Pa"``, ``"N/m"``, ``"J/m^2"``); empty for a
        nondimensional group or a word.
    metavar : str or tuple of str, optional
        The value's name in the help.
    choices : tuple of str, optional
        The words a ``text`` parameter takes.
    default : object, optional
        The value when not given (None: not given).
    flag : str, optional
        The command line's spelling, where it is not ``--`` and the name with ``-`` for
        ``_`` (``--half-width`` for ``a``).
    aliases : tuple of str
        Old spellings of the flag: accepted, with a note that names the new one.
    group : str
        The title of the help section it stands in (empty: the options).
    shell_only : bool
        A command-line input that is no computation's (a file to plot into): never an
        HTTP field or a sweep's dimension.
    positional : bool
        Given on the command line without its flag (``materials ZnO SiO2``); a text
        parameter of several values, none given by default.
    """

    name: str
    help: str
    kind: Kind = "number"
    many: Many = "one"
    unit: str = ""
    metavar: str | tuple[str, ...] | None = None
    choices: tuple[str, ...] | None = None
    default: Any = None
    flag: str = ""
    aliases: tuple[str, ...] = ()
    group: str = ""
    shell_only: bool = False
    positional: bool = False

    @property
    def option(self) -> str:
        """The command line's flag."""
        return self.flag or "--" + self.name.replace("_", "-")

    @property
    def key(self) -> str:
        """The HTTP field and the page's key: the flag without its dashes, ``_`` for ``-``."""
        return self.option[2:].replace("-", "_")

    def convert(self, value: Any, key: str) -> Any:
        """``value`` (a number, a word, a list of them) as this parameter takes it.

        Raises :class:`~linecontact.errors.ParameterError` naming ``key`` (the caller's
        spelling) for a value of the wrong kind or count.
        """
        if self.kind == "switch":
            if isinstance(value, bool):
                return value
            word = str(value).strip().lower()
            if word in ("", "1", "true", "yes", "on"):
                return True
            if word in ("0", "false", "no", "off"):
                return False
            raise ParameterError(key, f"{key} is a switch: true or false, got {value!r}")
        values = list(value) if _is_list(value) else [value]
        if not values:
            raise ParameterError(key, f"{key} needs a value")
        out = [self._one(v, key) for v in values]
        if self.many == "one":
            if len(out) != 1:
                raise ParameterError(key, f"{key} takes one value, got {len(out)}")
            return out[0]
        if self.many == "triple" and len(out) != 3:
            raise ParameterError(key, f"{key} takes three values (START STOP NUM), got {len(out)}")
        return out

    def refusal(self, values: Sequence[Any], said: str) -> str:
        """Why ``values`` (text) are refused, as the command line says it.

        ``argument --radius: invalid float value: 'abc'`` (or an invalid choice); ``said``,
        the message of :meth:`convert`, where neither applies.
        """
        if not values and self.kind != "switch":
            count = {"one": "one argument", "several": "at least one argument"}
            return f"argument {self.option}: expected {count.get(self.many, '3 arguments')}"
        if self.choices is not None:
            bad = next((v for v in values if v not in self.choices), values[0])
            choices = ", ".join(repr(c) for c in self.choices)
            return f"argument {self.option}: invalid choice: {bad!r} (choose from {choices})"
        kind = {"number": float, "integer": int}.get(self.kind)
        if kind is None:
            return said
        for v in values:
            try:
                kind(v)
            except (TypeError, ValueError):
                return f"argument {self.option}: invalid {kind.__name__} value: {v!r}"
        return said

    def _one(self, v: Any, key: str) -> Any:
        if self.kind == "text":
            if not isinstance(v, str):
                raise ParameterError(key, f"{key} takes a word, got {v!r}")
            if self.choices is not None and v not in self.choices:
                raise ParameterError(
                    key, f"{key}: invalid choice {v!r} (choose from {', '.join(self.choices)})"
                )
            return v
        if isinstance(v, bool):
            raise ParameterError(key, f"{key} takes a number, got {v!r}")
        try:
            x = float(v) if self.kind == "number" else _integer(v)
        except (TypeError, ValueError):
            what = "a number" if self.kind == "number" else "an integer"
            raise ParameterError(key, f"{key} takes {what}, got {v!r}") from None
        return x


def _is_list(value: Any) -> bool:
    return isinstance(value, list | tuple) or (
        hasattr(value, "__len__") and hasattr(value, "dtype") and getattr(value, "ndim", 0) > 0
    )


def _integer(v: Any) -> int:
    if isinstance(v, str):
        return int(v.strip())
    x = float(v)
    if not (math.isfinite(x) and x.is_integer()):
        raise ValueError(v)
    return int(x)


@dataclass(frozen=True)
class Entry:
    """Parameters shown as one entry of the command line's help (so that it fits a screen)."""

    names: tuple[str, ...]
    help: str


@dataclass(frozen=True)
class Operation:
    """A computation every shell offers: its parameters, declared once, and its function.

    Attributes
    ----------
    name : str
        The subcommand, the API's path, the sweep's command.
    summary : str
        One line (``linecontact --help``).
    description : str
        A short paragraph (the subcommand's help).
    examples : tuple of str
        Two or three command lines.
    parameters : tuple of Parameter
        In the order of the help.
    compute : callable
        ``compute(inputs) -> Table``.
    good : tuple of str
        The states of a computed point (a run none of whose points has one fails); empty:
        every record is computed.
    entries : tuple of Entry
        Parameters shown together in the help.
    api_names : dict
        The names the library's messages give some parameters, where they are not the
        parameter's own (``max_load`` for ``F_max``): each shell says its own spelling.
    rows : tuple of str
        The parameters of several values that give one record each, in one call (``load``
        of ``normal``): a sweep hands them a row of points at once. A parameter of several
        values not listed makes one record of all of them (a fit's radii).
    figures : str
        The module of :mod:`linecontact.figures` whose function draws the computation's
        figure where a shell has a file for it: the computation leaves
        ``inputs.drawing = (function name, arguments, keywords)``, the file comes last.
    format_help : str
        The help of the command line's ``--format``, where the records differ by format
        (the map's summary per ``mu`` in the readable table: the computation leaves it as
        ``inputs.readable``).
    image_formats : bool
        The command line's ``--format`` also takes, deprecated, the image formats (of a
        command that draws files, which took them before it took data formats).
    """

    name: str
    summary: str
    description: str
    examples: tuple[str, ...]
    parameters: tuple[Parameter, ...]
    compute: Callable[[Inputs], Table]
    good: tuple[str, ...] = ()
    entries: tuple[Entry, ...] = ()
    api_names: Mapping[str, str] = field(default_factory=dict)
    rows: tuple[str, ...] = ()
    figures: str = ""
    format_help: str = ""
    image_formats: bool = False
    _by_key: dict[str, Parameter] = field(default_factory=dict, repr=False, compare=False)

    def __post_init__(self) -> None:
        names = [p.name for p in self.parameters]
        if len(set(names)) != len(names):
            raise ValueError(f"{self.name}: a parameter declared twice in {names}")
        for name in self.rows:
            if name not in names:
                raise ValueError(f"{self.name}: rows names {name!r}, no parameter of it")
        for p in self.parameters:
            self._by_key[p.key] = p
            self._by_key.setdefault(p.name, p)
            for a in p.aliases:
                self._by_key.setdefault(a[2:].replace("-", "_"), p)

    def run(self, inputs: Inputs) -> Table:
        """The records of ``inputs``; SI contact half-widths that are no width warned about."""
        table = self.compute(inputs)
        check_widths(table)
        return table

    def parameter(self, key: str) -> Parameter:
        """The parameter a keyword, a field or an old spelling names (ParameterError: none)."""
        p = self._by_key.get(key)
        if p is None:
            raise ParameterError(
                key,
                f"{key!r} is not a parameter of {self.name} (its parameters: "
                f"{', '.join(q.key for q in self.parameters if not q.shell_only)})",
            )
        return p


class Inputs:
    """The typed values of one call of an operation: every parameter, given or its default.

    Read as attributes (``inputs.radius``). ``command`` is the operation's name; ``words``
    the command line that asked for it (the provenance's ``command``), as typed where the
    command line asked, or written from the values where another shell did; ``said_as``
    maps the names the library's messages use to the parameters they stand for (the
    operation's ``api_names``; a computation may add its own before it calls the library).
    """

    def __init__(
        self,
        operation: Operation,
        values: Mapping[str, Any],
        words: Sequence[str] | None = None,
        flags: Mapping[str, str] | None = None,
    ) -> None:
        # every parameter, given or its default (and a value a computation derives: kept)
        self.__dict__["_values"] = {
            **{p.name: p.default for p in operation.parameters},
            **values,
        }
        self.__dict__["command"] = operation.name
        self.__dict__["operation"] = operation
        #: the library calls the computation made, as Python lines (:mod:`._written`)
        self.__dict__["python"] = []
        #: the names the library's messages give parameters in this call, where the call
        #: chose them (``work_of_adhesion`` meaning the receding one): each shell says its
        #: spelling (compute adds to it); a value is a parameter's name, or words of flags
        #: (``"--pull-off-force-total / --length"``) said as they are
        self.__dict__["said_as"] = dict(operation.api_names)
        self.__dict__["words"] = (
            list(words) if words is not None else command_words(operation, values, flags)
        )

    def __getattr__(self, name: str) -> Any:
        try:
            return self.__dict__["_values"][name]
        except KeyError:
            raise AttributeError(name) from None

    def get(self, name: str, default: Any = None) -> Any:
        """The value ``name`` (a parameter, or a value a shell or the computation set)."""
        return self.__dict__["_values"].get(name, default)

    def __setattr__(self, name: str, value: Any) -> None:
        # a value the computation fills in or derives (a default, the advancing work of
        # adhesion of a pair): this call's own, never the caller's
        self.__dict__["_values"][name] = value

    def replace(self, words: Sequence[str] | None = None, **values: Any) -> Inputs:
        """A copy with ``values`` (parameters by name) in place of its own (and ``words``)."""
        new = Inputs(
            self.operation,
            {**self.__dict__["_values"], **values},
            words=self.words if words is None else words,
        )
        new.said_as.update(self.said_as)
        return new

    def command_line(self) -> list[str]:
        """The command line, ``linecontact`` first (the provenance's ``command``)."""
        return ["linecontact", *self.words]


def command_words(
    operation: Operation, values: Mapping[str, Any], flags: Mapping[str, str] | None = None
) -> list[str]:
    """The command line of ``values`` (declaration order; a switch by its flag alone)."""
    out = [operation.name]
    for p in operation.parameters:
        v = values.get(p.name)
        if v is None or p.shell_only:
            continue
        flag = (flags or {}).get(p.name, p.option)
        if p.positional:
            out += [_text(x) for x in v]
            continue
        if p.kind == "switch":
            if v:
                out.append(flag)
            continue
        out += [flag, *(_text(x) for x in (v if isinstance(v, list | tuple) else [v]))]
    return out


def _text(v: Any) -> str:
    return v if isinstance(v, str) else repr(float(v)) if isinstance(v, float) else str(v)


def call(operation: Operation, values: Mapping[str, Any] | Iterable[tuple[str, Any]]) -> Table:
    """Run ``operation`` on ``values`` (keywords, fields or old spellings; numbers or text).

    Every key must name a parameter, every value be of its kind and count: else
    :class:`~linecontact.errors.ParameterError` naming the key as given.
    """
    items = values.items() if isinstance(values, Mapping) else values
    typed: dict[str, Any] = {}
    for key, value in items:
        p = operation.parameter(key)
        if p.shell_only:
            raise ParameterError(key, f"{key!r} is an input of the command line only")
        if p.name in typed:
            raise ParameterError(key, f"{key} is given twice")
        typed[p.name] = p.convert(value, key)
    return operation.run(Inputs(operation, typed))
