"""Messages in the user's words, as a property (issue 30, point 5).

Every subcommand of the command line (enumerated from its parser) and each of its numeric
flags is sent the values of :data:`VALUES` on top of a valid command line of that
subcommand; the run ends with status 0 or 2 (never 1, never a traceback), and every line it
says on stderr is in the words of the user: no internal group of the library
(``F_over_Eh``, ``R/h``, ``mu``, ... listed from :data:`linecontact.domain.DOMAIN`) unless
the user typed that group's flag, no parameter name of the Python API (``normal_load``),
no NumPy warning; an error names a flag the user typed, or says something plain without
one. A path the user gave comes out verbatim, even one whose name is a flag's
(``z0/data.csv``). The SI Python API (the :class:`~linecontact.Cylinder` constructors and
methods, the inverse problems in SI units) is sent the same values keyword by keyword: a
:class:`ValueError` that names the caller's own keywords, never a group.

Every subcommand, every flag and every value is run, each on the valid command lines that
hold the flag (or the first one), in about half a minute on two cores.
"""

from __future__ import annotations

import argparse
import contextlib
import errno
import inspect
import io
import os
import re
import subprocess
import sys
import time
import warnings
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest

import linecontact as lc
from linecontact import ConvergenceError, Cylinder
from linecontact.cli import build_parser, main
from linecontact.domain import DOMAIN
from linecontact.laws import LennardJones

#: The out-of-range values sent to every numeric flag and keyword.
VALUES = ("-1", "0", "1e300", "-1e300", "nan", "inf", "1e-300")

# --------------------------------------------------------------------------------------------
# what no message may say


#: The groups of the library: every entry of the domain that is no SI input, the friction
#: coefficient ``mu`` and the groups of the results (any ``*_over_*`` name), in the API's
#: spelling and as ratios (``R/h``, ``F/(E h)``).
_SI_KEYS = {"E1", "E2", "work_of_adhesion", "equilibrium_spacing"}
GROUP_NAMES = sorted(
    {k.removeprefix("sliding_").removeprefix("friction_") for k in DOMAIN} - _SI_KEYS
)
GROUPS = re.compile(
    r"(?<![\w-])(?:\w+_over_\w+|mu|kappa|lambda|rho|lj_mu\w*"
    r"|R/h2?|sigma0/E|tau0/E|a/R|h1/h2|d/a|H/R|[FQT]/\((?:E ?[ah]2?|mu ?F)\))(?![\w-])"
)
#: A name of the Python API (``normal_load``, ``cohesive_stress``): no word of the user's.
SNAKE = re.compile(r"(?<![\w-])[A-Za-z][A-Za-z0-9]*(?:_[A-Za-z0-9]+)+(?![\w-])")
#: A quoted value (a path, a column, a choice): the user's own words, as they gave them.
QUOTED = re.compile(r"""(?<!\w)'[^'\n]*'(?!\w)|(?<!\w)"[^"\n]*"(?!\w)""")
FLAG = re.compile(r"(?<![\w-])(--[A-Za-z][\w-]*|-o)(?![\w-])")


def _normal(token: str) -> str:
    """A group's spelling without spaces and parentheses: ``F/(E h)`` -> ``F/Eh``."""
    return re.sub(r"[\s()]", "", token).replace("_over_", "/")


def test_the_group_list_is_the_librarys():
    # the groups the property refuses are those of the domain table: a new group in the
    # table is refused too (the regular expression matches each of them)
    assert {"R_over_h", "sigma0_over_E", "F_over_Eh", "T_over_Ea", "mu", "a_over_R"} <= set(
        GROUP_NAMES
    )
    for name in GROUP_NAMES:
        assert GROUPS.fullmatch(name), name
    for ratio in ("R/h", "sigma0/E", "F/(E h)", "T/(E a)", "T/(mu F)", "h1/h2"):
        assert GROUPS.fullmatch(ratio), ratio
    assert not GROUPS.search("--mu 0.3 --R-over-h 100 the modulus times the adhesion range")


def _allowed_groups(typed: set[str]) -> set[str]:
    """The group spellings a user may read: those of the group flags typed (``--R-over-h``)."""
    names = {f[2:].replace("-", "_") for f in typed if f.startswith("--")}
    out = {_normal(n) for n in names} | names
    if any("muF" in n for n in names):
        out.add("mu")
    return out


def _unprotected(line: str, values: list[str]) -> str:
    """``line`` without its quoted values and the values the user typed (kept verbatim)."""
    line = QUOTED.sub(" ", line)
    for v in sorted(values, key=len, reverse=True):
        line = re.sub(rf"(?<![\w-]){re.escape(v)}(?![\w-])", " ", line)
    return line


def _typed(argv: list[str]) -> tuple[set[str], list[str]]:
    """The flags and the values of ``argv`` (after the subcommand)."""
    flags, values = set(), []
    for word in argv[1:]:
        if re.fullmatch(r"-?(\d|\.\d|inf|nan)[\w.+-]*", word, re.IGNORECASE):
            values.append(word)
        elif word.startswith("-"):
            flags.add(word.split("=", 1)[0])
        else:
            values.append(word)
    return flags, values


