"""One collision, end to end: the public entry point used by the CLI and by studies.

``collide(params)`` picks the film grid for the parameters, builds the elasticity (the
half-space kernel or the FE solids, unless a compliance is passed in), integrates the normal
motion (:mod:`ehdfem.motion.normal`) and, for an oblique impact, the tangential motion
(:mod:`ehdfem.tangential.motion`). Inputs and outputs are dimensionless (see
:mod:`ehdfem.inputs.scales`).
"""

from __future__ import annotations

import warnings
from dataclasses import asdict, dataclass, replace

import numpy as np

from . import checks
from .config import DEFAULT_NODES, MODELS, RunConfig, curved_lower_sliding
from .exact import hertz
from .film import cavitation, viscosity
from .film.grid import AXIS_SPACING, OUTLET_RADIUS, RIM_SPACING, contact_grid
from .film.viscosity import ViscosityRangeWarning, barus_range_warning
from .inputs.scales import CollisionParameters, PhysicalCollision
from .motion.forces import SphereForce
from .motion.normal import FilmClosedError, NormalResult, NormalSolverError, solve_normal
from .motion.normal_problem import normal_problem
from .outputs import plausibility, provenance
from .outputs import registry as outputs
from .outputs.plausibility import ResultRangeWarning
from .solids.compliance import Compliance, ModeOneCompliance, default_shear_traction
from .solids.halfspace import (
    IDENTICAL_SOLIDS,
    HalfSpaceCompliance,
    HalfSpaceRange,
    HalfSpaceRangeWarning,
    halfspace_range,
)
from .tangential.motion import solve_tangential
from .tangential.outer_film import OuterFilm, outer_film, unestimated_for_pair
from .tangential.pair import SpherePair, solve_pair
from .tangential.result import TangentialEnergyWarning, TangentialResult
from .tangential.superposition import (
    SuperpositionValidity,
    SuperpositionWarning,
    superposition_validity,
)
from .threads import one_blas_thread

HARD_IMPACT = 1000.0  # St above which the film grid's rim is refined (contact_spacings)
IMMERSED_OUTER_RADIUS = 30.0  # far-field truncation, by sqrt(a x0) (the tail is added exactly)


def film_extent(params: CollisionParameters) -> tuple[float, float]:
    """(rim, outer) of the film grid, by sqrt(a x0): the rim of the largest contact the sphere
    can reach, the dry Hertz contact radius at the impact's energy (an upper bound, since the
    film dissipates) but never less than eps^(1/5), the radius where elastic flattening starts
    (gap ~ eps^(2/5)); the grid's end, for a thin layer where the wetted edge can reach,
    sqrt(2 (1 + compression)), plus 5 %, for an immersed one IMMERSED_OUTER_RADIUS (or 10 rims).
    """
    compression = hertz.max_compression(params.eps, params.St)
    rim = max(np.sqrt(compression), params.eps**0.2)
    if params.layer == "thin":
        return rim, 1.05 * np.sqrt(2.0 * (1.0 + compression))  # > 1.48 sqrt(compression)
    return rim, max(IMMERSED_OUTER_RADIUS, 10.0 * rim)


def contact_spacings(St: float) -> dict:
    """The film grid's axis spacing and rim spacing (relative to the contact's) and its outlet
    radius (by the rim radius), scaled, no unit (:func:`ehdfem.film.grid.contact_grid`'s
    keywords), for the Stokes number St. Up to St = HARD_IMPACT the grid's own, 0.2, 0.3 and
    1.5. Above it the thinnest film is the exit constriction at the rim of a contact flattened
    far more than the film is thick. Its width relative to the contact radius is about
    (H_min/C)^(2/3) (the gap outside a Hertz contact opens as the 3/2 power of the distance
    from its rim), and H_min/C, the thinnest film over the dry compression, falls as St^(-3/4)
    whatever eps (docs/model.md, "Film grid"): with q = (HARD_IMPACT/St)^(1/2) the rim's spacing
    is 0.3 q (at least 0.03), the outlet beyond it, where the film opens, is passed within
    1 + 0.5 q^(3/5) rims (at least 1.25, which keeps neighbouring elements within 15 % of each
    other), and the axis, where the film is then four times the thinnest, takes 0.2 q^(-4/5)
    (at most 0.5): 0.095, 1.25 and 0.5 at St = 1e4.
    """
    if St <= HARD_IMPACT:
        return {}
    q = np.sqrt(HARD_IMPACT / St)
    return {
        "axis_spacing": min(0.5, AXIS_SPACING * q**-0.8),
        "rim_spacing": max(0.03, RIM_SPACING * q),
        "outlet_radius": max(1.25, 1.0 + (OUTLET_RADIUS - 1.0) * q**0.6),
    }


