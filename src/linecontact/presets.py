r"""Material presets: Young's modulus and Poisson's ratio of common bodies, with sources.

Each :class:`Material` holds an isotropic-equivalent pair ``(E, nu)`` for a contact loaded
normal to the surface: in the line contact of a cylinder on a substrate (Eq. 7 of the paper)
only the indentation (plane-strain) modulus

.. math::

    M = \frac{E}{1-\nu^2}

of each body enters the composite modulus, and ``nu`` alone only through Dundurs' ``beta``.
For an isotropic body (amorphous SiO2, Si3N4 films, glassy polymers, untextured
polycrystals) ``E`` and ``nu`` are the usual ones. For a single crystal the directional
Young's modulus normal to the surface is *not* the right number (Si(100): ``E<100>`` is
130 GPa but ``M`` is 165 GPa): the presets of cubic and wurtzite crystals are the
Voigt-Reuss-Hill averages of the cited elastic constants, whose ``E/(1-nu^2)`` is within
about 5% of the indentation modulus of every common facet.

The layered crystals are strongly anisotropic, and there the preset depends on the face:

- ``"mica"`` and ``"HOPG-basal"`` are for a contact *normal to the planes*: a fibre lying on
  a cleaved mica or graphite sheet. Their ``nu`` is the physical ``nu31`` and
  ``E = M (1 - nu^2)`` with ``M`` the indentation modulus of the basal plane computed from the
  cited elastic constants.
- ``"mica-in-plane"`` and ``"HOPG-in-plane"`` are the Young's moduli *within* the basal plane
  (for stretching or bending a sheet). They are **not** contact moduli; not even for a
  contact on an edge face, whose indentation modulus is far lower.

The tips of AFM probes and colloidal probes are listed in :data:`TIP_MATERIALS`. Most are
films or coatings whose modulus depends on how they were deposited: LPCVD ``"Si3N4"`` is
stiffer than ``"SiNx-PECVD"``, and hydrogenated diamond-like carbon (``"DLC"``, a-C:H) has
about a third of the modulus of hydrogen-free tetrahedral amorphous carbon (``"ta-C"``). A
coating is a half-space only where it is much thicker than the contact radius; a thinner one
shares the load with what lies under it (silicon, for most coated tips).

``E_range`` records where the values scatter (crystal orientation, film deposition, purity,
size effects); ``source`` the citation; ``confirmed`` whether the number (or the elastic
constants it was computed from) was seen in a source found by a literature search. The
citations marked unconfirmed are standard values quoted from memory; their DOIs and some of
the Poisson ratios (marked nominal in the description) have not been checked against the
original. A preset never hides its numbers: the command line writes the moduli used and
their source into the output's ``parameters`` block.

Examples
--------
>>> zno = Material.from_name("zno")
>>> zno.name, zno.E, zno.nu
('ZnO', 124000000000.0, 0.36)
>>> round(zno.indentation_modulus / 1e9, 1)
142.5
>>> "SiO2" in material_names()
True
>>> [Material.from_name(name).name for name in ("dlc", "TA-C", "sinx-pecvd")]
['DLC', 'ta-C', 'SiNx-PECVD']
>>> [name for name in TIP_MATERIALS if MATERIALS[name].E > 200e9]
['Si3N4', 'DLC', 'ta-C']
"""

from __future__ import annotations

import types
from collections.abc import Mapping
from dataclasses import dataclass

__all__ = ["MATERIALS", "TIP_MATERIALS", "Material", "material_names"]


