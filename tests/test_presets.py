"""Material presets: the cited numbers, the lookup, the SI layer and the command line."""

import csv
import dataclasses
import json
import math
import re
import warnings
from pathlib import Path

import pytest

from linecontact import Cylinder, Sphere
from linecontact.cli import main
from linecontact.presets import MATERIALS, TIP_MATERIALS, Material, material_names

#: The cited numbers, written out: (E [Pa], nu, (E low, E high) [Pa], confirmed by search).
#: A silent change of a preset fails here; change both with the source.
CITED = {
    "Si": (163e9, 0.22, (130e9, 188e9), False),
    "SiO2": (72e9, 0.17, (60e9, 80e9), False),
    "Si3N4": (222e9, 0.28, (200e9, 310e9), True),
    "SiNx-PECVD": (150e9, 0.25, (120e9, 160e9), True),
    "DLC": (259e9, 0.25, (100e9, 259e9), True),
    "ta-C": (759e9, 0.17, (493e9, 781e9), True),
    "Al2O3": (403e9, 0.23, (345e9, 461e9), True),
    "Al2O3-poly": (416e9, 0.231, (300e9, 416e9), True),
    "mica": (54e9, 0.10, (50e9, 60e9), True),
    "mica-in-plane": (155e9, 0.25, (149e9, 161e9), True),
    "HOPG-basal": (25e9, 0.01, (5e9, 38.7e9), True),
    "HOPG-in-plane": (1.02e12, 0.17, (1.0e12, 1.09e12), False),
    "Au": (79e9, 0.42, (43e9, 117e9), False),
    "Ag": (82e9, 0.37, (44e9, 121e9), False),
    "Cu": (128e9, 0.34, (67e9, 191e9), False),
    "ZnO": (124e9, 0.36, (111e9, 145e9), False),
    "InAs": (76e9, 0.28, (51e9, 97e9), True),
    "GaN": (303e9, 0.26, (280e9, 360e9), True),
    "MWCNT-radial": (30e9, 0.2, (10e9, 80e9), True),
    "polystyrene": (3.2e9, 0.34, (2.3e9, 4.1e9), False),
    "nylon-6": (2.9e9, 0.39, (2.6e9, 3.2e9), True),
}

#: A key phrase of each source (author and DOI or the work), so that a swapped citation fails.
CITED_SOURCE = {
    "Si": "doi:10.1109/JMEMS.2009.2039697",
    "SiO2": "doi:10.1109/PROC.1982.12331",
    "Si3N4": "doi:10.1557/JMR.1992.3242",
    "SiNx-PECVD": "doi:10.1016/j.jeurceramsoc.2009.09.020",
    "DLC": "doi:10.1038/s41467-021-24766-6",
    "ta-C": "doi:10.1088/0960-1317/15/4/009",
    "Al2O3": "doi:10.6028/jres.064A.022",
    "Al2O3-poly": "doi:10.1111/j.1151-2916.1997.tb03074.x",
    "mica": "doi:10.1029/JB091iB05p04657",
    "mica-in-plane": "doi:10.1029/JB091iB05p04657",
    "HOPG-basal": "doi:10.1103/PhysRevB.75.153408",
    "HOPG-in-plane": "doi:10.1063/1.1659426",
    "Au": "doi:10.1103/PhysRev.111.707",
    "Ag": "doi:10.1103/PhysRev.111.707",
    "Cu": "doi:10.1103/PhysRev.98.969",
    "ZnO": "Kobiakov, Solid State Commun. 35 (1980)",
    "InAs": "Gerlich, J. Appl. Phys. 34 (1963)",
    "GaN": "doi:10.1063/1.361236",
    "MWCNT-radial": "doi:10.1103/PhysRevLett.94.175502",
    "polystyrene": "Physical Properties of Polymers Handbook",
    "nylon-6": "Dowling, Mechanical Behavior of Materials",
}

ADH = ("--work-of-adhesion", "0.1", "--z0", "0.3e-9")
DOCS = Path(__file__).resolve().parents[1] / "docs"


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


# --------------------------------------------------------------------------------------------
# the table