def check_words(line: str, typed: set[str], values: list[str]) -> None:
    """``line`` names no group (unless typed), no API name, no NumPy warning."""
    text = _unprotected(line, values)
    allowed = _allowed_groups(typed)
    groups = [g for g in GROUPS.findall(text) if g not in allowed and _normal(g) not in allowed]
    assert not groups, f"internal group {groups} in: {line}"
    names = [n for n in SNAKE.findall(text) if n not in allowed]
    assert not names, f"API name {names} in: {line}"
    assert "encountered in" not in text, f"a NumPy warning: {line}"
    assert "Traceback" not in line and "internal error" not in line, line


# --------------------------------------------------------------------------------------------
# the command line: valid command lines of every subcommand (SI first)

SI = ["--radius", "50e-9", "--modulus", "100e9", "--sigma0", "1e9", "--h", "0.5e-9"]
MATS = ["--E1", "70e9", "--nu1", "0.17", "--E2", "160e9", "--nu2", "0.22"]
WORK = ["--work-of-adhesion", "0.1", "--z0", "0.3e-9"]
PRESETS = ["--cylinder-material", "ZnO", "--substrate-material", "SiO2"]
SLIDE_SI = ["--radius", "50e-9", "--modulus", "100e9", "--sigma0", "1e9", "--h2", "0.5e-9"]
PUSH_SI = ["--radius", "50e-9", "--modulus", "48e9", "--sigma0", "1e8", "--h2", "0.3e-9"]
COULOMB_SI = ["--radius", "50e-9", "--modulus", "100e9", "--sigma0", "0", "--h", "0.5e-9"]
FRICTION = ["--radius", "50e-9", "--modulus", "51.7e9", *WORK]
RANGE = ["--a-over-R-range", "0.001", "0.1", "5"]
ND = ["--R-over-h", "100", "--sigma0-over-E", "0.01"]
ND2 = ["--R-over-h2", "100", "--h1-over-h2", "2", "--sigma0-over-E", "0.01"]

#: Radii [m] and Maugis-Dugdale pull-off forces [N/m] (w = 0.1 J/m^2, z0 = 0.3 nm, 50 GPa).
RADII = [1e-8, 2e-8, 4e-8, 8e-8, 1.6e-7]


