"""FE solids (DOLFINx): compliance against the half-space, Hertz, mesh convergence, MPI."""

from pathlib import Path

import numpy as np
import pytest
from fe_bodies import LOWER_BODIES
from mpi4py import MPI

from ehdfem.checks import InputError
from ehdfem.collision import collide
from ehdfem.config import RunConfig
from ehdfem.film.grid import radial_grid
from ehdfem.film.reynolds import Film
from ehdfem.inputs.scales import CollisionParameters
from ehdfem.solids.fe import mesh as fem_mesh
from ehdfem.solids.fe.bodies import CoatedWall, LowerSphere, Wall
from ehdfem.solids.fe.mode_one import FEModeOne
from ehdfem.solids.fe.solids import FESolids
from ehdfem.solids.halfspace import HalfSpaceCompliance

RADII = radial_grid(60, 0.5, 2.0)


def hertz_like(radii):
    return np.sqrt(np.clip(1 - (radii / 0.8) ** 2, 0, None))


@pytest.fixture(scope="module")
def small_delta():
    return FESolids(1e-3, RADII, comm=MPI.COMM_SELF).compliance(1.0)


@pytest.mark.serial
def test_compliance_matches_the_half_space_near_the_axis(small_delta):
    """delta = 1e-3: within 1 % for R <= 0.5. The difference is physical, the finite sphere
    (a load-proportional shift of order F/(E a)), and shrinks like sqrt(delta)."""
    fe = small_delta.deflection(hertz_like(RADII))
    hs = HalfSpaceCompliance(RADII, 1.0).deflection(hertz_like(RADII))
    near = RADII <= 0.5
    assert np.abs(fe[near] / hs[near] - 1).max() < 0.01


@pytest.mark.serial
def test_hertz_contact_with_fe_solids():
    """Dry contact solved with the FE compliance (active set on P >= 0, H >= 0): at the
    approach -X = c^2 the contact radius is c and the peak pressure 8c/(pi^2 eps) (Hertz,
    scaled), both within 2 % (delta = 1e-4, 100 film nodes)."""
    radii = radial_grid(100, 1.0, 2.0)
    eps, c = 1.0, 1.0
    matrix = FESolids(1e-4, radii, comm=MPI.COMM_SELF).compliance(eps).matrix
    rigid = -(c**2) + 0.5 * radii**2  # X + R^2/2
    active = radii < c
    for _ in range(50):
        pressure = np.zeros_like(radii)
        pressure[active] = np.linalg.solve(matrix[np.ix_(active, active)], -rigid[active])
        gap = rigid + matrix @ pressure
        new = (active & (pressure > 0)) | (~active & (gap < 0))
        if (new == active).all():
            break
        active = new
    assert radii[active].max() == pytest.approx(c, rel=0.02)
    assert pressure[0] == pytest.approx(8 * c / (np.pi**2 * eps), rel=0.02)


@pytest.mark.slow
@pytest.mark.serial
def test_mesh_convergence_of_the_compliance():
    """The mesh follows the film grid; refining the film grid (and so the mesh) converges the
    deflection under a smooth pressure, (1 - R^2/1.5^2)^2. The observed order is printed; it
    must exceed 1.5 (second order expected: linear pressure between nodes, P2 elements)."""
    deflections = []
    for n in (30, 60, 120):
        radii = radial_grid(n, 0.5, 2.0)
        smooth = np.clip(1 - (radii / 1.5) ** 2, 0, None) ** 2
        w = FESolids(1e-3, radii, comm=MPI.COMM_SELF).compliance(1.0).deflection(smooth)
        deflections.append(w[0])
    changes = np.abs(np.diff(deflections))
    order = np.log2(changes[0] / changes[1])
    print(f"W(0) on 30/60/120 film nodes: {deflections}; observed order {order:.2f}")
    assert order > 1.5


def test_same_compliance_on_two_ranks_as_on_one():
    """Runs under mpirun -n 2 too: the distributed FE compliance equals the one-process one."""
    radii = radial_grid(20, 0.5, 2.0)
    distributed = FESolids(1e-3, radii, comm=MPI.COMM_WORLD).compliance(1.0).matrix
    single = FESolids(1e-3, radii, comm=MPI.COMM_SELF).compliance(1.0).matrix
    assert np.abs(distributed - single).max() < 1e-8 * np.abs(single).max()


