"""Mass-conserving (JFO) cavitation against exact results: a manufactured one-step solution of
the complementarity film problem with its convergence order, liquid volume conservation
through a whole collision, and the reduction to truncation where no cavity forms."""

import numpy as np
import pytest

from ehdfem.collision import collide
from ehdfem.config import RunConfig
from ehdfem.film import cavitation
from ehdfem.film.cavitation import (
    NO_LIMIT,
    MassConserving,
    MassConservingSolver,
    NoCavitation,
    Truncation,
    TruncationSolver,
    Unlimited,
)
from ehdfem.film.grid import radial_grid
from ehdfem.film.reynolds import Film
from ehdfem.inputs.scales import CollisionParameters
from ehdfem.motion.implicit_step import ImplicitStep
from ehdfem.motion.normal import solve_normal
from ehdfem.motion.sphere import Sphere
from ehdfem.motion.timestepping import IntegratorOptions

pytestmark = pytest.mark.serial

P_CAV, GAP, STEP = -2.0, 0.5, 0.05
EDGE = np.sqrt(2 * (1 - GAP))  # thin layer: H = 1 there
RUPTURE = 0.45  # the cavity is R < RUPTURE


def manufactured(radii):
    """Exact JFO step: P = P_cav (1 - s^2), s = (R - R_c)/(R_e - R_c) in the full film (so P and
    dP/dR are continuous at the cavity), theta = theta_c - 0.3 (1 - R^2/R_c^2) in the cavity.
    The liquid before the step, c_old, follows from theta H - c_old = dt (1/(12R)) (R H^3 P')'
    (full film) and c_old = theta H (cavity, where there is no flux)."""
    r = np.asarray(radii)
    h = GAP + 0.5 * r**2
    length = EDGE - RUPTURE
    s = (r - RUPTURE) / length
    dp, d2p = -2 * P_CAV * s / length, -2 * P_CAV / length**2
    with np.errstate(divide="ignore", invalid="ignore"):
        reynolds = (h**3 * dp + 3 * r**2 * h**2 * dp + r * h**3 * d2p) / (12 * r)
    full = r >= RUPTURE
    h_c = GAP + 0.5 * RUPTURE**2
    theta_c = 1 - STEP * h_c**2 * d2p / 12  # theta jumps to 1 across the rupture front
    theta = np.where(full, 1.0, theta_c - 0.3 * (1 - (r / RUPTURE) ** 2))
    pressure = np.where(full, P_CAV * (1 - s**2), P_CAV)
    pressure = np.where(r < EDGE, pressure, 0.0)
    before = np.where(full, h - STEP * np.nan_to_num(reynolds), theta * h)
    return pressure, theta, before


def solve_step(n):
    """One implicit-Euler step of the integrator's own Newton on a rigid film held at X = GAP
    (St = 1e30 keeps the sphere still): the complementarity film solver alone."""
    radii = radial_grid(n, 0.5, 1.1)
    options = IntegratorOptions(newton_tol=1e-10, max_newton=100)
    still = Sphere(1e30)
    film, cavitation = Film(radii, "thin"), MassConservingSolver(P_CAV)
    step = ImplicitStep(film, np.zeros((n, n)), cavitation, still, options)
    _, theta, before = manufactured(radii)
    guess = (np.zeros(n), GAP, 0.0, np.ones(n), np.zeros(n, bool))
    s = step.solve(guess, STEP, 1.0, (-before, -GAP, 0.0), STEP)
    assert s.gap == pytest.approx(GAP, abs=1e-12)
    return radii, s.pressure, s.fill, s.cavitated, s.state


def test_manufactured_step_converges_at_second_order():
    """The discrete pressure approaches the exact step solution at second order in the max norm
    over the wetted nodes (N = 40 ... 320: measured orders 1.8, 2.2, 2.0). The cavity holds its
    liquid exactly: theta = c_old / H to round-off more than two cells from the rupture front,
    and the cavitated nodes are the exact ones except within two cells of it (where the front
    falls between nodes and theta is first order)."""
    errors = []
    for n in (40, 80, 160, 320):
        radii, pressure, fill, cavitated, state = solve_step(n)
        exact_p, exact_theta, _ = manufactured(radii)
        wet = ~state.dry
        away = wet & (np.abs(radii - RUPTURE) > 2 * np.gradient(radii))
        assert np.array_equal(cavitated[away], (radii < RUPTURE)[away])
        assert np.abs(fill - exact_theta)[away].max() < 1e-12
        errors.append(np.abs(pressure - exact_p)[wet].max() / abs(P_CAV))
    orders = np.log2(np.array(errors[:-1]) / errors[1:])
    print("pressure errors:", errors, "orders:", orders)
    assert errors[-1] < 1e-4
    assert np.all(orders > 1.7), orders