def bases(tmp) -> dict[str, list[list[str]]]:
    """Valid command lines per subcommand, their files under ``tmp`` (flag-like names)."""
    F = [float(lc.fits.pull_off_force(r, 50e9, 0.1, 0.3e-9)) for r in RADII]
    (tmp / "z0").mkdir(exist_ok=True)
    pulloffs = tmp / "z0" / "data.csv"
    pulloffs.write_text(
        "radius_m,pull_off_force_N_per_m\n"
        + "".join(f"{r},{f}\n" for r, f in zip(RADII, F, strict=True))
    )
    (tmp / "radius-dir").mkdir(exist_ok=True)
    frictions = tmp / "radius-dir" / "x.csv"
    frictions.write_text("normal_load_N_per_m,friction_force_N_per_m\n0.5,0.2\n1.0,0.3\n")
    # a wire dragged at its midpoint (a small bending: the parabola of a short cantilever)
    s = np.linspace(-1, 1, 41)
    profile = tmp / "radius-dir" / "profile.csv"
    profile.write_text(
        "x_nm,y_nm\n"
        + "".join(f"{2500 * v},{-40 * v * v * (6 - 4 * abs(v) + v * v) / 3}\n" for v in s)
    )
    out = str(tmp / "z0" / "out.json")
    figs = str(tmp / "radius-figs")
    return {
        "normal": [
            ["normal", *SI, "--load", "1", "--length", "1e-6"],
            ["normal", "--radius", "50e-9", *MATS, *WORK, "--half-width", "5e-9"],
            ["normal", "--radius", "50e-9", *PRESETS, *WORK, "--load", "0", "1", "-o", out,
             "--indent", "2"],
            ["normal", *ND, "--a-over-R", "0.01"],
            ["normal", *ND, *RANGE],
            ["normal", *ND, "--F-over-Eh", "0.5"],
        ],
        "pulloff": [
            ["pulloff", *SI, "--length", "1e-6"],
            ["pulloff", "--law", "lennard-jones", "--radius", "50e-9", *MATS, *WORK],
            ["pulloff", *ND],
        ],
        "curve": [
            ["curve", *SI, "--num", "20", "--num-noncontact", "5", "--a-max", "1e-8"],
            ["curve", "--law", "lennard-jones", "--radius", "50e-9", "--modulus", "50e9", *WORK,
             "--F-max", "1"],
            ["curve", *ND, "--num", "20", "--a-max-over-R", "0.1"],
            ["curve", "--law", "lennard-jones", *ND, "--F-max-over-Eh", "0.1"],
        ],
        **{
            cmd: [
                [cmd, *SI, "--load", "1", "--tau0", "1e8", "--tangential-load", "0.3"],
                [cmd, "--friction", "coulomb", "--mu", "0.3", *COULOMB_SI, "--load", "1",
                 "--tangential-load", "0.1"],
                [cmd, "--tau0-over-E", "0.01", "--d-over-a", "0.5"],
                [cmd, "--tau0-over-E", "0.01", "--T-over-Ea", "0.01", *ND, "--F-over-Eh", "0.5"],
                [cmd, "--friction", "coulomb", "--mu", "0.3", "--a-over-R", "0.01",
                 "--T-over-muF", "0.5"],
            ]
            for cmd in ("slide-init", "roll")
        },
        "cycle": [
            ["cycle", *SI, "--load", "1", "--tau0", "1e9", "--tangential-amplitude", "0.5"],
            ["cycle", "--friction", "coulomb", "--mu", "0.3", *COULOMB_SI, "--load", "1",
             "--tangential-amplitude", "0.1"],
            ["cycle", "--tau0-over-E", "0.01", "--T-amplitude-over-Ea", "0.005", *ND,
             "--F-over-Eh", "0.5"],
            ["cycle", "--friction", "coulomb", "--mu", "0.3", "--a-over-R", "0.01",
             "--T-amplitude-over-muF", "0.5"],
        ],
        "history": [
            ["history", *SI, "--load", "1", "--tau0", "1e9", "--tangential-load", "1", "-1"],
            ["history", "--friction", "coulomb", "--mu", "0.3", *COULOMB_SI, "--load", "1",
             "--tangential-load", "0.1", "-0.1"],
            ["history", "--tau0-over-E", "0.01", "--T-over-Ea", "0.016", "-0.008", *ND,
             "--F-over-Eh", "0.5"],
            ["history", "--friction", "coulomb", "--mu", "0.3", "--a-over-R", "0.01",
             "--T-over-muF", "0.5", "-0.5"],
        ],
        "fit-adhesion": [
            ["fit-adhesion", "--radius", "50e-9", "--pull-off-force", "-3.1", "--modulus",
             "51.7e9", "--z0", "0.3e-9", "--radius-sd", "3e-9", "--pull-off-force-sd", "5%",
             "--modulus-sd", "1e9", "--z0-sd", "1e-11", "--samples", "20", "--seed", "1"],
            ["fit-adhesion", "--radius", "50e-9", "--modulus", "50e9", "--z0", "0.3e-9",
             "--half-width", "5e-9", "--load", "0.5", "--half-width-sd", "2%", "--samples",
             "20"],
            ["fit-adhesion", "--radius", "50e-9", "--pull-off-force-total", "-3.1e-6",
             "--length", "1e-6", "--pull-off-force-total-sd", "1e-7", "--modulus", "51.7e9",
             "--z0", "0.3e-9", "--samples", "20"],
            ["fit-adhesion", "--data", str(pulloffs), "--modulus", "50e9", "--bootstrap", "0"],
            ["fit-adhesion", "--data", str(pulloffs), *MATS, "--z0", "3e-10", "--bootstrap",
             "10", "--samples", "10"],
        ],
        "fit-friction": [
            ["fit-friction", "--load", "0.5", "--friction-force", "0.2", "--friction-force-sd",
             "10%", *FRICTION, "--radius-sd", "1e-9", "--modulus-sd", "1e9", "--z0-sd",
             "1e-11", "--work-of-adhesion-sd", "0.01", "--samples", "20", "--seed", "1"],
            ["fit-friction", "--load", "0.5", "--friction-force", "0.2", *FRICTION,
             "--work-of-adhesion-receding", "0.2", "--samples", "20"],
            ["fit-friction", "--load", "0.5", "--friction-force", "0.2", "--half-width", "5e-9",
             "--half-width-sd", "1e-10", "--samples", "20"],
            ["fit-friction", "--data", str(frictions), "--radius", "50e-9", *PRESETS, *WORK,
             "--samples", "20"],
        ],
        "fit-bent-wire": [
            ["fit-bent-wire", "--data", str(profile), "--radius", "50e-9", "--modulus", "140e9",
             "--bootstrap", "10"],
            ["fit-bent-wire", "--data", str(profile), "--radius", "50e-9", "--radius-sd", "1%",
             "--cylinder-material", "ZnO", "--modulus-sd", "1e9", "--bootstrap", "0", *WORK,
             "--work-of-adhesion-sd", "0.01", "--z0-sd", "1e-11", "--substrate-material", "SiO2",
             "--samples", "20", "--noise", "1e-9", "--load", "0.01"],
            ["fit-bent-wire", "--data", str(profile), "--radius", "50e-9", "--modulus", "140e9",
             "--cross-section", "hexagon", "--corner-radius", "5e-9", "--bootstrap", "0", *WORK,
             "--contact-modulus", "50e9", "--samples", "20"],
            ["fit-bent-wire", "--data", str(profile), "--radius", "50e-9", "--modulus", "140e9",
             "--model", "held", "--bootstrap", "5"],
            ["fit-bent-wire", "--data", str(profile), "--radius", "50e-9", "--modulus", "140e9",
             "--inner-radius", "20e-9", "--bootstrap", "0", *WORK, "--nu1", "0.3", "--E2",
             "70e9", "--nu2", "0.17", "--samples", "20", "--seed", "2"],
        ],
        "slide": [
            ["slide", *SLIDE_SI, "--h1", "1e-9", "--load", "0.05", "--tau0", "5e8", "--length",
             "1e-6"],
            ["slide", "--radius", "50e-9", "--modulus", "100e9", "--work-of-adhesion-advancing",
             "0.1", "--z0", "0.3e-9", "--h1-over-h2", "2", "--half-width", "5e-9"],
            ["slide", *ND2, "--a-over-R", "0.01", "--tau0-over-E", "0.001"],
            ["slide", *ND2, "--F-over-Eh2", "0.1"],
            ["slide", *ND2, *RANGE],
        ],
        "push": [
            ["push", *PUSH_SI, "--h1", "0.6e-9", "--tau0", "1e6", "--height", "25e-9",
             "--push", "0.01", "--load", "0.1", "--length", "1e-6"],
            ["push", *PUSH_SI, "--h1", "0.6e-9", "--tau0", "1e6", "--tip-height", "50e-9",
             "--tip-friction", "0.1"],
            ["push", "--radius", "50e-9", "--modulus", "48e9", "--work-of-adhesion-receding",
             "0.2", "--work-of-adhesion-advancing", "0.1", "--z0", "0.3e-9", "--tau0", "1e6",
             "--height", "25e-9"],
            ["push", *ND2, "--tau0-over-E", "1e-3", "--H-over-R", "0.25", "--F-over-Eh2",
             "0.1", "--Q-over-Eh2", "0.01"],
        ],
        "paper": [["paper", "--outdir", figs, "--size", "9.6x5.4"]],
        "figures": [["figures", "--outdir", figs, "--size", "9.6x5.4"]],
        "cite": [["cite"]],
        "map": [
            ["map", "--quick", "--outdir", figs, "--tol", "0.05", "--mu-min", "0.1", "--mu-max",
             "1", "--y-max", "5", "--workers", "1", "--size", "9.6x5.4", "-o", out,
             "--indent", "2"],
            ["map", "--n-mu", "2", "--n-y", "2", "--outdir", figs],
        ],
        "materials": [["materials", "--json", "--indent", "2"]],
        "sweep": [
            ["sweep", "pulloff", "--radius", "1e-8:1e-7:2:log", "--modulus", "1e11", *WORK,
             "-o", str(tmp / "z0.zarr"), "--overwrite", "--workers", "1", "--chunk-points",
             "10"],
        ],
        "serve": [["serve", "--port", "0", "--workers", "2", "--time-limit", "60"]],
    }  # fmt: skip


