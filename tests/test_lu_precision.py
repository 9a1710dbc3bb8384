"""The Newton matrix's LU in single precision (lu_precision "mixed", the default) against double
precision (ehdfem.motion.implicit_step, "Mixed precision").

The residual is double precision either way, so a collision that stays in single precision
converges to the same steps within the Newton tolerance: its outputs agree with double
precision's to 1e-8 (3.5e-9 seen). A collision that turns to double precision (an update that
would close the film) continues from iterates that differ within that tolerance, and where a
step's Newton test or step control then decides otherwise the step sequences part: its outputs
agree at the time control's accuracy, rtol = 2e-4 (2.6e-4 seen in the thinnest film; 5e-4
asserted).
"""

import types

import numpy as np
import pytest

from ehdfem.collision import collide
from ehdfem.config import RunConfig
from ehdfem.film.cavitation import Unlimited
from ehdfem.film.grid import radial_grid
from ehdfem.film.reynolds import Film, FilmError
from ehdfem.inputs.presets import EXAMPLE
from ehdfem.inputs.scales import CollisionParameters, from_presets
from ehdfem.motion import implicit_step
from ehdfem.motion.implicit_step import ImplicitStep
from ehdfem.motion.sphere import Sphere
from ehdfem.motion.timestepping import IntegratorOptions

pytestmark = pytest.mark.serial

OUTPUTS = ("e_n", "min_film_thickness", "contact_time", "max_force", "max_compression")


@pytest.fixture
def precisions(monkeypatch):
    """The precisions of the LUs the Newton iterations factorise, in order."""
    seen = []

    class Counted(implicit_step.ReusableLU):
        def __init__(self, matrix, fixed, theta, workspace=None, single=None):
            super().__init__(matrix, fixed, theta, workspace, single)
            seen.append("single" if single is not None else "double")

    monkeypatch.setattr(implicit_step, "ReusableLU", Counted)
    return seen


def both(inputs, precisions):
    """(double, mixed): the normal motions at 80 nodes, and the precisions of mixed's LUs."""
    results = []
    for precision in ("double", "mixed"):
        precisions.clear()
        config = RunConfig.from_settings(nodes=80, lu_precision=precision)
        results.append(collide(inputs, config).normal)
    return results, list(precisions)


@pytest.mark.parametrize(
    "settings",
    [dict(St=20.0, eps=1e-3, layer="thin"), dict(St=50.0, eps=1e-4, layer="immersed")],
    ids=["thin", "immersed"],
)
def test_a_collision_in_single_precision_gives_the_double_precision_outputs(settings, precisions):
    """Every LU in single precision, the same steps, and the outputs within 1e-8."""
    (double, mixed), used = both(CollisionParameters.from_settings(**settings), precisions)
    assert set(used) == {"single"}
    assert mixed.steps == double.steps
    for name in OUTPUTS:
        assert getattr(mixed, name) == pytest.approx(getattr(double, name), rel=1e-8), name


@pytest.mark.parametrize(
    "inputs",
    [
        from_presets(**EXAMPLE),
        CollisionParameters.from_settings(St=1e4, eps=1e-12, layer="thin", p_cav=-1.0),
    ],
    ids=["example", "hard-impact"],
)
def test_a_collision_turns_to_double_precision_and_agrees_at_the_time_accuracy(inputs, precisions):
    """The README's example (its elastic rebound) and a hard impact: the LUs start in single
    precision and turn to double for good; the outputs agree within 5e-4."""
    (double, mixed), used = both(inputs, precisions)
    turned = used.index("double")
    assert 0 < turned and set(used[turned:]) == {"double"}
    for name in OUTPUTS:
        assert getattr(mixed, name) == pytest.approx(getattr(double, name), rel=5e-4), name


def test_an_lu_singular_in_single_precision_is_redone_in_double():
    """A Newton matrix whose float32 rounding is singular (two rows equal to 1e-10) is
    factorised again in double precision, which solves it to 1e-5 (its condition number is
    4e10), and the step goes on in double precision."""
    n = 8
    options = IntegratorOptions(lu_precision="mixed")
    radii = radial_grid(n, 0.5, 1.1)
    step = ImplicitStep(Film(radii, "thin"), np.zeros((n, n)), Unlimited(), Sphere(1.0), options)
    assert step.single
    matrix = np.asfortranarray(np.eye(n + 2))
    matrix[:2, :2] = [[1.0, 1.0], [1.0, 1.0 + 1e-10]]
    iterate = types.SimpleNamespace(fixed=np.zeros(n, bool), theta_nodes=np.zeros(n, bool))
    step._factorise(matrix, iterate)
    assert not step.single and step.factor.lu.dtype == np.float64
    exact = np.arange(1.0, n + 3)
    found = step.factor.solve(matrix @ exact, iterate.fixed, None)
    assert np.abs(found - exact).max() <= 1e-5 * np.abs(exact).max()


@pytest.mark.parametrize("failure", ["step", "film"])
def test_a_failed_step_turns_the_lu_to_double_precision(failure, monkeypatch):
    """A step whose Newton iteration fails (StepFailed) or whose iterate the film cannot take
    (FilmError: a pressure past the viscosity law's range) leaves the next LUs in double
    precision: its retries at shorter steps must not meet single precision's rounding again."""
    n = 8
    options = IntegratorOptions(lu_precision="mixed")
    radii = radial_grid(n, 0.5, 1.1)
    step = ImplicitStep(Film(radii, "thin"), np.zeros((n, n)), Unlimited(), Sphere(1.0), options)
    error = {"step": implicit_step.StepFailed("no", 1.0), "film": FilmError("overflow")}[failure]

    def fail(*args):
        raise error

    monkeypatch.setattr(step, "_newton", fail)
    assert step.single
    with pytest.raises(type(error)):
        step.solve(None, 1.0, 1.0, None, 0.0)
    assert not step.single
