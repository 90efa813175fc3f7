"""Material presets: the cited numbers, the lookup, the SI layer and the command line."""

import dataclasses
import json
import re
import warnings

import pytest

from linecontact import Cylinder
from linecontact.cli import main
from linecontact.presets import MATERIALS, Material, material_names

#: The cited numbers, written out: (E [Pa], nu, (E low, E high) [Pa], confirmed by search).
#: A silent change of a preset fails here; change both with the source.
CITED = {
    "Si": (163e9, 0.22, (130e9, 188e9), False),
    "SiO2": (72e9, 0.17, (60e9, 80e9), False),
    "Si3N4": (222e9, 0.28, (200e9, 310e9), True),
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


def test_cli_materials_unknown_name(capsys):
    code, out, err = run(capsys, "materials", "unobtainium")
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and "'unobtainium' is not a material preset" in err