def _subparsers() -> dict[str, argparse.ArgumentParser]:
    return build_parser()._defaults["_subparsers"].choices


SUBPARSERS = _subparsers()


def _is_numeric(action: argparse.Action) -> bool:
    """A flag that takes numbers: its type, or a metavar of numbers (SD, N, WxH)."""
    return bool(action.option_strings) and (
        action.type in (float, int) or action.metavar in ("SD", "N", "WxH")
    )


def _visible(action: argparse.Action) -> bool:
    return action.help != argparse.SUPPRESS


#: Every numeric flag of every subcommand, the deprecated spellings (not in the help) too.
NUMERIC = {
    name: [a.option_strings[-1] for a in sp._actions if _is_numeric(a)]
    for name, sp in SUBPARSERS.items()
}
CASES = [(name, flag) for name, flags in NUMERIC.items() for flag in flags] + [
    (name, None) for name, flags in NUMERIC.items() if not flags
]


class Reached(KeyboardInterrupt):
    """The work of a command whose checks passed (a map, a server, figures): not done here."""


@pytest.fixture(scope="module")
def lines(tmp_path_factory) -> dict[str, list[list[str]]]:
    return bases(tmp_path_factory.mktemp("messages"))


@pytest.fixture(autouse=True)
def _no_long_work(monkeypatch):
    """The map, the server and the figures stop where their work starts (status 130)."""
    import linecontact.adhesion_map
    import linecontact.figures
    import linecontact.web

    def reached(*args: Any, **kwargs: Any):
        raise Reached

    monkeypatch.setattr(linecontact.adhesion_map, "adhesion_map", reached)
    monkeypatch.setattr(linecontact.web, "create_app", reached)
    monkeypatch.setattr(linecontact.figures, "paper_figures", reached)
    monkeypatch.setattr(linecontact.figures, "extra_figures", reached)


def run(argv: list[str]) -> tuple[int, str]:
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = main(argv)
        except SystemExit as exc:  # argparse's own errors (status 2)
            code = int(exc.code or 0)
    return code, err.getvalue()


def with_value(base: list[str], flag: str, value: str) -> list[str]:
    """``base`` with ``flag`` given ``value`` (in place of its values, or appended)."""
    action = SUBPARSERS[base[0]]._option_string_actions[flag]
    count = action.nargs if isinstance(action.nargs, int) else 1
    argv = list(base)
    if flag in argv:
        i = argv.index(flag)
        j = i + 1
        while j < len(argv) and not (argv[j].startswith("-") and FLAG.fullmatch(argv[j])):
            j += 1
        argv[i + 1 : j] = [value] * count
    else:
        argv += [flag, *([value] * count)]
    return argv


#: Status 1 is a run none of whose points has a state (README, docs/cli.md): said so.
NO_POINT = ": error: no point could be computed: "