def film_radii(params: CollisionParameters, nodes: int = DEFAULT_NODES) -> np.ndarray:
    """Film nodes for a collision (by sqrt(a x0)): :func:`ehdfem.film.grid.contact_grid` graded
    to the rim of :func:`film_extent`, with the spacings of :func:`contact_spacings` (the
    grid's own up to St = HARD_IMPACT). A thin layer's grid ends at least 1.48 rims out
    (eps^(1/5) is cut to that at tiny St and large eps); an immersed one has a node at the
    sphere's radius 1/sqrt(delta), where the film's shear integrals end. The rigid approach
    needs no grading of its own: the film's conductances make its force exact on any grid
    (:mod:`ehdfem.film.reynolds`), so a sphere the film stops before the solids flatten (eps
    1e-12 up to St = 10) stops at the rigid stopping gap on this grid too.
    """
    rim, outer = film_extent(params)
    spacings = contact_spacings(params.St)
    if params.layer == "thin":
        return contact_grid(nodes, min(rim, outer / 1.48), outer, **spacings)
    return contact_grid(nodes, rim, outer, node_at=1.0 / np.sqrt(params.delta), **spacings)


def elasticity(
    params: CollisionParameters,
    radii,
    config: RunConfig | None = None,
    physical: PhysicalCollision | None = None,
    materials=None,
    comm=None,
) -> Compliance:
    """The compliance at the film nodes ``radii`` (by sqrt(a x0)) for params.eps: elastic
    half-spaces, or FE solids (:class:`ehdfem.solids.fe.solids.FESolids`) built for params.delta
    with the lower body of ``config`` (default :class:`ehdfem.config.RunConfig`).
    Materials, as (Young's modulus, Poisson ratio) of (sphere, wall): ``materials`` if given,
    else those of the physical inputs, else identical solids with Poisson ratio 0.3 (the
    half-space's pressure kernel only sees theta; the FE solids and the shear traction also
    see the moduli ratio and the nu's; a coating's modulus is the wall's times its stiffness).
    The squeeze-shear traction is applied when params.shear_traction says so (None: the
    solids', :func:`ehdfem.solids.compliance.default_shear_traction`). ``comm``: the FE
    solids' MPI communicator (default COMM_WORLD)."""
    config = RunConfig() if config is None else config
    sphere, wall = _materials(physical) if materials is None else materials
    shear = params.shear_traction
    shear = default_shear_traction(config.model) if shear is None else shear
    with one_blas_thread():
        if config.model == "halfspace":
            return HalfSpaceCompliance(
                radii, params.eps, (params.delta, (sphere, wall)) if shear else None, (sphere, wall)
            )
        from .solids.fe.solids import FESolids

        fe = FESolids(params.delta, radii, sphere=sphere, wall=wall, lower=config.lower, comm=comm)
        return fe.compliance(params.eps, shear=shear)


def _materials(physical):
    """(sphere, wall) as (Young's modulus, Poisson ratio): those of the physical inputs, else
    identical solids."""
    if physical is None:
        return IDENTICAL_SOLIDS
    return tuple((m.young_modulus, m.poisson_ratio) for m in (physical.sphere, physical.wall))