@pytest.mark.serial
@pytest.mark.parametrize("St,delta", [(10.0, 1e-3), (12.0, 1e-4)])
def test_fe_collision_agrees_with_the_half_space_at_small_delta(St, delta):
    """eps = 1e-3, thin layer, P_cav = -2: the full FE model (true sphere gap, shear traction)
    and the asymptotic theory agree on e_n within 1 % at small delta."""
    params = CollisionParameters.from_settings(
        St=St, eps=1e-3, layer="thin", p_cav=-2.0, delta=delta
    )
    half_space = collide(params, RunConfig.from_settings(nodes=120))
    fem = collide(params, RunConfig.from_settings(model="fem", nodes=120))
    assert fem.summary()["gap"] == "exact" and fem.summary()["shear_traction"]
    assert fem.normal.e_n == pytest.approx(half_space.normal.e_n, rel=0.01)


@pytest.mark.slow
@pytest.mark.serial
@pytest.mark.serial
def test_fe_energy_balance_at_finite_delta():
    """delta = 0.05, St = 20, eps = 1e-3, thin layer, no cavitation, the default film grid: the
    elastic energy (1/6) P.M C P is the film pressure's work only if M C is symmetric
    (docs/fem.md), so the FE balance is as good as the half-space model's on the same grid:
    within twice its error at rtol = 1e-5, where the time steps' share is small (measured
    2.4e-5 against the half-space's 4.8e-5; the point read-out gave 4.3e-3). At the default
    rtol both are dominated by the time steps (7.8e-4 and 2.0e-4). About 3 s."""
    params = CollisionParameters.from_settings(
        St=20.0, eps=1e-3, layer="thin", cavitation="none", delta=0.05
    )
    errors = {
        model: collide(params, RunConfig.from_settings(model=model, rtol=1e-5)).normal.energy_error
        for model in ("halfspace", "fem")
    }
    print(f"energy balance at delta = 0.05: {errors}")
    assert errors["fem"] < 2 * errors["halfspace"]


def test_film_reaching_round_the_sphere_is_refused():
    """The film must stay within 0.7 of the (smaller) sphere radius: R = 2 at delta = 0.2 is
    r = 0.89 a."""
    with pytest.raises(InputError, match="film"):
        FESolids(0.2, radial_grid(20, 0.5, 2.0), comm=MPI.COMM_SELF)


@pytest.mark.slow
@pytest.mark.serial
@pytest.mark.parametrize(
    ("options", "expected", "tolerance"),
    [
        # a coating of the wall's own material changes nothing
        ({"lower": CoatedWall(0.02, 1.0, 0.3)}, "wall", 1e-5),
        # a thick coating 10x softer: theta_eff / theta = (1 + 10) / 2 against the bare wall
        ({"lower": CoatedWall(1.0, 0.1, 0.3)}, 5.5, 0.01),
        # two spheres (radii 2a and 2a, or 4a and 4a/3) behave like half-spaces near the axis
        ({"lower": LowerSphere(1.0)}, "halfspace", 0.01),
        ({"lower": LowerSphere(3.0)}, "halfspace", 0.01),
    ],
)
def test_coated_wall_and_two_spheres(small_delta, options, expected, tolerance):
    """Exact limits of the other geometries at delta = 1e-3, on the axis and for R <= 0.5."""
    pressure = hertz_like(RADII)
    w = FESolids(1e-3, RADII, comm=MPI.COMM_SELF, **options).compliance(1.0).deflection(pressure)
    if expected == "wall":
        reference = small_delta.deflection(pressure)
    elif expected == "halfspace":
        reference = HalfSpaceCompliance(RADII, 1.0).deflection(pressure)
    else:
        reference = expected * small_delta.deflection(pressure)
    near = RADII <= 0.5
    assert np.abs(w[near] / reference[near] - 1).max() < tolerance


def vertex_opening(solids, shape):
    """The gap opening at the film nodes from the vertex displacements of ``shape`` (a
    :class:`ehdfem.solids.fe.fields.Deformation`, gathered over the ranks): u_z of the sphere's
    face minus u_z of the lower face at the vertices r = r_i, each free sphere relative to its
    centre of mass (a point read-out, not the reciprocal one)."""
    comm = solids.comm
    points, displacement, upper = (
        np.concatenate(comm.allgather(a)) for a in (shape.points, shape.displacement, shape.upper)
    )
    opening = []
    for r in solids.radii_a:
        at = np.isclose(points[:, 0], r, rtol=0, atol=1e-12)
        top = np.flatnonzero(at & upper)[np.argmin(points[at & upper, 1])]
        bottom = np.flatnonzero(at & ~upper)[np.argmax(points[at & ~upper, 1])]
        opening.append(displacement[top, 1] - displacement[bottom, 1])
    return np.array(opening)