def check_run(argv: list[str], code: int, err: str) -> None:
    """The property of one run: status, one error line, the user's words."""
    assert code in (0, 2, 130) or (code == 1 and NO_POINT in err), (argv, code, err)
    typed, values = _typed(argv)
    stderr = err.strip().splitlines()
    for line in stderr:
        check_words(line, typed, values)
    if code not in (1, 2):
        return
    errors = [line for line in stderr if ": error: " in line]
    assert len(errors) == 1 and errors[0] == stderr[-1], (argv, err)
    line = errors[0].split(": error: ", 1)[1]
    parser = SUBPARSERS[argv[0]]
    # an old spelling typed: the run said its new one (a warning line), which may be named
    for flag in list(typed):
        target = getattr(parser._option_string_actions.get(flag), "target", None)
        if target is not None:
            typed.add(target.option_strings[-1])
    named = set(FLAG.findall(_unprotected(line, values)))
    unknown = {f for f in named if f not in parser._option_string_actions}
    assert not unknown, f"flags of no option of {argv[0]} {unknown}: {line}"
    # a flag not typed is named only with the value its default gave ("--load=0.0 N/m")
    defaults = {f for f in named - typed if re.search(rf"{re.escape(f)}=", line)}
    assert named & typed or named == defaults, f"names no flag the user typed: {line}"


def test_every_subcommand_has_a_valid_command_line(lines):
    assert set(lines) == set(SUBPARSERS)  # a new subcommand needs one here
    for argvs in lines.values():
        for argv in argvs:
            code, err = run(argv)
            assert code in (0, 130), (argv, err)
            for line in err.strip().splitlines():
                check_words(line, *_typed(argv))


@pytest.mark.parametrize("command, flag", CASES, ids=[f"{c} {f}" for c, f in CASES])
def test_out_of_range_values_are_said_in_the_users_words(lines, command, flag):
    if flag is None:  # no numeric flag: the command line as it is
        for argv in lines[command]:
            code, err = run(argv)
            check_run(argv, code, err)
        return
    holding = [b for b in lines[command] if flag in b]
    group = "-over-" in flag or flag == "--mu"
    nondimensional = [b for b in lines[command] if any("-over-" in w for w in b)]
    for base in holding or (nondimensional if group and nondimensional else lines[command][:1]):
        for value in VALUES:
            argv = with_value(base, flag, value)
            code, err = run(argv)
            check_run(argv, code, err)


# --------------------------------------------------------------------------------------------
# paths come out verbatim


def _path_flags(command: str) -> list[str]:
    return [
        a.option_strings[-1]
        for a in SUBPARSERS[command]._actions
        if _visible(a) and a.metavar in ("FILE", "DIR")
    ]


PATH_CASES = [(c, f) for c in SUBPARSERS for f in _path_flags(c)]


@pytest.mark.parametrize("command, flag", PATH_CASES, ids=[f"{c} {f}" for c, f in PATH_CASES])
def test_a_path_with_a_flags_name_comes_out_verbatim(lines, tmp_path, command, flag):
    # a path under a regular file, its parts flags' names: the error says it as given
    (tmp_path / "z0").write_text("a file, not a directory")
    path = str(tmp_path / "z0" / "radius-dir" / "h" / "load.csv")
    base = next((b for b in lines[command] if flag in b), lines[command][0])
    argv = with_value(base, flag, path)
    code, err = run(argv)
    check_run(argv, code, err)
    # the figures create their directory as they draw (not here: status 130)
    assert code == 130 or (code == 2 and repr(path) in err), err
    for name in ("z0", "radius-dir", "h", "load"):
        assert f"--{name}/" not in err and f"/--{name}" not in err, err


@pytest.mark.parametrize(
    "command, header, flags",
    [
        ("fit-adhesion", "radius_m,pull_off_force_N_per_m", ["--modulus", "50e9"]),
        ("fit-friction", "normal_load_N_per_m,friction_force_N_per_m", FRICTION),
    ],
)
def test_a_data_file_under_a_flags_name_is_named_verbatim(tmp_path, command, header, flags):
    # the fuzz's finding: --data z0/data.csv was reported with --z0 inside the path
    for folder in ("z0", "radius", "h", "load", "modulus"):
        (tmp_path / folder).mkdir()
        path = tmp_path / folder / "data.csv"
        path.write_text(f"{header}\n1e-8,abc\n")
        argv = [command, "--data", str(path), *flags]
        code, err = run(argv)
        check_run(argv, code, err)
        assert code == 2 and repr(str(path)) in err and "'abc'" in err, err


# --------------------------------------------------------------------------------------------
# the SI Python API


