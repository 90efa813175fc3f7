"""Closed-form line-contact solutions in the paper's groups, one module per model.

Units and scaling (stated once for the whole library): lengths in units of the cylinder
radius ``R`` (``a/R``, ``c/R``), the force per unit length in units of ``E h``
(``F/(E h)``), stresses in units of the composite modulus ``E`` (``sigma0/E``), with
``1/E = (1 - nu1**2)/E1 + (1 - nu2**2)/E2`` and ``h`` the range of the Dugdale stress
``sigma0`` (work of adhesion ``w = sigma0 h``). Compressive pressure and compressive load are
positive, so adhesive (pull-off) forces are negative.

- :mod:`~linecontact.closed_forms.hertz` -- Hertz, Eq. (13), and ``A_OVER_R_SMALL_STRAIN``
  (Johnson 1985, doi:10.1017/CBO9781139171731);
- :mod:`~linecontact.closed_forms.jkr` -- JKR line contact and the rigid pull-off
  (Chaudhury et al. 1996, doi:10.1063/1.362819);
- :mod:`~linecontact.closed_forms.zero_width` -- the load at vanishing width, Eq. (14);
- :mod:`~linecontact.closed_forms.maugis_dugdale` -- the Maugis--Dugdale line contact of Baney
  & Hui (doi:10.1163/156856197X00796) and Johnson & Greenwood
  (doi:10.1088/0022-3727/41/15/155315) in overflow-free scaled form;
- :mod:`~linecontact.closed_forms.groups` -- ``kappa``, the Maugis parameter, ``KAPPA_MAX``;
- :mod:`~linecontact.closed_forms.lennard_jones_rigid` -- the Lennard-Jones law of Eq. (1) on
  a rigid cylinder.

Each closed form and group is written once, in its module (``tests/test_once.py``). This
package re-exports the public names and the private ones that the solvers import.
"""

from __future__ import annotations

from .groups import (
    KAPPA_MAX,
    kappa,
    maugis_parameter,
)
from .groups import (
    _check_kappa as _check_kappa,
)
from .groups import (
    _kappa as _kappa,
)
from .groups import (
    _maugis_parameter as _maugis_parameter,
)
from .hertz import (
    A_OVER_R_SMALL_STRAIN,
    hertz_load,
)
from .hertz import (
    _hertz as _hertz,
)
from .hertz import (
    _hertz_half_width as _hertz_half_width,
)
from .hertz import (
    _warn_wide as _warn_wide,
)
from .jkr import (
    _jkr as _jkr,
)
from .jkr import (
    _jkr_half_width as _jkr_half_width,
)
from .jkr import (
    _jkr_pull_off as _jkr_pull_off,
)
from .jkr import (
    _rigid_pull_off as _rigid_pull_off,
)
from .jkr import (
    _strip_pull_off as _strip_pull_off,
)
from .jkr import (
    jkr_load,
)
from .lennard_jones_rigid import (
    lennard_jones_rigid_load,
    lennard_jones_rigid_pull_off,
)
from .maugis_dugdale import (
    LN2 as LN2,
)
from .maugis_dugdale import (
    _branch_point as _branch_point,
)
from .maugis_dugdale import (
    _f1_series as _f1_series,
)
from .maugis_dugdale import (
    _kappa_stationary as _kappa_stationary,
)
from .maugis_dugdale import (
    _scaled as _scaled,
)
from .maugis_dugdale import (
    _solve_abar as _solve_abar,
)
from .maugis_dugdale import (
    _u_guess as _u_guess,
)
from .maugis_dugdale import (
    _u_of_abar as _u_of_abar,
)
from .maugis_dugdale import (
    _u_stationary as _u_stationary,
)
from .zero_width import (
    _zero_width as _zero_width,
)
from .zero_width import (
    zero_width_load,
)

__all__ = [
    "A_OVER_R_SMALL_STRAIN",
    "KAPPA_MAX",
    "hertz_load",
    "jkr_load",
    "kappa",
    "lennard_jones_rigid_load",
    "lennard_jones_rigid_pull_off",
    "maugis_parameter",
    "zero_width_load",
]