@pytest.mark.parametrize("lower", [Wall(), LowerSphere()])
def test_deformation_matches_the_compliance_at_the_film_nodes(lower):
    """Runs on 2 ranks too: the solids under a film pressure open the gap, read out as the
    compliance reads it (``gap_opening``, the hat-weighted vertical motion of the faces), by
    compliance.deflection(P) (to 1e-9); the vertex displacements (by x0, free spheres relative
    to their centre of mass) at the film nodes agree with it to the difference between a point
    value and a hat average, within 1 % of the largest opening inside the last node (whose
    half hat reads only its inner side; measured 0.47 %, near the pressure's edge); the
    stresses are finite, one per owned triangle, and linear in the load; ``upper`` marks the
    sphere."""
    comm = MPI.COMM_WORLD
    radii = radial_grid(20, 0.5, 2.0)
    solids = FESolids(1e-3, radii, lower=lower, comm=comm)
    assert len(solids.free_bodies) == (2 if lower.kind == "sphere" else 1)
    assert solids.free_bodies[0].direction == -1.0
    compliance = solids.compliance(1e-3)
    assert compliance.surface_radii == ((2.0, 2.0) if lower.kind == "sphere" else (1.0, np.inf))
    pressure = hertz_like(radii)
    half = solids.deformation(0.5 * pressure, compliance.eps)
    shape = solids.deformation(pressure, compliance.eps)
    expected = compliance.deflection(pressure)
    opening = solids.gap_opening() * solids.scale(compliance.eps)
    assert np.allclose(opening, expected, rtol=0, atol=1e-9 * np.abs(expected).max())
    n, m = len(shape.points), len(shape.triangles)
    assert shape.displacement.shape == (n, 2) and shape.upper.shape == (n,)
    assert shape.triangles.max() < n and shape.von_mises.shape == shape.hydrostatic.shape == (m,)
    assert np.isfinite(shape.von_mises).all() and (shape.von_mises >= 0).all()
    assert np.allclose(half.hydrostatic, 0.5 * shape.hydrostatic, rtol=1e-8, atol=1e-12)
    above = shape.points[:, 1] > solids.delta / 2  # the film is between z = 0 and z = delta
    assert (shape.upper == above).all()
    points = vertex_opening(solids, shape)
    error = np.abs(points - expected)[:-1].max() / np.abs(expected).max()
    print(f"vertex opening against the read-out ({lower}): {error:.2e}")
    assert error < 1e-2


def antisymmetry(matrix) -> float:
    """||A - A^T|| / ||A|| (Frobenius)."""
    return float(np.linalg.norm(matrix - matrix.T) / np.linalg.norm(matrix))


@pytest.mark.serial
@pytest.mark.parametrize("options", LOWER_BODIES)
def test_compliance_is_reciprocal(options):
    """delta = 0.05, 16 film nodes. Loads and read-outs are the same balanced functionals, so
    with M the film's lumped mass (Film.full_mass), all four blocks are reciprocal to the
    direct solver's rounding, 1e-12 relative in the Frobenius norm (measured below 1e-14): M C
    (gap from pressure) and M C_TT (the faces' tangential displacement from shear) symmetric,
    and M C_nT = (M C_tP)^T: the gap from shear against the tangential displacement (the sum
    of both faces', twice the mean) from pressure, the shear's sqrt(delta) unit divided out.
    On a wall, the point read-out that it replaces (u_z at the nodes, as the vertices give it)
    is far from reciprocal: measured 0.16 (0.14, 0.13 and 0.16 on a wall, a coated wall and a
    sphere on 20 nodes)."""
    radii = radial_grid(16, 0.5, 2.0)
    solids = FESolids(0.05, radii, comm=MPI.COMM_SELF, **options)
    blocks = solids._condensed(shear=True)
    mass = Film(radii).full_mass[:, None]
    shear = np.sqrt(solids.delta)
    assert antisymmetry(mass * blocks["gap"]) < 1e-12
    assert antisymmetry(mass * blocks["radial_shear"]) < 1e-12
    gap_from_shear = mass * blocks["shear"] / shear
    tangential_from_pressure = mass * 2 * blocks["radial_pressure"]
    difference = gap_from_shear - tangential_from_pressure.T
    assert np.linalg.norm(difference) < 1e-12 * np.linalg.norm(gap_from_shear)
    if not options:
        hats = np.eye(len(radii))
        point = np.column_stack(
            [vertex_opening(solids, solids.deformation(hat, 1.0)) for hat in hats.T]
        ) / solids.scale(1.0)
        measured = antisymmetry(mass * point)
        print(f"point read-out: ||MC - (MC)^T|| / ||MC|| = {measured:.3f}")
        assert measured > 0.05
    solids.close()