def _api_cases() -> list[tuple[str, Callable[..., Any], dict[str, Any]]]:
    cyl = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)
    cylw = Cylinder.from_modulus(50e-9, 100e9, work_of_adhesion=0.1, equilibrium_spacing=0.3e-9)
    cyl0 = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=0.0, adhesion_range=0.5e-9)
    F3 = [float(lc.fits.pull_off_force(r, 50e9, 0.1, 0.3e-9)) for r in RADII[:3]]
    w = dict(work_of_adhesion=0.1, equilibrium_spacing=0.3e-9)
    sigma = dict(cohesive_stress=1e9, adhesion_range=0.5e-9)
    mats = dict(E1=70e9, nu1=0.17, E2=160e9, nu2=0.22)
    inv = dict(radius=50e-9, modulus=50e9, equilibrium_spacing=0.3e-9)
    return [
        ("Cylinder", Cylinder,
         dict(radius=50e-9, modulus=100e9, adhesion=lc.Dugdale(**sigma), dundurs_beta=0.1)),
        ("Dugdale", lc.Dugdale, sigma),
        ("Dugdale (w, z0)", lc.Dugdale, w),
        ("LennardJones", lc.LennardJones, w),
        ("Cylinder.from_modulus", Cylinder.from_modulus, dict(radius=50e-9, modulus=1e11, **sigma)),
        ("Cylinder.from_modulus (w, z0)", Cylinder.from_modulus,
         dict(radius=50e-9, modulus=1e11, **w)),
        ("Cylinder.from_materials", Cylinder.from_materials, dict(radius=50e-9, **mats, **w)),
        ("Cylinder.from_presets", Cylinder.from_presets,
         dict(radius=50e-9, cylinder_material="ZnO", substrate_material="SiO2", **sigma)),
        ("contact (load)", cyl.contact, dict(load=1.0)),
        ("contact (width)", cyl.contact, dict(contact_half_width=5e-9)),
        ("load_curve", cyl.load_curve, dict(max_half_width=1e-8, num=20, num_noncontact=5)),
        ("lennard_jones_contact", cylw.under(LennardJones).contact, dict(load=1.0)),
        ("lennard_jones_load_curve", cylw.under(LennardJones).load_curve, dict(max_load=1.0)),
        ("sliding (load)", cyl.sliding, dict(receding_range=1e-9, load=0.05, friction_stress=5e8)),
        ("sliding (width)", cyl.sliding, dict(receding_range=1e-9, contact_half_width=5e-9)),
        ("sliding (h1_over_h2)", cyl.sliding, dict(h1_over_h2=2.0, load=0.05)),
        ("sliding_initiation", cyl.sliding_initiation,
         dict(normal_load=1.0, friction_stress=1e8, tangential_load=0.3)),
        ("sliding_initiation (d_over_a)", cyl.sliding_initiation,
         dict(normal_load=1.0, friction_stress=1e8, d_over_a=0.5)),
        ("steady_rolling", cyl.steady_rolling,
         dict(normal_load=1.0, friction_stress=1e8, tangential_load=0.3)),
        ("sliding_initiation (Coulomb)", cyl0.sliding_initiation,
         dict(normal_load=1.0, friction_coefficient=0.3, tangential_load=0.1)),
        ("steady_rolling (Coulomb)", cyl0.steady_rolling,
         dict(normal_load=1.0, friction_coefficient=0.3, tangential_load=0.1)),
        ("tangential_history", cyl.tangential_history,
         dict(normal_load=1.0, tangential_load=[1.0, -1.0], friction_stress=1e9)),
        ("tangential_history (Coulomb)", cyl0.tangential_history,
         dict(normal_load=1.0, tangential_load=[0.1, -0.1], friction_coefficient=0.3)),
        ("cyclic_loss", cyl.cyclic_loss, dict(normal_load=1.0, amplitude=0.5, friction_stress=1e9)),
        ("cyclic_loss (Coulomb)", cyl0.cyclic_loss,
         dict(normal_load=1.0, amplitude=0.1, friction_coefficient=0.3)),
        ("push", cyl.push,
         dict(friction_stress=1e6, height=25e-9, receding_range=1e-9, normal_load=0.1, push=0.01,
              length=1e-6)),
        ("push (receding work)", cylw.push,
         dict(friction_stress=1e6, height=25e-9, receding_work_of_adhesion=0.2, normal_load=0.1)),
        ("push (tip)", cyl.push,
         dict(friction_stress=1e6, height=80e-9, receding_range=1e-9, tip_friction=0.1)),
        ("tangential_load", cyl.tangential_load, dict(normal_load=1.0, value=0.01)),
        ("total", cyl.total, dict(value=1.0, length=1e-6)),
        ("fit_pull_off", lc.fit_pull_off,
         dict(radius=RADII[:3], pull_off_force=F3, modulus=50e9, equilibrium_spacing=0.3e-9,
              bootstrap=0, modulus_sd=1e9, equilibrium_spacing_sd=1e-11, samples=2)),
        ("fit_pull_off (joint)", lc.fit_pull_off,
         dict(radius=RADII[:3], pull_off_force=F3, modulus=50e9, sd=[0.1, 0.1, 0.1],
              bootstrap=0)),
        ("work_of_adhesion_from_pull_off", lc.work_of_adhesion_from_pull_off,
         dict(pull_off_force=-3.1, **inv)),
        ("work_of_adhesion_from_width", lc.work_of_adhesion_from_width,
         dict(half_width=5e-9, normal_load=0.5, **inv)),
        ("shear_strength_from_friction", lc.shear_strength_from_friction,
         dict(friction_force=0.2, normal_load=0.5, **inv, work_of_adhesion=0.1)),
        ("shear_strength_from_friction (receding)", lc.shear_strength_from_friction,
         dict(friction_force=0.2, normal_load=0.5, **inv, work_of_adhesion=0.1,
              receding_work_of_adhesion=0.2)),
        ("shear_strength_from_friction (jkr)", lc.shear_strength_from_friction,
         dict(friction_force=0.2, normal_load=0.5, **inv, work_of_adhesion=0.1, contact="jkr")),
        ("adhesion_from_work", lc.adhesion_from_work, dict(**w)),
        ("composite_modulus", lc.composite_modulus, dict(**mats)),
        ("dundurs_beta", lc.dundurs_beta, dict(**mats)),
        ("pull_off_force", lc.fits.pull_off_force, dict(radius=50e-9, modulus=50e9, **w)),
        ("jkr_pull_off_force", lc.fits.jkr_pull_off_force,
         dict(radius=50e-9, modulus=50e9, work_of_adhesion=0.1)),
        ("dmt_pull_off_force", lc.fits.dmt_pull_off_force, dict(radius=50e-9, **w)),
    ]  # fmt: skip


