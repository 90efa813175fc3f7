"""The operations' messages in the user's words: flags for the API's names, real causes.

:func:`flag_message` turns the API's parameter names in a message into the flags the user
typed (the command line's spelling; :func:`spell` for a call made with typed values, by the
HTTP API or a sweep), leaving every quoted value and every value typed as it was;
:func:`write_failure`
names the real cause of a failed write (a full disk, a quota); :func:`is_units_warning` and
:func:`coupling_effect` sort and complete the warnings the command line prints.
"""

from __future__ import annotations

import argparse
import errno
import re
import sys
from collections.abc import Sequence
from typing import Any

from ..errors import ModelValidityWarning, UnitsWarning

#: Values that are numbers even though they start with "-": argparse (before Python 3.13)
#: knows only -5 and -0.5, so "--load -1e-3" failed with "expected one argument".
_NEGATIVE_NUMBER = re.compile(
    r"^-(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$|^-(inf|infinity|nan)$", re.IGNORECASE
)

__all__ = [
    "API_FLAGS",
    "COUPLING_EFFECT",
    "coupling_effect",
    "flag_message",
    "is_units_warning",
    "spell",
    "write_failure",
]

#: API parameter names whose flag is not the parameter name with dashes.
API_FLAGS = {
    "radius": "--radius",
    "modulus": "--modulus",
    "cohesive_stress": "--sigma0",
    "adhesion_range": "--h",
    "work_of_adhesion": "--work-of-adhesion",
    "equilibrium_spacing": "--z0",
    "contact_half_width": "--half-width",
    "load": "--load",
    "normal_load": "--load",
    "friction_stress": "--tau0",
    "friction_coefficient": "--mu",
    "tangential_load": "--tangential-load",
    "amplitude": "--tangential-amplitude",
    "max_half_width": "--a-max",
    "receding_range": "--h1",
    "receding_work_of_adhesion": "--work-of-adhesion-receding",
    "half_width": "--half-width",
}


def is_units_warning(message: Warning | str, category: type[Warning]) -> bool:
    """Whether a warning asks about units (never silenced by ``--quiet``).

    :class:`~linecontact.errors.UnitsWarning`, or a
    :class:`~linecontact.errors.ModelValidityWarning` that says "linecontact takes SI units"
    (raised before that class existed). The other warnings are model notes (the coupling,
    the small-strain range), which ``--quiet`` silences.
    """
    if issubclass(category, UnitsWarning):
        return True
    return issubclass(category, ModelValidityWarning) and "takes SI units" in str(message)


#: What the coupling warning adds, once: the effect of beta, its sign and order, no number.
COUPLING_EFFECT = (
    "; its effect on the results is not computed. Without friction at the interface the "
    "coupling does not change the normal contact (no shear tractions to couple; Johnson "
    "1985, Contact Mechanics, sec. 5.4); where the interface holds shear (friction, stick, "
    "adhesion) it brings shear tractions that change the contact a little. Exchanging the "
    "bodies changes the sign of beta and not the contact, so the change of the width is even "
    "in beta (of order beta^2) and grows with |beta| (at most 0.5); no figure for it is given"
)


def coupling_effect(text: str) -> str:
    """What the coupling warning ``text`` adds (once per run): :data:`COUPLING_EFFECT`."""
    return "" if COUPLING_EFFECT in text else COUPLING_EFFECT


def write_failure(what: str, exc: OSError) -> ValueError:
    """The error for a failed write to ``what`` (a flag and its file): its real cause.

    A full disk is ``no space left on the device writing -o/--output 'x.csv'``, a quota
    ``disk quota exceeded writing ...``; any other failure ``cannot write ...: <reason>``.
    """
    if exc.errno == errno.ENOSPC:
        return ValueError(f"no space left on the device writing {what}")
    if exc.errno == getattr(errno, "EDQUOT", None):
        return ValueError(f"disk quota exceeded writing {what}")
    return ValueError(f"cannot write {what}: {exc.strerror or exc}")


#: A quoted value in a message (a Python ``repr`` of a string: a path, a column, a choice):
#: never rewritten by :func:`flag_message`. An apostrophe inside a word (cylinder's) opens
#: no quote.
_QUOTED = re.compile(r"""(?<!\w)'[^'\n]*'(?!\w)|(?<!\w)"[^"\n]*"(?!\w)""")


def _typed_values(argv: Sequence[str]) -> list[str]:
    """The values on the command line ``argv`` (no flag, no subcommand), longest first."""
    values = []
    for i, word in enumerate(argv):
        if word.startswith("-") and not _NEGATIVE_NUMBER.match(word):
            if "=" in word:
                values.append(word.split("=", 1)[1])
        elif i > 0:  # argv[0] is the subcommand
            values.append(word)
    return sorted({v for v in values if v}, key=len, reverse=True)