def test_the_presets_are_the_cited_ones():
    assert list(MATERIALS) == list(CITED) == list(material_names())
    for name, (E, nu, E_range, confirmed) in CITED.items():
        m = MATERIALS[name]
        assert (m.name, m.E, m.nu, m.E_range, m.confirmed) == (name, E, nu, E_range, confirmed)
        assert CITED_SOURCE[name] in m.source


@pytest.mark.parametrize("name", list(CITED))
def test_every_preset_is_consistent_and_sourced(name):
    m = MATERIALS[name]
    assert isinstance(m, Material)
    low, high = m.E_range
    assert 0 < low <= m.E <= high
    assert 0 < m.nu < 0.5
    assert m.source.strip() and re.search(r"\b(19|20)\d\d\b", m.source), m.source
    assert m.description.strip()
    assert m.indentation_modulus == m.E / (1 - m.nu**2)


def test_the_table_is_read_only():
    with pytest.raises(TypeError):
        MATERIALS["Si"] = MATERIALS["SiO2"]  # type: ignore[index]
    with pytest.raises(dataclasses.FrozenInstanceError):
        MATERIALS["Si"].E = 1.0  # type: ignore[misc]


def test_layered_crystals_normal_and_in_plane():
    # a fibre on a cleaved sheet sees the soft direction: the in-plane moduli are far larger
    assert MATERIALS["mica"].E * 2 < MATERIALS["mica-in-plane"].E
    assert MATERIALS["HOPG-basal"].E * 10 < MATERIALS["HOPG-in-plane"].E
    for name in ("mica-in-plane", "HOPG-in-plane"):
        assert "not a contact modulus" in MATERIALS[name].description.replace("NOT", "not")


# --------------------------------------------------------------------------------------------
# the tips of AFM probes and colloidal probes

#: E/(1 - nu^2) [Pa] of the tip presets, by hand: 1 - 0.25^2 = 0.9375, 1 - 0.17^2 = 0.9711,
#: 1 - 0.22^2 = 0.9516, 1 - 0.28^2 = 0.9216.
TIP_INDENTATION_MODULI = {
    "Si": 163e9 / 0.9516,
    "SiO2": 72e9 / 0.9711,
    "Si3N4": 222e9 / 0.9216,
    "SiNx-PECVD": 160e9,  # 150 / 0.9375
    "DLC": 276.26666666666667e9,  # 259 / 0.9375
    "ta-C": 781.58789002162496e9,  # 759 / 0.9711
}


def test_tip_materials_are_presets_in_table_order():
    assert TIP_MATERIALS == ("Si", "SiO2", "Si3N4", "SiNx-PECVD", "DLC", "ta-C")
    order = list(MATERIALS)
    assert [order.index(name) for name in TIP_MATERIALS] == sorted(
        order.index(name) for name in TIP_MATERIALS
    )
    # the families: silicon, silicon nitride, silica, diamond-like carbon
    for word in ("silicon", "nitride", "silica", "diamond-like carbon"):
        assert any(word in MATERIALS[n].description.lower() for n in TIP_MATERIALS), word


@pytest.mark.parametrize("name", list(TIP_INDENTATION_MODULI))
def test_tip_indentation_moduli_by_hand(name):
    assert MATERIALS[name].indentation_modulus == pytest.approx(
        TIP_INDENTATION_MODULI[name], rel=1e-14
    )


@pytest.mark.parametrize(
    "given, name",
    [
        ("DLC", "DLC"),
        ("dlc", "DLC"),
        ("Dlc", "DLC"),
        ("ta-c", "ta-C"),
        ("TA-C", "ta-C"),
        (" ta-C ", "ta-C"),
        ("sinx-pecvd", "SiNx-PECVD"),
        ("SINX-PECVD", "SiNx-PECVD"),
    ],
)
def test_tip_presets_by_name(given, name):
    assert Material.from_name(given) is MATERIALS[name]


def test_tip_presets_order_of_stiffness():
    m = MATERIALS
    # hydrogen-free ta-C is the stiffest; hydrogenated DLC about a third of it
    assert max(TIP_MATERIALS, key=lambda n: m[n].E) == "ta-C"
    assert 0.25 < m["DLC"].E / m["ta-C"].E < 0.45
    # LPCVD nitride is stiffer than PECVD nitride, and their ranges meet at most at an edge
    assert m["SiNx-PECVD"].E < m["Si3N4"].E
    assert m["SiNx-PECVD"].E_range[1] <= m["Si3N4"].E_range[0]
    # ta-C's range lies above every other tip preset's value
    assert all(m[n].E < m["ta-C"].E_range[0] for n in TIP_MATERIALS if n != "ta-C")