API_CASES = _api_cases()
#: The Cylinder's own keywords (a method may say which of the cylinder's inputs it needs).
CYLINDER_KEYS = {
    "radius", "modulus", "cohesive_stress", "adhesion_range", "work_of_adhesion",
    "equilibrium_spacing", "dundurs_beta", "E1", "nu1", "E2", "nu2", "cylinder_material",
    "substrate_material",
}  # fmt: skip


def test_every_api_case_is_valid():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", lc.ModelValidityWarning)
        warnings.simplefilter("ignore", lc.CouplingWarning)
        for _, fn, kwargs in API_CASES:
            fn(**kwargs)


def _numbers(value: Any) -> bool:
    return not isinstance(value, str) and np.asarray(value).dtype.kind in "if"


API_KEYWORDS = [(name, key) for name, _, kw in API_CASES for key, v in kw.items() if _numbers(v)]


@pytest.mark.parametrize("case, keyword", API_KEYWORDS, ids=[f"{c}: {k}" for c, k in API_KEYWORDS])
def test_the_si_api_names_its_own_keywords(case, keyword):
    fn, kwargs = next((f, kw) for name, f, kw in API_CASES if name == case)
    keywords = set(inspect.signature(fn).parameters) | set(kwargs)
    if "adhesion" in kwargs:  # a law value's parameters are the cylinder's too
        keywords |= set(kwargs["adhesion"].given)
    allowed = keywords | CYLINDER_KEYS
    for text in VALUES:
        value = float(text)
        shaped = np.full(np.shape(kwargs[keyword]), value) if np.ndim(kwargs[keyword]) else value
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            try:
                fn(**{**kwargs, keyword: shaped})
            except (ValueError, ConvergenceError) as exc:
                message = str(exc)
            else:
                message = ""
        # its notes too: in SI terms, and no NumPy warning
        for w in caught:
            assert not issubclass(w.category, RuntimeWarning), (case, keyword, value, w.message)
            note = QUOTED.sub(" ", str(w.message))
            assert not GROUPS.findall(note), (case, keyword, value, w.message)
        if not message:
            continue
        text_ = QUOTED.sub(" ", message)
        groups = [g for g in GROUPS.findall(text_) if g not in kwargs]
        assert not groups, f"{case}({keyword}={value!r}): group {groups}: {message}"
        names = set(SNAKE.findall(text_))
        assert names <= allowed, f"{case}({keyword}={value!r}): {names - allowed}: {message}"
        assert names & keywords or not names, f"{case}({keyword}={value!r}): {message}"
        assert "encountered in" not in message, message


# --------------------------------------------------------------------------------------------
# a full disk: the file it was writing, or standard output only where it was standard output

CURVE = ["curve", "--R-over-h", "100", "--sigma0-over-E", "0.01", "--num", "20"]


def _full(*args: Any, **kwargs: Any):
    raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="needs /dev/full")
def test_a_full_disk_under_standard_output_is_said_so():
    with open("/dev/full", "w") as full:
        proc = subprocess.run(
            [sys.executable, "-m", "linecontact", *CURVE, "--format", "csv"],
            stdout=full,
            stderr=subprocess.PIPE,
            text=True,
            timeout=120,
        )
    assert proc.returncode == 2
    assert proc.stderr == (
        "linecontact curve: error: cannot write to standard output: No space left on device\n"
    )


def test_a_full_disk_under_standard_output_in_process(monkeypatch):
    class Full(io.StringIO):
        def write(self, text: str) -> int:
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    err = io.StringIO()
    with contextlib.redirect_stdout(Full()), contextlib.redirect_stderr(err):
        code = main([*CURVE, "--format", "csv"])
    assert code == 2
    assert err.getvalue() == (
        "linecontact curve: error: cannot write to standard output: No space left on device\n"
    )


def test_a_full_disk_under_the_output_file_names_the_file(tmp_path, monkeypatch):
    # the data are written, then flushed to the disk: there the disk is full
    monkeypatch.setattr(os, "fsync", _full)
    target = tmp_path / "z0" / "curve.json"
    target.parent.mkdir()
    code, err = run([*CURVE, "-o", str(target)])
    assert code == 2
    assert err == (
        f"linecontact curve: error: no space left on the device writing -o/--output "
        f"{str(target)!r}\n"
    )
    assert "standard output" not in err and list(target.parent.iterdir()) == []