def mode_one_elasticity(params: CollisionParameters, compliance: Compliance, physical=None):
    """The solids' mode-1 compliance (:class:`ehdfem.solids.compliance.ModeOneCompliance`) matching
    ``compliance`` at params.eps, for the sliding film: half-spaces of the same materials, or
    the FE solids' own mesh (:class:`ehdfem.solids.fe.mode_one.FEModeOne`). None for rigid
    solids. A curved FE lower body (a lower sphere) is refused: its mode-1 compliance is not
    built."""
    if compliance.model == "rigid":
        return None
    if compliance.model == "fem":
        from .solids.fe.mode_one import FEModeOne

        lower = compliance.solids.lower
        if lower.radius is not None:
            raise checks.InputError(curved_lower_sliding(lower.kind))
        return FEModeOne(compliance.solids, params.eps)
    from .solids.halfspace_mode_one import HalfSpaceModeOne

    materials = getattr(compliance, "materials", None) or _materials(physical)
    return HalfSpaceModeOne(compliance.radii, params.eps, params.delta, materials)


@dataclass
class CollisionResult:
    """A collision's outcome: the normal motion (:class:`ehdfem.motion.normal.NormalResult`), the
    tangential motion (:class:`ehdfem.tangential.result.TangentialResult`, None for a head-on
    impact), the elasticity model used, for physical inputs the inputs (to convert back to SI), and
    the compliance used (:class:`ehdfem.solids.compliance.Compliance`; an FE compliance keeps its
    solids, for the fields of :mod:`ehdfem.outputs.fields` and the pictures of
    :mod:`ehdfem.outputs.render`), and for the sliding film the validity of its mode-1
    superposition (:class:`ehdfem.tangential.superposition.SuperpositionValidity`; a flagged one
    was also warned of). ``config``: how it was computed (:class:`ehdfem.config.RunConfig`).
    ``halfspace_range``: for the half-space model, how far the collision strays from the
    theory's range (:class:`ehdfem.solids.halfspace.HalfSpaceRange`; a flagged one was warned
    of); None for the other models. ``outer_film``: for an immersed oblique impact whose run
    leaves the flow beyond the tangential integrals out (outer_flow "none"), its estimated
    effect on e_t and the spin change (:class:`ehdfem.tangential.outer_film.OuterFilm`; a
    flagged one was warned of); None otherwise."""

    params: CollisionParameters
    model: str
    normal: NormalResult
    tangential: TangentialResult | None = None
    physical: PhysicalCollision | None = None
    compliance: Compliance | None = None
    superposition: SuperpositionValidity | None = None
    config: RunConfig | None = None
    halfspace_range: HalfSpaceRange | None = None
    outer_film: OuterFilm | None = None

    def summary(self, command: list[str] | None = None) -> dict:
        """A JSON-ready dict: where it comes from under "provenance"
        (:func:`ehdfem.outputs.provenance.record`: version, git commit, date, libraries, the
        command line ``command``, default sys.argv, MPI size); the collision's groups and
        models; the outputs of :mod:`ehdfem.outputs.registry` (dimensionless, DSH scales),
        with the reasons of those that do not apply under "not_applicable", the plausibility
        notes under "notes" (:func:`ehdfem.outputs.plausibility.notes`, empty when there is
        none) and, for physical inputs, the SI values under "si"; the time-step control and
        the tangential model used; and under "inputs" everything needed to run the collision
        again (see :meth:`inputs`)."""
        n = self.normal
        p = self.params
        out = {
            "provenance": provenance.record(command),
            "model": self.model,
            "layer": p.layer,
            "St": p.St,
            "eps": p.eps,
            "delta": p.delta,
            **cavitation.MODELS.flat(p.cavitation, written=True),
            **viscosity.LAWS.flat(p.viscosity, written=True),
            "gap": n.gap.name,
            "shear_traction": getattr(self.compliance, "shear_matrix", None) is not None,
            "e_dry": p.e_dry,
            "angle": p.angle,
            **outputs.values(self),
            "rtol": n.rtol,
            "film_control": n.film_control,
            "bdf_order": n.order,
        }
        if self.tangential is not None:
            t = self.tangential
            out.update(tangential_model=t.model, tangential_at=t.at)
            if t.energy is not None:
                out["sliding_deformation"] = t.deformation
        out["not_applicable"] = outputs.not_applicable(self)
        out["notes"] = plausibility.notes(self)
        if self.physical is not None:
            out["si"] = outputs.si_values(self)
        out["inputs"] = self.inputs()
        return out

    def inputs(self) -> dict:
        """The inputs of this collision as a JSON-ready dict, which
        :func:`ehdfem.config.read_inputs` reads back: "parameters", the flat settings of the
        CollisionParameters (:meth:`~ehdfem.inputs.scales.CollisionParameters.settings`:
        every field, the cavitation model and viscosity law by name with their constants;
        dimensionless, DSH scales; P_cav None for no limit);
        "physical", for physical inputs, every PhysicalCollision field (SI) with the
        materials' and the liquid's values; "run", the flat settings of the run configuration
        (:meth:`ehdfem.config.RunConfig.settings`)."""
        parameters = self.params.settings(written=True)
        config = RunConfig() if self.config is None else self.config
        run = config.settings()
        if self.model in MODELS:  # a compliance passed to collide() says which solids were used
            run["model"] = self.model
        return {
            "parameters": parameters,
            "physical": None if self.physical is None else asdict(self.physical),
            "run": run,
        }