def liquid_balance(result, film):
    """Largest change of the liquid volume in the immersed film, sum m_i theta_i H_i (times
    2 pi, by a x0^2), plus the liquid that left through the far-field boundary, R^2 H^2 P / 6
    per unit time (implicit Euler: the outflow at the end of each step)."""
    hist = result.history
    volume = (film.full_mass * hist.fill * hist.film_thickness).sum(axis=1)
    r = film.radii[-1]
    outflow = r**2 * hist.film_thickness[:, -1] ** 2 * hist.pressure[:, -1] / 6
    left = np.concatenate([[0.0], np.cumsum(np.diff(hist.time) * outflow[1:])])
    return np.abs(volume + left - volume[0]).max()


@pytest.mark.slow
def test_liquid_volume_is_conserved_through_cavitation_and_rebound():
    """Immersed sphere (St = 10, eps = 1e-2, P_cav = -2) with implicit Euler steps: the liquid
    volume plus the outflow stays constant to 1e-6 of the largest cavity volume,
    max sum m_i (1 - theta_i) H_i (the Newton tolerance), while the cavity opens (theta down to
    < 0.5) and the sphere rebounds. Truncation, with the same bookkeeping, fills its cavity
    with liquid from nowhere: an imbalance above half the cavity volume."""
    options = IntegratorOptions(order=1, rtol=1e-3, newton_tol=1e-10)
    imbalance = {}
    for model in ("mass-conserving", "truncate"):
        params = CollisionParameters.from_settings(
            St=10.0, eps=1e-2, layer="immersed", p_cav=P_CAV, cavitation=model
        )
        compliance = collide(params, RunConfig.from_settings(nodes=80)).compliance
        result = solve_normal(params, compliance, options)
        film = Film(compliance.radii, "immersed")
        assert result.rebound
        imbalance[model] = liquid_balance(result, film)
        if model == "mass-conserving":
            hist = result.history
            assert hist.fill.min() < 0.5
            cavity = (film.full_mass * (1 - hist.fill) * hist.film_thickness).sum(axis=1).max()
    print(f"cavity volume {cavity:.4g}, imbalance {imbalance}")
    assert imbalance["mass-conserving"] < 1e-6 * cavity
    assert imbalance["truncate"] > 0.5 * cavity


def test_mass_conserving_reduces_to_truncation_without_cavity():
    """With a cavitation pressure the suction never reaches, the two models solve the same
    equations with the same Newton matrices: e_n agrees to 1e-12 and the gap history, which
    crosses zero, to 1e-10 x0 (round-off gathered over a hundred steps). With the LU in double
    precision: a single-precision LU rounds the two models' matrices, equal up to their last
    bits, apart and the Newton iterates part within the Newton tolerance (2e-10 in e_n)."""
    double = RunConfig.from_settings(lu_precision="double")
    results = [
        collide(
            CollisionParameters.from_settings(St=10.0, eps=1e-3, p_cav=-1e4, cavitation=model),
            double,
        ).normal
        for model in ("truncate", "mass-conserving")
    ]
    assert results[0].history.pressure.min() > -1e4
    assert np.array_equal(results[1].history.fill, np.ones_like(results[1].history.fill))
    assert results[0].e_n == pytest.approx(results[1].e_n, rel=1e-12)
    assert results[0].history.gap == pytest.approx(results[1].history.gap, rel=0, abs=1e-10)


def test_truncation_holds_nodes_where_suction_would_exceed_the_limit():
    """Truncation's active set: wet nodes whose pressure would fall below P_cav with a
    non-negative residual are held at P_cav (their residual rows become P - P_cav); without a
    limit, or with the "none" model, no node is held."""
    pressure, dry = np.full(40, -3.0), np.zeros(40, bool)
    dry[30:] = True
    for name, p_cav, held in (
        ("truncate", -2.0, True),
        ("truncate", NO_LIMIT, False),
        ("none", -2.0, False),
        ("mass-conserving", NO_LIMIT, False),
    ):
        residual = np.ones(40)
        model = cavitation.MODELS[name].with_limit(p_cav).solver()
        cavitated = model.limit(residual, pressure, np.zeros(40, bool), dry, lambda: np.ones(40))
        assert cavitated[:30].all() == held and not cavitated[30:].any()
        if held:
            assert residual[:30] == pytest.approx(-1.0) and residual[30:] == pytest.approx(1.0)
        else:
            assert type(model) is Unlimited and (residual == 1.0).all()


