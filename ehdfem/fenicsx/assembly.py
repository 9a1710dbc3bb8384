"""Compiled forms and what they assemble into: PETSc matrices and vectors, owned values,
integrals; and the Dirichlet conditions applied to them."""

from __future__ import annotations

import inspect

import numpy as np

from .functions import function
from .libraries import fem, fem_petsc, petsc
from .spaces import sub_space, velocity_component_dofs


def form(expression):
    """The compiled form of the UFL ``expression`` (bilinear, linear or a functional)."""
    return fem().form(expression)


def integral(integrand, comm) -> float:
    """The value of the functional ``integrand`` (a UFL form with its measure), summed over the
    ranks of ``comm``."""
    module = fem()
    return comm.allreduce(module.assemble_scalar(module.form(integrand)))


def assemble_matrix(form, bcs):
    """The assembled PETSc matrix of a bilinear ``form``, with the rows and columns of the
    Dirichlet ``bcs`` replaced by the identity.

    0.5: ``fem.petsc.assemble_matrix(form, bcs=bcs)`` then ``.assemble()``; the same in 0.11,
    where the submodule must be imported explicitly.
    """
    matrix = fem_petsc().assemble_matrix(form, bcs=bcs)
    matrix.assemble()
    return matrix


def assembled_values(form) -> np.ndarray:
    """The owned entries of the assembled vector of the linear ``form``, ghost contributions
    summed onto their owners (a copy; the PETSc vector is freed).

    ``fem.petsc.assemble_vector`` and ``ghostUpdate(ADD, REVERSE)``: the same calls in 0.5 and
    0.11.
    """
    PETSc = petsc()
    vector = fem_petsc().assemble_vector(form)
    try:
        vector.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
        return vector.getArray().copy()
    finally:
        vector.destroy()


def vector_of(form):
    """A ghosted PETSc vector laid out as the test space of the linear ``form``, not zeroed.

    0.5: ``fem.petsc.create_vector(form)``; 0.10 takes the space instead of the form
    (``create_vector(form.function_spaces[0])``).
    """
    create = fem_petsc().create_vector
    if next(iter(inspect.signature(create).parameters)) == "V":  # 0.10+: of a space ("V")
        return create(form.function_spaces[0])
    return create(form)  # 0.5: of a form ("L")


def assemble_lifted(vector, linear, bilinear, bcs, x0=None, scale: float = 1.0) -> None:
    """Assemble the linear form ``linear`` into the PETSc ``vector`` (zeroed first), lift the
    Dirichlet ``bcs`` of the bilinear form ``bilinear`` (b - scale A (g - x0)), sum the ghosts
    onto their owners and set the constrained rows to scale (g - x0).

    Positional arguments, as the keywords differ: 0.5 ``apply_lifting(b, [a], [bcs], x0=[x],
    scale=s)`` and ``set_bc(b, bcs, x0, scale)``; 0.10+ names ``scale`` ``alpha`` (and takes
    ``x0=None`` for none).
    """
    PETSc = petsc()
    module = fem_petsc()
    with vector.localForm() as local:
        local.set(0.0)
    module.assemble_vector(vector, linear)
    module.apply_lifting(vector, [bilinear], [bcs], [] if x0 is None else [x0], scale)
    vector.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
    module.set_bc(vector, bcs, x0, scale)


def zero_condition(space, dofs, component: int | None = None):
    """The homogeneous Dirichlet condition on the ``dofs`` of ``space`` (every component of a
    vector space), or of its ``component`` (then ``dofs`` is the pair of
    :func:`ehdfem.fenicsx.spaces.entity_dofs`)."""
    module, PETSc = fem(), petsc()
    if component is not None:
        sub, collapsed = sub_space(space, component)
        return module.dirichletbc(function(collapsed), dofs, sub)
    size = space.dofmap.index_map_bs
    value = np.zeros(size, dtype=PETSc.ScalarType) if size > 1 else PETSc.ScalarType(0.0)
    return module.dirichletbc(value, dofs, space)


def velocity_component_condition(space, component: int, facets, value):
    """The Dirichlet condition ``value`` (a number, or a constant of
    :func:`ehdfem.fenicsx.functions.constant` whose value can be changed between solves) on
    ``component`` of the velocity of a Taylor-Hood ``space`` on the mesh ``facets``."""
    dofs = velocity_component_dofs(space, component, facets)
    if isinstance(value, int | float):
        value = petsc().ScalarType(value)
    return fem().dirichletbc(value, dofs, space.sub(0).sub(component))


def constrained_rows(form, bcs) -> np.ndarray:
    """The owned rows of the vector of the linear ``form`` that the Dirichlet ``bcs`` fix
    (a vector of ones, the constrained rows set to zero: :func:`vector_of`, ``set_bc``)."""
    marker = vector_of(form)
    with marker.localForm() as local:
        local.set(1.0)
    fem_petsc().set_bc(marker, bcs)
    rows = np.flatnonzero(marker.getArray() == 0.0)
    marker.destroy()
    return rows