def test_tip_presets_name_the_other_kind():
    # each carbon (and each nitride) points to its sibling, so that a reader picks the right one
    assert "'ta-C'" in MATERIALS["DLC"].description
    assert "'DLC'" in MATERIALS["ta-C"].description
    assert "'SiNx-PECVD'" in MATERIALS["Si3N4"].description
    assert "a-C:H" in MATERIALS["DLC"].description


@pytest.mark.parametrize("tip", ["Si", "Si3N4", "SiNx-PECVD", "DLC", "ta-C"])
def test_a_sphere_from_tip_presets_is_from_their_moduli(tip):
    t, s = MATERIALS[tip], MATERIALS["SiO2"]
    adh = dict(work_of_adhesion=0.1, equilibrium_spacing=0.3e-9)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ref = Sphere.from_materials(20e-9, t.E, t.nu, s.E, s.nu, **adh)
        got = Sphere.from_presets(20e-9, tip.upper(), "SiO2", **adh)
    assert got == ref
    # the composite modulus of two half-spaces, written here: 1/E = 1/M1 + 1/M2
    assert got.modulus == pytest.approx(
        1 / (1 / TIP_INDENTATION_MODULI[tip] + 1 / (72e9 / 0.9711)), rel=1e-14
    )


def _docs_table(header_start):
    """The rows (cells) of the table of docs/sphere.md whose header starts so."""
    lines = (DOCS / "sphere.md").read_text(encoding="utf-8").splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith(header_start))
    rows = []
    for line in lines[start + 2 :]:
        if not line.startswith("|"):
            break
        rows.append([cell.strip() for cell in line.strip("|").split("|")])
    return rows


def _gpa(text):
    return float(text.replace("\N{MINUS SIGN}", "-"))


def test_the_docs_table_of_tip_presets_is_the_presets():
    rows = _docs_table("| preset |")
    assert [row[0].strip("`") for row in rows] == list(TIP_MATERIALS)
    for name, _, E, nu, M, reported, confirmed, _ in rows:
        m = MATERIALS[name.strip("`")]
        assert _gpa(E) * 1e9 == m.E and float(nu) == m.nu
        assert M == f"{m.indentation_modulus / 1e9:.1f}"
        low, high = reported.split("\N{EN DASH}")
        assert (float(low) * 1e9, float(high) * 1e9) == m.E_range
        assert confirmed == ("yes" if m.confirmed else "no")


def test_the_docs_table_of_tips_on_silica_is_computed():
    rows = _docs_table("| tip on `SiO2` |")
    assert [row[0].strip("`") for row in rows] == list(TIP_MATERIALS)
    w, R = 0.1, 20e-9
    for name, E, lam, force, over in rows:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            tip = Sphere.from_presets(
                R, name.strip("`"), "SiO2", work_of_adhesion=w, equilibrium_spacing=0.3e-9
            )
            F = tip.pull_off().pull_off_force
        assert E == f"{tip.modulus / 1e9:.1f}"
        assert lam == f"{tip.maugis_parameter:.3f}"
        assert _gpa(force) == round(F * 1e9, 3)
        assert _gpa(over) == round(F / (math.pi * w * R), 3)


# --------------------------------------------------------------------------------------------
# lookup


@pytest.mark.parametrize("given", ["ZnO", "zno", "ZNO", " ZnO "])
def test_from_name_is_case_insensitive(given):
    assert Material.from_name(given) is MATERIALS["ZnO"]


def test_from_name_of_every_preset():
    for name in material_names():
        assert Material.from_name(name.lower()).name == name


def test_unknown_name_lists_the_known_ones():
    with pytest.raises(ValueError, match="unknown material 'unobtainium'") as exc:
        Material.from_name("unobtainium")
    for name in material_names():
        assert name in str(exc.value)


# --------------------------------------------------------------------------------------------
# the SI layer