@dataclass(frozen=True)
class Material:
    """An elastic body: isotropic-equivalent Young's modulus and Poisson's ratio, with a source.

    Attributes
    ----------
    name : str
        The preset's name (``"ZnO"``, ``"HOPG-basal"``, ...).
    E : float
        Young's modulus [Pa], isotropic equivalent for a contact normal to the surface.
    nu : float
        Poisson's ratio.
    E_range : tuple of float
        ``(low, high)`` [Pa]: where the reported values scatter.
    description : str
        What the value is for, how it was obtained, and its caveats.
    source : str
        The citation(s) of the value.
    confirmed : bool
        Whether the value (or the elastic constants it was computed from) was seen in a
        source found by a literature search; False: a standard value cited from memory.

    Examples
    --------
    >>> si = Material.from_name("Si")
    >>> si.E, si.nu, si.E_range
    (163000000000.0, 0.22, (130000000000.0, 188000000000.0))
    """

    name: str
    E: float
    nu: float
    E_range: tuple[float, float]
    description: str = ""
    source: str = ""
    confirmed: bool = False

    @property
    def indentation_modulus(self) -> float:
        """``E/(1 - nu^2)`` [Pa]: the plane-strain modulus that a normal contact sees."""
        return self.E / (1.0 - self.nu**2)

    @classmethod
    def from_name(cls, name: str) -> Material:
        """The preset called ``name`` (case-insensitive).

        Parameters
        ----------
        name : str
            One of :func:`material_names`.

        Returns
        -------
        Material

        Raises
        ------
        ValueError
            If there is no such preset (the message lists the known names).

        Examples
        --------
        >>> Material.from_name("hopg-BASAL").name
        'HOPG-basal'
        """
        key = _BY_LOWER.get(str(name).strip().lower())
        if key is None:
            raise ValueError(
                f"unknown material {name!r}: one of {', '.join(MATERIALS)} "
                "(linecontact materials lists them)"
            )
        return MATERIALS[key]


def _m(
    name: str,
    E: float,
    nu: float,
    E_range: tuple[float, float],
    description: str,
    source: str,
    confirmed: bool,
) -> tuple[str, Material]:
    return name, Material(name, E, nu, E_range, description, source, confirmed)


_VAUGHAN = (
    "M. T. Vaughan, S. Guggenheim, J. Geophys. Res. 91(B5) (1986) 4657-4664. "
    "doi:10.1029/JB091iB05p04657"
)
_BLAKSLEE = (
    "O. L. Blakslee, D. G. Proctor, E. J. Seldin, G. B. Spence, T. Weng, J. Appl. Phys. 41 "
    "(1970) 3373-3382"
)
_NEIGHBOURS = "J. R. Neighbours, G. A. Alers, Phys. Rev. 111 (1958) 707-712"