class SharedNormals:
    """Normal motions solved once per normal problem, for collisions that differ only in what
    the normal integration does not read (the angle, the spin; delta on half-spaces under a
    thin layer): :meth:`solve` stands for :func:`ehdfem.motion.normal.solve_normal` and keeps
    each result under the digest of its :class:`ehdfem.motion.normal_problem.NormalProblem`
    (the film nodes, the solids' matrices, the gap, the film's laws, the sphere, the time-step
    options: what the integration reads, whatever inputs they came from). A later collision
    with an equal digest gets that normal motion with its own inputs as ``params``; the
    normal motion holds nothing else of them, so the collision is the one a new solve gives,
    bit for bit. A failed integration (a closed film on one grid of the refinement, a
    solver error) is kept too and raised again for each collision of that problem; each grid
    of the refinement is a problem of its own (its nodes are in the digest). ``solved``: the
    normal motions integrated. Hold one for a group of collisions (its results keep their
    histories in memory)."""

    def __init__(self):
        self.solved = 0
        self._results: dict[str, NormalResult | Exception] = {}

    def solve(self, params, compliance, options=None, forces=()) -> NormalResult:
        """The normal motion of ``params`` on ``compliance`` (arguments of
        :func:`ehdfem.motion.normal.solve_normal`), integrated only if its problem is new."""
        key = normal_problem(params, compliance, options, forces).digest()
        if key is not None and key in self._results:
            found = self._results[key]
            if isinstance(found, Exception):
                raise found
            return replace(found, params=params)
        self.solved += 1
        try:
            normal = solve_normal(params, compliance, options, forces)
        except (NormalSolverError, np.linalg.LinAlgError) as err:
            if key is not None:
                self._results[key] = err
            raise
        if key is not None:
            self._results[key] = normal
        return normal


def normal_key(
    params: CollisionParameters | PhysicalCollision, config: RunConfig | None = None
) -> str | None:
    """The digest of the first normal problem :func:`collide` solves for ``params`` and
    ``config`` (:meth:`ehdfem.motion.normal_problem.NormalProblem.digest`): on the film grid of
    ``config.numerics.nodes``, before any refinement, with the solids built as :func:`collide`
    builds them (for the FE model that is the whole cost of its solids). Collisions with equal
    keys share that normal motion in :class:`SharedNormals`; None: a problem without a digest,
    shared with none."""
    physical = params if isinstance(params, PhysicalCollision) else None
    params = params if physical is None else physical.dimensionless()
    config = RunConfig() if config is None else config
    solids = elasticity(params, film_radii(params, config.numerics.nodes), config, physical)
    try:
        return normal_problem(params, solids, config.options).digest()
    finally:
        solids.close()