@pytest.mark.parametrize("pair", [("ZnO", "Si"), ("SiO2", "Si"), ("MWCNT-radial", "HOPG-basal")])
def test_from_presets_is_from_materials(pair):
    m1, m2 = (MATERIALS[n] for n in pair)
    adh = dict(work_of_adhesion=0.1, equilibrium_spacing=0.3e-9)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ref = Cylinder.from_materials(50e-9, m1.E, m1.nu, m2.E, m2.nu, **adh)
        assert Cylinder.from_presets(50e-9, *pair, **adh) == ref
        assert Cylinder.from_presets(50e-9, pair[0].upper(), m2, **adh) == ref
    sig = dict(cohesive_stress=1e8, adhesion_range=0.5e-9)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        assert Cylinder.from_presets(50e-9, m1, m2, **sig) == Cylinder.from_materials(
            50e-9, m1.E, m1.nu, m2.E, m2.nu, **sig
        )


def test_from_presets_warns_where_it_is_called():
    from linecontact import CouplingWarning

    with pytest.warns(CouplingWarning) as rec:
        Cylinder.from_presets(50e-9, "SiO2", "Si", work_of_adhesion=0.1, equilibrium_spacing=3e-10)
    assert rec[0].filename == __file__


def test_from_presets_unknown_name():
    with pytest.raises(ValueError, match="unknown material 'Zn'"):
        Cylinder.from_presets(50e-9, "Zn", "Si", work_of_adhesion=0.1, equilibrium_spacing=3e-10)


# --------------------------------------------------------------------------------------------
# the command line


def test_cli_presets_in_the_parameters_block(capsys):
    code, out, err = run(
        capsys,
        "pulloff",
        "--radius",
        "50e-9",
        "--cylinder-material",
        "SiO2",
        "--substrate-material",
        "Si",
        *ADH,
        "--json",
    )
    assert code == 0, err
    doc = json.loads(out)
    p = doc["parameters"]
    si, sio2 = MATERIALS["Si"], MATERIALS["SiO2"]
    assert p["cylinder_material"] == "SiO2" and p["cylinder_source"] == sio2.source
    assert p["substrate_material"] == "Si" and p["substrate_source"] == si.source
    assert (p["E1_Pa"], p["nu1"], p["E2_Pa"], p["nu2"]) == (sio2.E, sio2.nu, si.E, si.nu)
    assert doc["units"]["E1_Pa"] == "Pa" and doc["units"]["nu1"] == "1"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        cyl = Cylinder.from_materials(
            50e-9, sio2.E, sio2.nu, si.E, si.nu, work_of_adhesion=0.1, equilibrium_spacing=3e-10
        )
    assert p["modulus_Pa"] == cyl.modulus and p["dundurs_beta"] == cyl.dundurs_beta
    assert doc["results"][0]["F_pulloff_N_per_m"] == cyl.pull_off().pull_off_force


def test_cli_a_preset_for_one_body_explicit_moduli_for_the_other(capsys):
    code, out, err = run(
        capsys,
        "pulloff",
        "--radius",
        "50e-9",
        "--cylinder-material",
        "zno",
        "--E2",
        "160e9",
        "--nu2",
        "0.22",
        *ADH,
        "--json",
    )
    assert code == 0, err
    p = json.loads(out)["parameters"]
    assert p["cylinder_material"] == "ZnO" and "substrate_material" not in p
    assert (p["E1_Pa"], p["nu1"], p["E2_Pa"], p["nu2"]) == (124e9, 0.36, 160e9, 0.22)


def test_cli_presets_work_in_other_subcommands(capsys):
    code, out, err = run(
        capsys,
        "normal",
        "--radius",
        "50e-9",
        "--cylinder-material",
        "ZnO",
        "--substrate-material",
        "Si",
        *ADH,
        "--a",
        "2e-9",
        "--json",
    )
    assert code == 0, err
    assert json.loads(out)["parameters"]["substrate_material"] == "Si"