@pytest.mark.parametrize("opening, cavity", [(0.3, False), (3.0, True)])
def test_truncated_cavity_released_far_at_once_converges_to_the_same_step(opening, cavity):
    """A cavity held over the inner 0.7 of a rigid thin film (the guess) that the film squeezed
    outside it (dH/dT = -2 beyond R = 0.4) refills while the inside opens slowly (dH/dT =
    ``opening``): Truncation's release reaching 1, 2, 4, ... nodes into the cavity gives the
    same step as freeing node by node, to 1e-12 of the largest pressure, with the same held
    nodes (none, or a cavity left on the axis when the inside opens fast), in fewer Newton
    iterates (measured 8 against 59, and 17 against 27). The LU in double precision: in
    single precision the iterates contract more slowly and stop within the Newton tolerance
    (1e-10), 2e-11 of the largest pressure apart."""
    n = 120
    radii = radial_grid(n, 0.5, 1.1)
    h = GAP + 0.5 * radii**2
    before = h - STEP * np.where(radii < 0.4, opening, -2.0)
    guess = (np.where(radii < 0.7, P_CAV, 0.0), GAP, 0.0, np.ones(n), np.zeros(n, bool))
    solutions, iterates = [], []
    for reach in (True, False):
        model = TruncationSolver(P_CAV)
        if not reach:
            model._reach_into = lambda previous, held: held
        options = IntegratorOptions(newton_tol=1e-10, max_newton=100, lu_precision="double")
        step = ImplicitStep(Film(radii, "thin"), np.zeros((n, n)), model, Sphere(1e30), options)
        solution = step.solve(guess, STEP, 1.0, (-before, -GAP, 0.0), STEP)
        solutions.append(solution)
        iterates.append(solution.iterations)
    first, second = solutions
    scale = np.abs(second.pressure).max()
    assert np.abs(first.pressure - second.pressure).max() < 1e-12 * scale
    held = [(s.pressure <= P_CAV) & ~s.state.dry for s in solutions]
    assert (held[0] == held[1]).all() and held[0].any() == cavity
    assert iterates[0] < iterates[1]


def test_every_model_name_gives_the_model_of_that_name():
    """Each registered name gives its class (a name without its class is no longer possible:
    the names are the classes'); a limit gives the solver of that model, none the unlimited
    one (its tracking of the liquid as the model's); the "none" model ignores a limit."""
    solvers = {
        Truncation: TruncationSolver,
        MassConserving: MassConservingSolver,
        NoCavitation: Unlimited,
    }
    assert set(cavitation.MODELS) == {cls.name for cls in solvers}
    for name in cavitation.MODELS:
        model = cavitation.MODELS[name].with_limit(-1.0)
        assert model.name == name and type(model.solver()) is solvers[type(model)]
        assert model.solver().tracks_liquid == model.tracks_liquid
        assert type(cavitation.MODELS[name].with_limit(NO_LIMIT).solver()) is Unlimited
    assert NoCavitation.with_limit(-1.0).p_cav == NO_LIMIT and not cavitation.has_limit("none")
    assert cavitation.has_limit("truncate") and cavitation.has_limit("mass-conserving")


def test_the_newton_rows_formed_alone_are_the_whole_matrix_rows():
    """The rows a kept LU's Woodbury update asks for, formed alone (ImplicitStep._newton_rows),
    equal those of the whole Newton matrix bit for bit: free rows next to the wetted edge, a
    mass-conserving cavity's rows (their unknown theta) and rows beside it, on a deformable
    thin film with the half-space compliance (eps 1e-3) and a piezoviscous liquid (Barus,
    alpha 0.1: the viscosity's own bands are not zero)."""
    from ehdfem.film.viscosity import Barus
    from ehdfem.solids.halfspace import influence_matrix

    n = 60
    radii = radial_grid(n, 0.5, 2.0)
    compliance = 1e-3 * influence_matrix(radii)
    film, cavitation = Film(radii, "thin", Barus(alpha=0.1)), MassConservingSolver(P_CAV)
    step = ImplicitStep(film, compliance, cavitation, Sphere(10.0), IntegratorOptions())
    pressure = np.where(radii < 0.8, 3.0 * (1 - radii**2 / 0.64), P_CAV)
    cavitated = (radii > 0.9) & (radii < 1.1)
    fill = np.where(cavitated, 0.7, 1.0)
    past = (-(GAP + 0.5 * radii**2), -GAP, 0.3)
    it, cavitated, fill = step._residual(pressure, GAP, -0.5, fill, cavitated, 0.01, 1.5, past, 0.0)
    whole = step._newton_matrix(it, 0.01, 1.5, fill).copy()
    free = np.flatnonzero(~it.fixed)
    rows = np.concatenate([free[:2], free[-3:], np.flatnonzero(it.theta_nodes)[:3]])
    assert it.theta_nodes[rows].any() and not it.fixed[rows].any()
    assert np.array_equal(step._newton_rows(it, 0.01, 1.5, fill, rows), whole[rows])