def collide(
    params: CollisionParameters | PhysicalCollision,
    config: RunConfig | None = None,
    compliance: Compliance | None = None,
    mode_one: ModeOneCompliance | None = None,
    forces: tuple[SphereForce, ...] = (),
    normals: SharedNormals | None = None,
    **settings,
) -> CollisionResult:
    """Simulate one collision with dimensionless (or physical) inputs, computed as ``config``
    says (:class:`ehdfem.config.RunConfig`; default: half-space solids, Couette
    tangential film, 240 film nodes); see the module docstring. Instead of ``config``, its flat
    settings may be given as keywords, the names of the command line and of study files
    (``collide(params, model="fem", nodes=120, tangential="lubrication")``,
    :meth:`ehdfem.config.RunConfig.from_settings`).

    If the film closes on the grid of ``config.numerics.nodes`` (hard impacts of stiff
    solids, where the rim of the flattened contact gets thinner than the grid resolves), the
    collision is run again on a grid with twice the nodes, at most ``numerics.refinements``
    times; the nodes used are reported in the result (``film_nodes``). The tangential motion
    is solved when the impact is oblique (angle > 0). ``compliance``: an elasticity built
    before (e.g. by :func:`elasticity` for the widest collision of a sweep, whose grid then
    serves every point), used at params.eps on its own grid, without refinement; the model,
    lower body and nodes of ``config`` are then not used. ``mode_one``: the solids' mode-1
    compliance (:class:`ehdfem.solids.compliance.ModeOneCompliance`) built before by
    :func:`mode_one_elasticity` for ``compliance``, at any eps; only with ``compliance`` (the
    same elasticity model on the same film nodes). It is used at params.eps (``with_eps``) by
    the lubrication model with deformation "gap" or "full", where it maps the mode-1 film loads
    (pressure by mu V0 a / x0^2, shear tractions by sqrt(delta) times that, at the film nodes
    by sqrt(a x0)) to the faces' displacements (by x0). Without it the collision builds one,
    which for FE solids is a factorisation of tens of seconds. The caller owns it: ``collide``
    does not close it. ``forces``: forces on the sphere besides those of ``params``, scaled by
    this collision's force scale (:func:`ehdfem.motion.normal.solve_normal`; e.g. the history
    force of the liquid around the film, :class:`ehdfem.motion.forces.HistoryForce`).
    """
    physical = params if isinstance(params, PhysicalCollision) else None
    if physical is not None:
        params = physical.dimensionless()
        _check_liquid(physical)
    if not isinstance(params, CollisionParameters):
        raise checks.InputError(
            f"params must be CollisionParameters or PhysicalCollision, got {params!r}"
        )
    if settings and config is not None:
        raise checks.InputError(
            f"give the run settings either as config or as keywords, not both "
            f"(got config and {', '.join(sorted(settings))})",
            "config",
        )
    config = RunConfig.from_settings(**settings) if config is None else config
    if not isinstance(config, RunConfig):
        raise checks.InputError(f"config must be a RunConfig, got {config!r}", "config")
    config.check_inputs(params)
    _check_pair_inputs(physical, config)
    mode_one = _mode_one_at(mode_one, compliance, params.eps)
    with one_blas_thread():
        if compliance is not None:
            eps_compliance = compliance.with_eps(params.eps)
            return _collide_on(params, eps_compliance, config, physical, mode_one, forces, normals)
        numerics = config.numerics
        for attempt in range(numerics.refinements + 1):
            radii = film_radii(params, numerics.nodes * 2**attempt)
            try:
                solids = elasticity(params, radii, config, physical)
                return _collide_on(params, solids, config, physical, None, forces, normals)
            except FilmClosedError:
                if attempt == numerics.refinements:
                    raise


def _check_pair_inputs(physical, config) -> None:
    """Refuse physical inputs for two spheres in the half-space model or obliquely: they
    describe one sphere (its radius and mass), while the pair's groups are by the reduced
    radius a1 a2 / (a1 + a2) and mass m1 m2 / (m1 + m2)."""
    if physical is None or config.lower.kind != "sphere":
        return
    if config.model == "halfspace" or physical.angle > 0.0:
        raise checks.InputError(
            "lower = 'sphere' takes scaled inputs here (St, eps and delta by the reduced radius "
            "a1 a2 / (a1 + a2) and mass m1 m2 / (m1 + m2), ehdfem.inputs.scales.reduced_radius "
            "and reduced_mass): the physical inputs describe one sphere; for two spheres use "
            "ehdfem.inputs.scales.PhysicalPair (its dimensionless() and lower_settings())",
            "lower",
        )