def _protected(message: str, values: Sequence[str]) -> list[tuple[str, bool]]:
    """``message`` cut into ``(text, protected)`` pieces, in order.

    Protected: every quoted value (:data:`_QUOTED`) and every value the user typed
    (``values``, where it stands as a whole word: a path, a preset's name), which must
    come out verbatim; the rest is the message's own words.
    """
    spans = [m.span() for m in _QUOTED.finditer(message)]
    for v in values:
        for m in re.finditer(rf"(?<![\w-]){re.escape(v)}(?![\w-])", message):
            spans.append(m.span())
    pieces: list[tuple[str, bool]] = []
    at = 0
    for lo, hi in sorted(spans):
        if lo < at:  # inside (or overlapping) a span already kept
            if hi > at:
                pieces.append((message[at:hi], True))
                at = hi
            continue
        pieces += [(message[at:lo], False), (message[lo:hi], True)]
        at = hi
    pieces.append((message[at:], False))
    return [(text, keep) for text, keep in pieces if text]


def flag_message(message: str, args: argparse.Namespace) -> str:
    """``message`` with the API's parameter names replaced by the flags of the command line.

    A name is replaced by the flag the user typed for it; a parameter name (one with an
    underscore) whose flag was not typed by its flag where the subcommand has one (its
    default was used), or by what the command said it stands for (``args._api_flags``).
    Only the message's own words are rewritten: a quoted value and any value the user
    typed (a path such as ``z0/data.csv``, a preset's name) come out verbatim
    (:func:`_protected`).

    Parameters
    ----------
    message : str
        The API's message (an error's, a warning's).
    args : argparse.Namespace
        The run's arguments: ``argv``, and ``_flags``, ``_choice_flags`` of
        :func:`record_flags` (``_api_flags``, ``_typed_as`` where the command set them).

    Returns
    -------
    str
        The message in the words of the command line.
    """
    argv = list(args.argv if args.argv is not None else sys.argv[1:])
    given = {t.split("=", 1)[0] for t in argv}
    flags: dict[str, str] = getattr(args, "_flags", {})
    run_flags: dict[str, str] = getattr(args, "_api_flags", {})  # this run's: always said
    names: dict[str, str] = dict(flags)
    names.update({**API_FLAGS, **run_flags})
    known = set(flags.values()) | set(run_flags.values())
    typed = getattr(args, "_typed_as", None) or {}  # an old spelling: named as typed
    subs: list[tuple[re.Pattern[str], str]] = []
    for name, flag in sorted(names.items(), key=lambda kv: -len(kv[0])):
        flag = typed.get(flag, flag)
        n = re.escape(name)
        # a group (a_over_R) is named as a flag only where the user typed that flag: a flag
        # of the subcommand left out (its default) is named for an SI parameter only
        untyped = flag in known and ("_over_" not in name or flag in run_flags.values())
        if "_" in name and (flag in given or untyped):
            # a parameter's name, wherever it stands
            subs.append((re.compile(rf"(?<![\w-]){n}(?![\w])"), flag))
        elif flag in given:
            # a plain word (radius, load) only where it is the subject of a check ("load
            # must ...", "load=...") or a term of a ratio ("radius / equilibrium_spacing")
            subs.append((re.compile(rf"(?<![\w-]){n}(?= must| =|=| ?/)|(?<=/){n}(?![\w])"), flag))
    out = []
    for text, keep in _protected(message, _typed_values(argv)):
        if not keep:
            for pattern, flag in subs:
                text = pattern.sub(flag, text)
        out.append(text)
    message = "".join(out)
    # a choice as the API writes it (law='dugdale') as it is typed (--law dugdale)
    choices = getattr(args, "_choice_flags", None)
    return re.sub(
        r"(--[\w-]+)='([\w-]+)'",
        lambda m: f"{m[1]} {m[2]}" if choices is None or m[1] in choices else m[0],
        message,
    )


def spell(message: str, inputs: Any) -> str:
    """``message`` in the flags of the operation of ``inputs`` (a call with typed values).

    As :func:`flag_message` for a command line made of ``inputs.words``: each parameter's
    declared flag, the library's names of this call (``inputs.said_as``) said as theirs.
    """
    op = inputs.operation
    args = argparse.Namespace(
        argv=list(inputs.words),
        _flags={p.name: p.option for p in op.parameters},
        _choice_flags={p.option for p in op.parameters if p.choices is not None},
        _api_flags={
            k: v if v.startswith("--") else op.parameter(v).option
            for k, v in inputs.said_as.items()
        },
        _typed_as={},
    )
    return flag_message(message, args)
