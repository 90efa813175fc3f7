"""linecontact: adhesive contact mechanics of a cylinder on an elastic substrate.

The public API, in the paper's nondimensional groups (lengths over ``R``, force per unit
length over ``E h``, stresses over ``E``; compressive load positive):

- :func:`normal_contact`, :func:`contact_for_load`, :func:`equilibria`, :func:`non_contact`,
  :func:`pull_off`, :func:`load_curve` -- normal loading with Maugis--Dugdale adhesion;
- :func:`sliding_initiation`, :func:`steady_rolling` (and their ``_coulomb`` counterparts)
  -- tangential loading with a constant friction stress (:mod:`linecontact.tangential`;
  forces over ``E a``); :func:`tangential_history`, :func:`cyclic_loss` (and their
  ``_coulomb`` counterparts) -- load histories with memory and the loss per cycle;
- :func:`sliding_contact`, :func:`sliding_contact_for_load`, :func:`sliding_pull_off` --
  steady sliding with different trailing and leading adhesion (:mod:`linecontact.sliding`);
- :mod:`linecontact.laws` -- in the paper's groups a law is a module: ``laws.dugdale`` and
  ``laws.lennard_jones`` have the same ``pull_off``, ``contact_for_load`` and ``load_curve``
  (the Lennard-Jones law of Eq. 1); in SI units a value: :class:`Dugdale`,
  :class:`LennardJones`, the ``adhesion`` of a :class:`Cylinder`;
- :func:`facet_contact`, :func:`facet_contact_for_load`, :func:`facet_pull_off`,
  :func:`facet_load_curve` -- a faceted
  wire (a regular polygon with rounded corners) on its facet (:mod:`linecontact.facet`); in SI
  units the :class:`Cylinder` with ``cross_section=Polygon(sides, corner_radius)``
  (:mod:`linecontact.geometry`: :class:`Round`, :class:`Polygon`);
- :func:`sphere_contact`, :func:`sphere_contact_for_load`, :func:`sphere_pull_off`,
  :func:`sphere_load_curve` -- the Maugis--Dugdale sphere (an AFM tip, a colloidal probe:
  :mod:`linecontact.sphere`, force over ``E h R``); in SI units the :class:`Sphere` (forces
  in N), a :class:`Body` as the :class:`Cylinder` is; :func:`sphere_lj_pull_off`,
  :func:`sphere_lj_curve` -- the self-consistent Lennard-Jones sphere (Greenwood 1997);
- :mod:`linecontact.closed_forms` -- closed forms (Hertz, JKR, Maugis--Dugdale, Eq. 14; the
  sphere's Hertz, JKR, DMT);
- :mod:`linecontact.sie` -- the Gauss--Chebyshev singular-integral core;
- :func:`fit_pull_off`, :func:`work_of_adhesion_from_pull_off`,
  :func:`shear_strength_from_friction`, :func:`propagate` -- from measurements to properties
  with uncertainty (:mod:`linecontact.inverse`); :class:`Material` -- presets with sources;
- :class:`Cylinder` -- the SI layer (materials, adhesion a law value or (sigma0, h) or
  (w, z0)), one method per problem (``contact``, ``pull_off``, ``load_curve``, ``sliding``,
  ``sliding_initiation``, ``steady_rolling``, ``push``, ``tangential_history``,
  ``cyclic_loss``), each solved under the cylinder's law or refused naming both;
- :mod:`linecontact.output` -- results to JSON, JSON Lines, CSV or tables, with provenance;
  :func:`read` -- any of those files back as a ``pandas.DataFrame`` (provenance in ``.attrs``);
- :func:`sweep`, :func:`open_sweep` -- parameter studies: a subcommand over every combination
  of its flags' values, as an ``xarray.Dataset``, resumable, on Dask
  (:mod:`linecontact.sweeps`; the extra ``[sweep]``).
"""

# Ctrl-C during these imports (about a second) ends the command line with status 130 and
# one line, no traceback (linecontact._interrupt); a library user gets KeyboardInterrupt
from ._interrupt import imports_interruptible as _imports_interruptible