@pytest.mark.parametrize(
    "extra, message",
    [
        (
            ["--cylinder-material", "ZnO", "--E1", "100e9", "--substrate-material", "Si"],
            "give the cylinder either as --cylinder-material or as --E1 --nu1, not both",
        ),
        (
            ["--cylinder-material", "ZnO", "--substrate-material", "Si", "--nu2", "0.3"],
            "give the substrate either as --substrate-material or as --E2 --nu2, not both",
        ),
        (
            ["--cylinder-material", "ZnO", "--substrate-material", "Si", "--modulus", "1e10"],
            "give either --modulus or the materials (--cylinder-material, "
            "--substrate-material), not both",
        ),
        (
            ["--modulus", "1e10", "--substrate-material", "Si"],
            "give either --modulus or the materials",
        ),
        (
            ["--cylinder-material", "ZnO"],
            "SI inputs need --modulus, or the materials: --cylinder-material or --E1 --nu1, "
            "and --substrate-material or --E2 --nu2",
        ),
        (
            ["--cylinder-material", "ZnO", "--substrate-material", "unobtainium"],
            "--substrate-material 'unobtainium' is not a material preset: one of Si, SiO2,",
        ),
    ],
)
def test_cli_preset_errors_name_the_flags(capsys, extra, message):
    code, out, err = run(capsys, "pulloff", "--radius", "50e-9", *ADH, *extra)
    assert code == 2
    assert out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("linecontact pulloff: error: ")
    assert message in lines[0]


def test_cli_preset_counts_as_si_input(capsys):
    code, _, err = run(capsys, "pulloff", "--R-over-h", "100", "--cylinder-material", "ZnO")
    assert code == 2
    assert "give either the nondimensional groups" in err


def test_cli_materials_lists_every_preset(capsys):
    code, out, err = run(capsys, "materials", "--json")
    assert code == 0, err
    doc = json.loads(out)
    recs = doc["results"]
    assert [r["name"] for r in recs] == list(CITED)
    for r in recs:
        assert set(r) == {
            "name",
            "E_Pa",
            "nu",
            "E_low_Pa",
            "E_high_Pa",
            "description",
            "source",
            "confirmed",
        }
        m = MATERIALS[r["name"]]
        assert (r["E_Pa"], r["nu"], (r["E_low_Pa"], r["E_high_Pa"])) == (m.E, m.nu, m.E_range)
        assert (r["source"], r["description"], r["confirmed"]) == (
            m.source,
            m.description,
            m.confirmed,
        )
    assert doc["units"]["E_Pa"] == "Pa"


def test_cli_materials_by_name_table_and_csv(capsys, tmp_path):
    code, out, err = run(capsys, "materials", "zno", "Si")
    assert code == 0, err
    rows = [line.split()[0] for line in out.splitlines()[2:]]
    assert rows == ["ZnO", "Si"]
    assert MATERIALS["ZnO"].source in out
    code, _, err = run(capsys, "materials", "-o", str(tmp_path / "m.csv"), "--quiet")
    assert code == 0, err
    text = (tmp_path / "m.csv").read_text()
    assert "name,E_Pa,nu,E_low_Pa,E_high_Pa,description,source,confirmed" in text
    assert "\nHOPG-basal,25000000000.0,0.01," in text


def test_cli_materials_lists_the_tip_presets(capsys):
    code, out, err = run(capsys, "materials", "dlc", "TA-C", "SiNx-pecvd", "--format", "csv")
    assert code == 0, err
    rows = list(csv.reader(line for line in out.splitlines() if not line.startswith("#")))
    assert rows[0] == [
        "name",
        "E_Pa",
        "nu",
        "E_low_Pa",
        "E_high_Pa",
        "description",
        "source",
        "confirmed",
    ]
    assert [row[:5] for row in rows[1:]] == [
        ["DLC", "259000000000.0", "0.25", "100000000000.0", "259000000000.0"],
        ["ta-C", "759000000000.0", "0.17", "493000000000.0", "781000000000.0"],
        ["SiNx-PECVD", "150000000000.0", "0.25", "120000000000.0", "160000000000.0"],
    ]
    code, out, err = run(capsys, "materials")
    assert code == 0, err
    rows = [line.split()[0] for line in out.splitlines()[2:]]
    for name in TIP_MATERIALS:
        assert name in rows


def test_cli_materials_unknown_name(capsys):
    code, out, err = run(capsys, "materials", "unobtainium")
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and "'unobtainium' is not a material preset" in err