def test_pressure_on_the_solids_is_linear_between_film_nodes_and_zero_beyond():
    radii = radial_grid(20, 0.5, 2.0)
    solids = FESolids(1e-3, radii, comm=MPI.COMM_WORLD)
    nodal = hertz_like(radii) + 0.1
    pressure = solids.film_pressure(nodal)
    middle = 0.5 * (solids.radii_a[3] + solids.radii_a[4])
    assert np.allclose(pressure(solids.radii_a), nodal)
    assert pressure(middle) == pytest.approx(0.5 * (nodal[3] + nodal[4]))
    assert pressure(1.01 * solids.radii_a[-1]) == 0.0


def test_fe_compliance_at_another_eps():
    """The FE compliance is linear in eps and keeps its solids."""
    compliance = FESolids(1e-3, radial_grid(20, 0.5, 2.0), comm=MPI.COMM_WORLD).compliance(1e-3)
    other = compliance.with_eps(3e-3)
    assert compliance.model == other.model == "fem" and other.solids is compliance.solids
    assert other.eps == 3e-3 and np.allclose(other.matrix, 3 * compliance.matrix, rtol=1e-14)


def test_cached_compliance_is_the_computed_one(tmp_path, monkeypatch):
    """With a compliance cache (rank 0's temporary directory), the second build of the same
    solids reads the axisymmetric unit matrices (pressure, shear, surface sum) and the mode-1
    one bit for bit, without solving; other moduli are another entry. On 2 ranks too."""
    comm = MPI.COMM_WORLD
    monkeypatch.setattr(fem_mesh, "COMPLIANCE_CACHE", comm.bcast(str(tmp_path)))
    radii = radial_grid(30, 0.5, 2.0)
    first = FESolids(1e-3, radii)
    computed = first.compliance(1.0, shear=True), FEModeOne(first, 1.0)

    def fail(*_):
        raise AssertionError("solved although cached")

    monkeypatch.setattr(FESolids, "_condensed", fail)
    monkeypatch.setattr(FEModeOne, "_condense", fail)
    again = FESolids(1e-3, radii)
    cached = again.compliance(1.0, shear=True), FEModeOne(again, 1.0)
    for name in ("unit_matrix", "unit_shear", "unit_surface_sum"):
        assert np.array_equal(getattr(cached[0], name), getattr(computed[0], name))
    assert np.array_equal(cached[1].unit_matrix, computed[1].unit_matrix)
    if comm.rank == 0:
        assert len(list(Path(tmp_path).glob("*.npz"))) == 2
    with pytest.raises(AssertionError, match="although cached"):
        FESolids(1e-3, radii, wall=(0.5, 0.3)).compliance(1.0, shear=True)


def test_the_caches_are_kept_apart_per_library_versions(tmp_path, monkeypatch):
    """A mesh or compliance cached by one install stack (gmsh, DOLFINx and PETSc versions) is
    not read by the other: with other versions reported the solids are meshed and solved
    again. On 2 ranks too."""
    comm = MPI.COMM_WORLD
    folder = Path(comm.bcast(str(tmp_path)))
    monkeypatch.setattr(fem_mesh, "COMPLIANCE_CACHE", str(folder / "compliances"))
    monkeypatch.setattr(fem_mesh, "MESH_CACHE", folder / "meshes")
    radii = radial_grid(20, 0.5, 2.0)
    FESolids(1e-3, radii).compliance(1.0)
    versions = fem_mesh.library_versions()
    assert [v.split()[0] for v in versions] == ["gmsh", "dolfinx", "petsc"]
    monkeypatch.setattr(
        fem_mesh, "library_versions", lambda meshing_only=False: ("gmsh 0.0",) + versions[1:]
    )

    def fail(*_):
        raise AssertionError("solved again")

    monkeypatch.setattr(FESolids, "_condensed", fail)
    with pytest.raises(AssertionError, match="solved again"):
        FESolids(1e-3, radii).compliance(1.0)
    if comm.rank == 0:
        assert len(list((folder / "meshes").glob("*.msh"))) == 2
