"""Solves of assembled problems: a linear one by a direct factorisation, a nonlinear one (with a
lower bound on the solution, or not) by Newton's method, both with MUMPS.

Both are assembled by hand into PETSc objects (:mod:`.assembly`) on 0.5 and 0.11 alike. 0.10's
``fem.petsc.LinearProblem`` and ``NonlinearProblem`` build the same solvers, but register
options of their own at each construction, and the bounded solve needs the SNES before the
solve anyway, so the one hand-written path serves both releases. Every PETSc object is
destroyed after the solve, so these can be called any number of times.
"""

from __future__ import annotations

from .assembly import assemble_lifted, assemble_matrix, vector_of
from .functions import petsc_vector
from .libraries import fem_petsc, petsc

METHODS = ("newton", "linear")
"""Of :func:`solve_nonlinear`: Newton's method with a line search, or one linear solve per
iteration (for a residual linear in the solution)."""
BOUNDED_OPTIONS_PREFIX = "ehdfem_bounded_newton_"  # of the PETSc options of a bounded solve


def solve_linear(bilinear, linear, bcs, solution) -> None:
    """Solve the linear problem a(u, v) = L(v) with the Dirichlet ``bcs`` (lifted) by a direct
    LU factorisation (MUMPS) into the function ``solution``; raises if PETSc reports a failure."""
    PETSc = petsc()
    matrix = assemble_matrix(bilinear, bcs)
    vector = vector_of(linear)
    assemble_lifted(vector, linear, bilinear, bcs)
    ksp = PETSc.KSP().create(solution.function_space.mesh.comm)
    try:
        ksp.setOperators(matrix)
        _direct(ksp, "lu")
        ksp.solve(vector, petsc_vector(solution))
        if ksp.getConvergedReason() <= 0:
            raise RuntimeError(f"the linear solve failed (KSP reason {ksp.getConvergedReason()})")
        solution.x.scatter_forward()
    finally:
        for petsc_object in (ksp, matrix, vector):
            petsc_object.destroy()


def _direct(ksp, factorisation: str) -> None:
    """Make ``ksp`` one solve with the MUMPS ``factorisation`` ("lu" or "cholesky")."""
    ksp.setType("preonly")
    ksp.getPC().setType(factorisation)
    ksp.getPC().setFactorSolverType("mumps")


def solve_nonlinear(
    residual,
    jacobian,
    bcs,
    solution,
    *,
    rtol: float,
    atol: float,
    max_iterations: int,
    method: str = "newton",
    lower_bound: float | None = None,
):
    """Solve residual(u) = 0 for the function ``solution`` (its values the initial guess) by
    PETSc SNES with the Jacobian form ``jacobian`` and the Dirichlet ``bcs``, the solution's
    values set on them; each linear step by MUMPS LU. Converged when the residual's norm is
    below ``rtol`` times the first one or ``atol``, after at most ``max_iterations``.
    ``method``: of METHODS. With ``lower_bound``, u >= lower_bound everywhere as a
    variational inequality (the reduced-space active-set Newton method with a full step,
    "vinewtonrsls" and a basic line search; ``method`` is then not used). Returns (SNES
    converged reason, positive when converged; iterations)."""
    if method not in METHODS:
        raise ValueError(f"method must be one of {METHODS}, got {method!r}")
    PETSc = petsc()
    module = fem_petsc()
    target = petsc_vector(solution)

    def assemble_residual(snes, x, b):
        x.ghostUpdate(addv=PETSc.InsertMode.INSERT, mode=PETSc.ScatterMode.FORWARD)
        x.copy(target)
        solution.x.scatter_forward()
        assemble_lifted(b, residual, jacobian, bcs, x, -1.0)

    def assemble_jacobian(snes, x, matrix, preconditioner):
        matrix.zeroEntries()
        module.assemble_matrix(matrix, jacobian, bcs)
        matrix.assemble()

    matrix = module.create_matrix(jacobian)
    vector = vector_of(residual)
    snes = PETSc.SNES().create(solution.function_space.mesh.comm)
    owned = [snes, matrix, vector]
    try:
        snes.setFunction(assemble_residual, vector)
        snes.setJacobian(assemble_jacobian, matrix)
        if lower_bound is None:
            snes.setType("newtonls" if method == "newton" else "ksponly")
        else:
            owned += _bound_below(snes, vector, lower_bound)
        snes.setTolerances(rtol=rtol, atol=atol, max_it=max_iterations)
        _direct(snes.getKSP(), "lu")
        snes.solve(None, target)
        return snes.getConvergedReason(), snes.getIterationNumber()
    finally:
        solution.x.scatter_forward()
        for petsc_object in owned:
            petsc_object.destroy()


def _bound_below(snes, template, lower_bound: float) -> list:
    """Make ``snes`` the bounded solve of :func:`solve_nonlinear` (u >= ``lower_bound``; the
    bounds laid out as ``template``); returns the bounds' vectors (to be destroyed)."""
    PETSc = petsc()
    snes.setType("vinewtonrsls")
    lower, upper = template.duplicate(), template.duplicate()
    lower.set(lower_bound)
    upper.set(PETSc.INFINITY)
    snes.setVariableBounds(lower, upper)
    snes.setOptionsPrefix(BOUNDED_OPTIONS_PREFIX)
    PETSc.Options()[f"{BOUNDED_OPTIONS_PREFIX}snes_linesearch_type"] = "basic"
    snes.setFromOptions()
    return [lower, upper]