def test_a_full_disk_under_the_figures_names_their_directory(tmp_path, monkeypatch):
    import linecontact.figures

    monkeypatch.setattr(linecontact.figures, "extra_figures", _full)  # as savefig says it
    out = str(tmp_path / "radius-figs")
    code, err = run(["figures", "--outdir", out])
    assert code == 2
    assert err == (
        f"linecontact figures: error: no space left on the device writing the figures to "
        f"--outdir {out!r}\n"
    )


@pytest.mark.parametrize(
    "error, said",
    [
        (OSError(errno.ENOSPC, "No space left on device"), "no space left on the device "
         "writing a file (not standard output)"),
        (OSError(errno.ENOSPC, "No space left on device", "/data/z0.csv"),
         "no space left on the device writing '/data/z0.csv'"),
        (OSError(errno.EIO, "Input/output error", "/data/z0.csv"),
         "cannot write '/data/z0.csv': Input/output error"),
    ],
)  # fmt: skip
def test_a_failed_write_of_a_command_is_not_blamed_on_standard_output(monkeypatch, error, said):
    # a write the command makes itself (not through -o): stdout is fine, the file is not
    import linecontact.operations.normal as cli_normal

    def failing(*args: Any, **kwargs: Any):
        raise error

    monkeypatch.setattr(cli_normal, "load_curve", failing)
    code, err = run(CURVE)
    assert code == 2 and err == f"linecontact curve: error: {said}\n", err


# --------------------------------------------------------------------------------------------
# the incremental history refuses a step it cannot resolve at once, not after seconds


@pytest.mark.parametrize("loads", [[1e-300, -1e-300, 1e-300], [1e-13, -1e-13], [0.5, 0.5 - 1e-7]])
def test_an_unresolvable_step_of_the_incremental_history_is_refused_at_once(loads):
    # before: 7 s (three steps at 1e-300 of full slip), 2.4 s (two at 1e-13) of solving
    # every size up to 4096 nodes, to raise the same ConvergenceError
    T = np.asarray(loads) * 2 * 0.01  # over E a, tau0/E = 0.01: full slip at 0.02
    start = time.perf_counter()
    with pytest.raises(
        ConvergenceError, match=r"cannot resolve step \d: .* use method='closed-form'"
    ):
        lc.tangential_history(0.01, T, method="incremental")
    assert time.perf_counter() - start < 1.5
    # reported, every step is solved (and flagged): the solver is not skipped
    h = lc.tangential_history(0.01, T[:2], method="incremental", on_failure="report")
    assert not h.converged.all() and h.state.size == 2


def test_the_up_front_refusal_is_only_where_the_solver_fails():
    # Coulomb friction resolves tiny steps; a loose tolerance accepts them; a continuation
    # in the same direction opens no new stick zone
    assert lc.tangential_history_coulomb(
        0.3, 0.01, [1e-7, -1e-7], method="incremental"
    ).converged.all()
    loose = lc.tangential_history(0.01, [2e-9], method="incremental", tol=5e-5)
    assert loose.converged.all()
    on = lc.tangential_history(0.01, [0.01, 0.01 + 2e-9], method="incremental")
    assert on.converged.all()


def test_an_unresolvable_history_on_the_command_line_is_one_line_at_once():
    argv = ["history", *SI, "--load", "1", "--tau0", "1e9", "--method", "incremental",
            "--tangential-load", "1e-300", "-1e-300", "1e-300"]  # fmt: skip
    start = time.perf_counter()
    code, err = run(argv)
    assert time.perf_counter() - start < 1.5
    assert code == 1 and err.count("\n") == 1 and "cannot resolve step 1" in err, err


# --------------------------------------------------------------------------------------------
# the model notes of an SI run are said in SI terms too


def test_a_contact_beyond_small_strain_is_said_in_metres():
    cyl = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)
    cyl0 = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=0.0, adhesion_range=0.5e-9)
    calls = [
        lambda: cyl.contact(load=1000.0),
        lambda: cyl.contact(contact_half_width=2e-8),
        lambda: cyl.load_curve(max_half_width=3e-8),
        lambda: cyl.sliding(receding_range=1e-9, load=1000.0),
        lambda: cyl.sliding_initiation(1000.0, friction_stress=1e9, tangential_load=1.0),
        lambda: cyl0.steady_rolling(1000.0, friction_coefficient=0.3, tangential_load=1.0),
        lambda: cyl0.tangential_history(1000.0, [1.0, -1.0], friction_coefficient=0.3),
        lambda: cyl.push(friction_stress=1e6, height=25e-9, receding_range=1e-9, normal_load=1e3),
        lambda: lc.shear_strength_from_friction(20.0, 1000.0, 50e-9, 50e9, 0.1, 0.3e-9),
    ]
    for call in calls:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            call()
        said = [str(w.message) for w in caught if issubclass(w.category, lc.ModelValidityWarning)]
        assert said and all(re.search(r" m is [0-9.]+ times the radius, beyond", s) for s in said)
        for s in said:
            assert not GROUPS.search(s) and not SNAKE.search(s), s
    code, err = run(["normal", *SI, "--load", "1000"])
    assert code == 0 and err == (
        "linecontact normal: warning: the contact half-width 2.55e-08 m is 0.511 times the "
        "radius, beyond the small-strain range of the half-plane theory (at most 0.2 times the "
        "radius, a strain of 0.1): the results are those of linear elasticity\n"
    )