def _mode_one_at(mode_one, compliance, eps):
    """A given mode-1 compliance at ``eps`` (None stays None); refused without ``compliance`` or
    not matching it (model, nodes)."""
    if mode_one is None:
        return None
    if not isinstance(mode_one, ModeOneCompliance):
        raise checks.InputError(
            f"mode_one must be a ModeOneCompliance, got {type(mode_one).__name__}"
        )
    if compliance is None:
        raise checks.InputError(
            "mode_one needs compliance: pass the compliance it was built for "
            "(mode_one_elasticity(params, compliance))"
        )
    if mode_one.model != compliance.model:
        raise checks.InputError(
            f"mode_one is for {mode_one.model} solids, compliance for {compliance.model}"
        )
    if not np.array_equal(mode_one.radii, compliance.radii):
        raise checks.InputError(
            "mode_one and compliance must be on the same film nodes (radii differ)"
        )
    return mode_one.with_eps(eps)


def _collide_on(params, compliance, config, physical, given_mode_one, forces, normals):
    """The normal and (oblique impacts) tangential motion on a given compliance, with the
    tangential model, mode-1 deformation and time integration of ``config``;
    ``given_mode_one``: a mode-1 compliance at params.eps that is not closed here (None: built
    here when needed, and closed); ``forces``: the further forces on the sphere; ``normals``:
    the normal motions solved before (:class:`SharedNormals`; None: solved here)."""
    solve = solve_normal if normals is None else normals.solve
    normal = solve(params, compliance, config.options, forces)
    result = CollisionResult(
        params, compliance.model, normal, physical=physical, compliance=compliance, config=config
    )
    if compliance.model == "halfspace":
        largest = normal.history.pressure[int(np.argmax(normal.history.force))]
        result.halfspace_range = halfspace_range(
            normal.radii, largest, normal.compression_by_radius, params.delta
        )
        if result.halfspace_range.flagged:
            warnings.warn(result.halfspace_range.warning(), HalfSpaceRangeWarning, stacklevel=3)
    _check_viscosity_range(params, physical, normal)
    _check_result_range(params, physical, normal)
    if params.tangential_speed == 0:
        return result
    return _slide(result, given_mode_one)


def _check_liquid(physical) -> None:
    """Warn (ResultRangeWarning), before any work, of a liquid viscosity outside the Newtonian
    liquids (physical inputs only; :func:`ehdfem.outputs.plausibility.liquid_note`)."""
    note = plausibility.liquid_note(physical)
    if note is not None:
        warnings.warn(note, ResultRangeWarning, stacklevel=3)


def _check_result_range(params, physical, normal: NormalResult) -> None:
    """Warn (ResultRangeWarning, or a category of it) of each of the normal motion's
    plausibility notes (:func:`ehdfem.outputs.plausibility.result_notes`: e_n above 1, a rough
    contact the impact model does not hold for, a stuck sphere's unresolved stop, a weak
    rebound, a nanometre film of physical inputs); the result keeps them."""
    for note in plausibility.result_notes(params, physical, normal):
        warnings.warn(note, note.category, stacklevel=4)


def _check_viscosity_range(params, physical, normal: NormalResult) -> None:
    """Warn (ViscosityRangeWarning) when the film's largest pressure went past its viscosity
    law's validity, its ``validity_pressure`` (:mod:`ehdfem.film.viscosity`; SI, Pa);
    physical inputs only (scaled ones give no liquid to compare the law with)."""
    if physical is None:
        return
    law = params.viscosity_law()
    validity = law.validity_pressure(physical.alpha, physical.liquid.viscosity)
    largest = float(np.max(normal.history.pressure)) * physical.scales().pressure
    if largest > validity:
        warnings.warn(barus_range_warning(largest, validity), ViscosityRangeWarning, stacklevel=4)