#: The presets by name (read-only), in the order of the table of ``linecontact materials``.
MATERIALS: Mapping[str, Material] = types.MappingProxyType(
    dict(
        [
            _m(
                "Si",
                163e9,
                0.22,
                (130e9, 188e9),
                "Single-crystal Si, isotropic equivalent (Voigt-Reuss-Hill average of "
                "C11=165.7, C12=63.9, C44=79.6 GPa); E/(1-nu^2)=171 GPa vs indentation modulus "
                "M=165 (100), 173 (110), 175 GPa (111). Directional E: 130 <100>, 169 <110>, "
                "188 <111>. Polysilicon in tension: 169+-6 GPa, nu 0.22+-0.01 (W. N. Sharpe Jr., "
                "B. Yuan, R. Vaidyanathan, R. L. Edwards, Proc. IEEE MEMS 1997, 424-429). The "
                "tip of a silicon AFM probe (with its native oxide).",
                "M. A. Hopcroft, W. D. Nix, T. W. Kenny, J. Microelectromech. Syst. 19 (2010) "
                "229-238. doi:10.1109/JMEMS.2009.2039697",
                False,
            ),
            _m(
                "SiO2",
                72e9,
                0.17,
                (60e9, 80e9),
                "Amorphous SiO2: fused silica / thermal oxide (isotropic). PECVD/sputtered "
                "oxides scatter more.",
                "K. E. Petersen, Proc. IEEE 70 (1982) 420-457 (SiO2 ~73 GPa), "
                "doi:10.1109/PROC.1982.12331; cf. H. Ni, X. Li, H. Gao, Appl. Phys. Lett. 88 "
                "(2006) 043108 (a-SiO2 nanowires 76.6+-7.2 GPa, 'close to bulk and thermal "
                "SiO2').",
                False,
            ),
            _m(
                "Si3N4",
                222e9,
                0.28,
                (200e9, 310e9),
                "LPCVD silicon nitride thin film (amorphous, isotropic); bulge test 222+-3 GPa, "
                "nu 0.28+-0.05; nanoindentation 216+-10 GPa. Stoichiometric / low-stress films "
                "and bulk ceramic can be up to ~300 GPa. The LPCVD nitride of commercial AFM "
                "cantilevers and tips: 280-290 GPa, nu 0.20 by surface acoustic waves and "
                "cantilever resonances (A. Khan, J. Philip, P. Hess, J. Appl. Phys. 95 (2004) "
                "1667-1672, doi:10.1063/1.1638886). PECVD nitride is softer: 'SiNx-PECVD'.",
                "J. J. Vlassak, W. D. Nix, J. Mater. Res. 7 (1992) 3242-3249. "
                "doi:10.1557/JMR.1992.3242",
                True,
            ),
            _m(
                "SiNx-PECVD",
                150e9,
                0.25,
                (120e9, 160e9),
                "Plasma-enhanced CVD silicon nitride (amorphous SiNx:H, isotropic), for a tip "
                "or cantilever of PECVD nitride: nanoindentation of a 218 nm film on Si ~150 "
                "GPa (hardness 19 GPa); N-rich plasma films deposited at 150-300 C gave "
                "reduced moduli 120-160 GPa (an abstract; its citation not checked). Stiffer "
                "with deposition temperature, plasma power and density. nu 0.23-0.25 for "
                "low-temperature PECVD films (double-membrane bulge test). The ~150 GPa may be "
                "an indentation modulus (E/(1-nu^2) = 1.07 E).",
                "'Mechanical properties of PECVD thin ceramic films', J. Eur. Ceram. Soc. 30 "
                "(2010) 689-697, doi:10.1016/j.jeurceramsoc.2009.09.020 (authors not checked); "
                "nu: 'Poisson's ratio of low-temperature PECVD silicon nitride thin films' "
                "(Univ. of Western Australia; authors and journal not checked)",
                True,
            ),
            _m(
                "DLC",
                259e9,
                0.25,
                (100e9, 259e9),
                "Diamond-like carbon, hydrogenated amorphous carbon a-C:H (20 at.% H, hardness "
                "27 GPa): a hard DLC coating. DLC-coated AFM tips rarely state their film; a-C:H "
                "depends on its hydrogen and sp3 content: 133-213 GPa for dc-plasma DLC from "
                "benzene (Dorner et al., Wear 249 (2001) 489), below 100 GPa for soft, "
                "polymer-like films (surface acoustic waves, Phys. Status Solidi A 145 (1994) "
                "385). "
                "Hydrogen-free ta-C is far stiffer: 'ta-C'. nu nominal.",
                "V. R. Salinas Ruiz, T. Kuwahara, J. Galipaud, K. Masenelli-Varlot, M. Ben "
                "Hassine, C. Heau, M. Stoll, L. Mayrhofer, G. Moras, J. M. Martin, M. Moseler, "
                "M.-I. de Barros Bouchet, Nat. Commun. 12 (2021) 4550, Table 1. "
                "doi:10.1038/s41467-021-24766-6",
                True,
            ),
            _m(
                "ta-C",
                759e9,
                0.17,
                (493e9, 781e9),
                "Tetrahedral amorphous carbon (hydrogen-free, sp3-rich diamond-like carbon, "
                "isotropic): uniaxial tension of 1.5 um thick ta-C MEMS specimens with AFM "
                "digital image correlation, E 759+-22 GPa, nu 0.17+-0.03. Arc-deposited ta-C "
                "coatings 493-625 GPa, rising with the sp3 fraction (Salinas Ruiz et al., Nat. "
                "Commun. 12 (2021) 4550). Hydrogenated DLC is softer: 'DLC'.",
                "S. Cho, I. Chasiotis, T. A. Friedmann, J. P. Sullivan, J. Micromech. Microeng. "
                "15 (2005) 728-735. doi:10.1088/0960-1317/15/4/009",
                True,
            ),
            _m(
                "Al2O3",
                403e9,
                0.23,
                (345e9, 461e9),
                "Sapphire (alpha-Al2O3), isotropic equivalent (VRH of Wachtman C_ij); "
                "E/(1-nu^2)=426 GPa vs M=431 GPa on c-plane (0001), 432 on a/m-planes. "
                "Directional E: 425 (in basal plane) to 461 GPa (along c).",
                "J. B. Wachtman Jr., W. E. Tefft, D. G. Lam Jr., R. P. Stinchfield, J. Res. "
                "Natl. Bur. Stand. 64A (1960) 213-228. doi:10.6028/jres.064A.022",
                True,
            ),
            _m(
                "Al2O3-poly",
                416e9,
                0.231,
                (300e9, 416e9),
                "Dense (>=98%), high-purity (>=99.5%) sintered polycrystalline alpha-alumina "
                "at 20 C, 416(30) GPa. Lower-purity (96%) alumina ~300-370 GPa. nu not checked "
                "against the source.",
                "R. G. Munro, J. Am. Ceram. Soc. 80 (1997) 1919-1928. "
                "doi:10.1111/j.1151-2916.1997.tb03074.x (NIST SRD 150)",
                True,
            ),
            _m(
                "mica",
                54e9,
                0.10,
                (50e9, 60e9),
                "Muscovite, contact NORMAL to the cleavage (001) plane (a fibre on a cleaved "
                "mica sheet). Indentation modulus from the 13 C_ij: M=54.7 GPa "
                "(E_3=1/s33=53.4 GPa, C33=58.6); nu~0.1 (nu31=0.08-0.13). In-plane E is ~3x "
                "larger (see 'mica-in-plane').",
                _VAUGHAN,
                True,
            ),
            _m(
                "mica-in-plane",
                155e9,
                0.25,
                (149e9, 161e9),
                "Muscovite Young's modulus WITHIN the basal plane (1/s11=149, 1/s22=161 GPa). "
                "For stretching/bending of a mica sheet, not a contact modulus (indentation "
                "modulus on an edge face ~128-129 GPa). nu nominal.",
                _VAUGHAN,
                True,
            ),
            _m(
                "HOPG-basal",
                25e9,
                0.01,
                (5e9, 38.7e9),
                "HOPG, contact NORMAL to the basal planes (a fibre lying on cleaved HOPG). "
                "Isotropic equivalent chosen so E/(1-nu^2) equals the transversely-isotropic "
                "indentation modulus M = 24-27 GPa (C33=36.5-38.7, C44=4-5 GPa). NOT C33: the "
                "contact modulus depends strongly on C44; with the dislocation-softened "
                "C44=0.18-0.35 GPa of as-grown HOPG, M drops to 5-7 GPa. nu31 of graphite ~0.01.",
                "Computed from A. Bosak, M. Krisch, M. Mohr, J. Maultzsch, C. Thomsen, Phys. "
                "Rev. B 75 (2007) 153408 (C11=1109, C12=139, C13=0, C33=38.7, C44=4.95 GPa), "
                f"doi:10.1103/PhysRevB.75.153408; and {_BLAKSLEE}, doi:10.1063/1.1659426",
                True,
            ),
            _m(
                "HOPG-in-plane",
                1.02e12,
                0.17,
                (1.0e12, 1.09e12),
                "Graphite Young's modulus PARALLEL to the basal planes, 1/s11 (C11=1060 GPa "
                "Blakslee; 1109 Bosak); nu12~0.17 (0.13-0.17). Axial/in-plane stiffness, NOT a "
                "contact modulus: the indentation modulus on an edge (prismatic) face is only "
                "~0.3-0.5 TPa.",
                f"{_BLAKSLEE}. doi:10.1063/1.1659426",
                False,
            ),
            _m(
                "Au",
                79e9,
                0.42,
                (43e9, 117e9),
                "Gold, polycrystalline (untextured) isotropic value (VRH of C11=192, C12=163, "
                "C44=42 GPa -> 78.6 GPa, nu 0.42). Strongly anisotropic: E<100>=43, "
                "E<111>=117 GPa; (111)-textured films: M=100 GPa vs E/(1-nu^2)=96.",
                f"{_NEIGHBOURS} (single-crystal C_ij of Ag and Au), doi:10.1103/PhysRev.111.707",
                False,
            ),
            _m(
                "Ag",
                82e9,
                0.37,
                (44e9, 121e9),
                "Silver, polycrystalline isotropic value (VRH of C11=124, C12=93.4, C44=46.1 "
                "GPa -> 81 GPa, nu 0.37; handbooks 83 GPa). E<100>=44, E<111>=120 GPa.",
                f"{_NEIGHBOURS}, doi:10.1103/PhysRev.111.707",
                False,
            ),
            _m(
                "Cu",
                128e9,
                0.34,
                (67e9, 191e9),
                "Copper, polycrystalline isotropic value (VRH of C11=168.4, C12=121.4, "
                "C44=75.4 GPa -> 127 GPa, nu 0.345). E<100>=67, E<111>=191 GPa; handbook "
                "polycrystal 115-130 GPa.",
                "W. C. Overton Jr., J. Gaffney, Phys. Rev. 98 (1955) 969-977, "
                "doi:10.1103/PhysRev.98.969",
                False,
            ),
            _m(
                "ZnO",
                124e9,
                0.36,
                (111e9, 145e9),
                "Wurtzite ZnO bulk, isotropic equivalent (VRH of C11=209.7, C12=121.1, "
                "C13=105.1, C33=210.9, C44=42.5 GPa); E/(1-nu^2)=142 GPa vs M=141 (m/a-plane "
                "side facet of a c-axis nanowire), 146 (c-plane). Axial E along c = 144 GPa "
                "('bulk 140 GPa' of the nanowire literature). Nanowire values scatter widely "
                "(tens to >200 GPa).",
                "I. B. Kobiakov, Solid State Commun. 35 (1980) 305-310 (C_ij); cf. S. O. "
                "Kucheyev et al., Appl. Phys. Lett. 80 (2002) 956, doi:10.1063/1.1448175 "
                "(c-plane nanoindentation 111+-5 GPa)",
                False,
            ),
            _m(
                "InAs",
                76e9,
                0.28,
                (51e9, 97e9),
                "Zinc-blende InAs, isotropic equivalent (VRH of C11=83.3, C12=45.3, C44=39.6 "
                "GPa); E/(1-nu^2)=82 GPa vs M=78 (100), 83 (110 side facet of <111> wires), 85 "
                "(111). Directional E: 51 <100>, 79 <110>, 97 <111>.",
                "D. Gerlich, J. Appl. Phys. 34 (1963) 2915 (C_ij of InAs); values as tabulated "
                "in Ioffe/matprop 'NSM archive' (C11=8.34, C12=4.54, C44=3.95 x10^11 dyn/cm^2)",
                True,
            ),
            _m(
                "GaN",
                303e9,
                0.26,
                (280e9, 360e9),
                "Wurtzite GaN, isotropic equivalent (VRH of C11=390, C12=145, C13=106, "
                "C33=398, C44=105 GPa); E/(1-nu^2)=325 GPa vs M=330 (c-plane), 329 "
                "(a/m-plane). Directional E: 324 (in basal plane) to 356 GPa (along c). "
                "Nanoindentation reports ~280-300 GPa.",
                "A. Polian, M. Grimsditch, I. Grzegory, J. Appl. Phys. 79 (1996) 3343-3344. "
                "doi:10.1063/1.361236",
                True,
            ),
            _m(
                "MWCNT-radial",
                30e9,
                0.2,
                (10e9, 80e9),
                "Multi-wall CNT RADIAL (transverse) Young's modulus from AFM indentation + "
                "Hertz; strongly radius dependent, decreasing with radius to an asymptotic "
                "30+-10 GPa for large tubes (outer radius >~ 5 nm). The axial modulus (~1 TPa) "
                "is irrelevant for transverse contact. nu nominal.",
                "I. Palaci, S. Fedrigo, H. Brune, C. Klinke, M. Chen, E. Riedo, Phys. Rev. "
                "Lett. 94 (2005) 175502. doi:10.1103/PhysRevLett.94.175502",
                True,
            ),
            _m(
                "polystyrene",
                3.2e9,
                0.34,
                (2.3e9, 4.1e9),
                "Bulk glassy atactic polystyrene at room temperature (quasi-static). "
                "Electrospun PS fibres scatter widely and can be much softer; viscoelastic, "
                "rate/temperature dependent.",
                "J. E. Mark (ed.), Physical Properties of Polymers Handbook, 2nd ed., Springer "
                "(2007) (typical 3.0-3.5 GPa); handbook range 2.3-4.1 GPa",
                False,
            ),
            _m(
                "nylon-6",
                2.9e9,
                0.39,
                (2.6e9, 3.2e9),
                "Nylon-6, dry, bulk tensile modulus; moisture reduces E substantially (to ~1 "
                "GPa when conditioned); drawn fibres are anisotropic (higher axial E). nu "
                "nominal.",
                "N. E. Dowling, Mechanical Behavior of Materials, 4th ed., Pearson (2013), "
                "Table 4.3 (nylon 6, dry: 2.6-3.2 GPa)",
                True,
            ),
        ]
    )
)

_BY_LOWER = {name.lower(): name for name in MATERIALS}

#: The presets of common AFM tips and colloidal probes, in table order: silicon (with its
#: native oxide), silica (oxidised tips, colloidal spheres), LPCVD and PECVD silicon
#: nitride, and diamond-like carbon (hydrogenated and tetrahedral amorphous carbon).
TIP_MATERIALS: tuple[str, ...] = ("Si", "SiO2", "Si3N4", "SiNx-PECVD", "DLC", "ta-C")


def material_names() -> tuple[str, ...]:
    """The names of the presets, in table order.

    Returns
    -------
    tuple of str
    """
    return tuple(MATERIALS)