with _imports_interruptible():
    from . import _moved, laws
    from ._version import __version__
    from .bent_wire import (
        BentWireFit,
        DraggedWire,
        NormalFriction,
        StaticWire,
        bending_stiffness,
        dragged_wire,
        fit_bent_wire,
        normal_friction_from_curvature,
        second_moment_of_area,
        static_wire,
    )
    from .closed_forms import hertz_load, jkr_load, kappa, maugis_parameter, zero_width_load
    from .cylinder import Body, Cylinder, Sphere
    from .errors import ConvergenceError, CouplingWarning, ModelValidityWarning, NoEquilibriumError
    from .facet import (
        FacetContact,
        FacetLoadCurve,
        FacetPullOff,
        FacetTipping,
        facet_contact,
        facet_contact_for_load,
        facet_load_curve,
        facet_pull_off,
        facet_tipping,
    )
    from .geometry import Polygon, Round
    from .inverse import (
        fit_pull_off,
        propagate,
        shear_strength_from_bent_wire,
        shear_strength_from_friction,
        sphere_shear_strength_from_friction,
        sphere_work_of_adhesion_from_pull_off,
        work_of_adhesion_from_pull_off,
        work_of_adhesion_from_width,
    )
    from .laws import Dugdale, LennardJones
    from .materials import (
        adhesion_from_work,
        compliance_constants,
        composite_modulus,
        dundurs_beta,
    )
    from .measurements import read_measurements
    from .normal import (
        NormalContact,
        PullOff,
        contact_for_load,
        equilibria,
        load_curve,
        non_contact,
        normal_contact,
        pull_off,
    )
    from .presets import Material
    from .push import Push, TipPush, push, tip_push
    from .reading import read
    from .sliding import (
        SlidingContact,
        SlidingPullOff,
        sliding_contact,
        sliding_contact_for_load,
        sliding_pull_off,
    )
    from .sphere import (
        SphereAdhesionFit,
        SphereContact,
        SphereLJCurve,
        SphereLJPullOff,
        SphereLoadCurve,
        SphereModelChoice,
        SphereModels,
        SpherePullOff,
        SphereShearStrengthFit,
        cos_alpha,
        maugis_parameter_of_cos_alpha,
        sphere_contact,
        sphere_contact_for_load,
        sphere_fit_pull_off,
        sphere_fit_shear_strength,
        sphere_lj_curve,
        sphere_lj_pull_off,
        sphere_load_curve,
        sphere_models,
        sphere_pull_off,
        sphere_which_model,
    )
    from .sweeps import open_sweep, sweep
    from .tangential import (
        cyclic_loss,
        cyclic_loss_coulomb,
        sliding_initiation,
        sliding_initiation_coulomb,
        steady_rolling,
        steady_rolling_coulomb,
        tangential_history,
        tangential_history_coulomb,
    )

__all__ = [
    "BentWireFit",
    "DraggedWire",
    "NormalFriction",
    "StaticWire",
    "bending_stiffness",
    "dragged_wire",
    "fit_bent_wire",
    "normal_friction_from_curvature",
    "second_moment_of_area",
    "shear_strength_from_bent_wire",
    "static_wire",
    "Body",
    "Sphere",
    "SphereContact",
    "SphereLoadCurve",
    "SpherePullOff",
    "sphere_contact",
    "sphere_contact_for_load",
    "sphere_load_curve",
    "sphere_pull_off",
    "SphereModels",
    "SphereLJCurve",
    "SphereLJPullOff",
    "sphere_lj_curve",
    "sphere_lj_pull_off",
    "sphere_shear_strength_from_friction",
    "sphere_work_of_adhesion_from_pull_off",
    "cos_alpha",
    "maugis_parameter_of_cos_alpha",
    "sphere_models",
    "sphere_fit_pull_off",
    "sphere_fit_shear_strength",
    "sphere_which_model",
    "SphereAdhesionFit",
    "SphereShearStrengthFit",
    "SphereModelChoice",
    "ConvergenceError",
    "Material",
    "CouplingWarning",
    "Cylinder",
    "Dugdale",
    "FacetContact",
    "FacetLoadCurve",
    "FacetPullOff",
    "FacetTipping",
    "LennardJones",
    "ModelValidityWarning",
    "NoEquilibriumError",
    "NormalContact",
    "Polygon",
    "PullOff",
    "Push",
    "Round",
    "SlidingContact",
    "SlidingPullOff",
    "TipPush",
    "__version__",
    "adhesion_from_work",
    "compliance_constants",
    "composite_modulus",
    "contact_for_load",
    "cyclic_loss",
    "cyclic_loss_coulomb",
    "dundurs_beta",
    "equilibria",
    "facet_contact",
    "facet_contact_for_load",
    "facet_load_curve",
    "facet_pull_off",
    "facet_tipping",
    "fit_pull_off",
    "hertz_load",
    "jkr_load",
    "kappa",
    "laws",
    "load_curve",
    "maugis_parameter",
    "non_contact",
    "normal_contact",
    "open_sweep",
    "pull_off",
    "propagate",
    "read",
    "read_measurements",
    "push",
    "sliding_contact",
    "sliding_contact_for_load",
    "sliding_initiation",
    "sliding_initiation_coulomb",
    "shear_strength_from_friction",
    "sliding_pull_off",
    "steady_rolling",
    "steady_rolling_coulomb",
    "sweep",
    "tangential_history",
    "tangential_history_coulomb",
    "tip_push",
    "work_of_adhesion_from_pull_off",
    "work_of_adhesion_from_width",
    "zero_width_load",
]

# the names deleted before 1.0: their errors name the replacement (linecontact._moved)
_moved.install_finder()


def __getattr__(name: str) -> object:
    return _moved.resolve(__name__, name)