def with_tangential(
    result: CollisionResult,
    tangential: str,
    mode_one: ModeOneCompliance | None = None,
    deformation: str = "gap",
) -> CollisionResult:
    """The same collision with another tangential film model: the normal motion of ``result``
    (oblique, with its compliance) is kept and only the tangential motion is solved again, as
    :func:`collide` would with ``tangential``, ``deformation`` and ``mode_one`` (the mode-1
    compliance for ``result.compliance``; None: built and closed here when needed). The normal
    motion does not depend on the tangential one (the decoupling of
    :mod:`ehdfem.tangential.motion`), so this equals a new :func:`collide` call at a fraction of
    its cost. Results are dimensionless (DSH scales), as those of :func:`collide`; the result's
    run configuration records the new tangential model and deformation."""
    config = RunConfig() if result.config is None else result.config
    config = replace(config, tangential=tangential, deformation=deformation)
    if result.params.tangential_speed == 0 or result.compliance is None:
        raise checks.InputError("with_tangential needs an oblique collision with its compliance")
    mode_one = _mode_one_at(mode_one, result.compliance, result.params.eps)
    bare = replace(result, tangential=None, superposition=None, config=config, outer_film=None)
    return _slide(bare, mode_one)


def sphere_pair(params: CollisionParameters, lower) -> SpherePair:
    """The partner of a two-sphere collision (:class:`ehdfem.tangential.pair.SpherePair`) from
    the upper sphere's inertia factor in ``params`` and the :class:`ehdfem.config.LowerSphere`
    ``lower`` (its mass ratio, inertia factor, spin and radius ratio)."""
    return SpherePair(
        lower.mass_ratio,
        params.inertia_factor,
        lower.lower_inertia_factor,
        lower.lower_spin,
        lower.radius_ratio,
    )


def _slide(result, given_mode_one):
    """``result`` (its normal motion solved) with the tangential motion of its run
    configuration (tangential model, mode-1 deformation) added; ``given_mode_one`` as in
    :func:`_collide_on`."""
    params, normal, compliance = result.params, result.normal, result.compliance
    model, deformation = result.config.tangential, result.config.deformation
    pair = result.config.lower.kind == "sphere"
    outer_flow = result.config.outer_flow
    mode_one = None
    if model == "lubrication" and deformation != "none":
        mode_one = given_mode_one
        if mode_one is None:
            mode_one = mode_one_elasticity(params, compliance, result.physical)
    built = mode_one is not None and given_mode_one is None
    surface_sum = getattr(compliance, "surface_sum_matrix", None)
    try:
        if pair:  # two spheres: no 2-D superposition check, no outer flow (docs/tangential.md)
            partner = sphere_pair(params, result.config.lower)
            film = (mode_one, surface_sum, deformation)
            result.tangential = solve_pair(normal, model, partner, *film)
        else:
            result.tangential = solve_tangential(
                normal, model, mode_one, surface_sum, deformation, outer_flow=outer_flow
            )
        if model == "lubrication" and not pair:
            result.superposition = superposition_validity(
                normal,
                result.tangential,
                lambda unloaded: solve_tangential(
                    normal, model, mode_one, surface_sum, deformation, unloaded, outer_flow
                ),
            )
            if result.superposition.flagged:
                warnings.warn(result.superposition.warning(), SuperpositionWarning, stacklevel=4)
        energy = result.tangential.energy
        if model == "lubrication" and energy.flagged:
            warnings.warn(energy.warning(deformation), TangentialEnergyWarning, stacklevel=4)
    finally:
        if built:
            mode_one.close()
    if outer_flow == "none" and not pair:
        result.outer_film = outer_film(normal, result.tangential)
        if result.outer_film is not None and result.outer_film.flagged:
            warnings.warn(result.outer_film.note(), ResultRangeWarning, stacklevel=4)
    note = unestimated_for_pair(normal, result.tangential) if pair else None
    if note is not None:
        warnings.warn(note, ResultRangeWarning, stacklevel=4)
    return result
