"""The seam between ehdfem and FEniCSx: every use of DOLFINx objects (meshes, spaces, functions,
forms, conditions), of basix, and of the PETSc objects they assemble into, so that a change of
DOLFINx release touches this package alone.

It serves Debian 12's DOLFINx 0.5.2 and the wheels' 0.11 (``dolfinx-solver-real`` on Python
>= 3.12, numpy 2, petsc4py 3.25) at once. Each difference is decided, in one function, by what
the installed DOLFINx offers (``hasattr(fem, "functionspace")``, a dofmap that is already a 2-D
array, ...), not by its version number, so a release in between takes whichever form it has;
the docstring of each such function names both forms.

By role: :mod:`.libraries` (loading DOLFINx and petsc4py, MPI and h5py first), :mod:`.meshes`
(gmsh to DOLFINx, vertices, cells, facets, tags), :mod:`.spaces` (the finite-element spaces and
their dofs), :mod:`.functions` (functions, constants, their values, interpolation, point
values), :mod:`.assembly` (compiled forms, assembled matrices, vectors and integrals, Dirichlet
conditions), :mod:`.solvers` (linear and nonlinear solves), :mod:`.matrices` (PETSc matrices:
products, a Cholesky factorisation for blocks of loads, to scipy) and :mod:`.schur` (a Schur
complement from one MUMPS factorisation).

The physics stays with the physics: the weak forms are written in UFL by the modules that own
them (UFL is the same form language on both releases; its element constructors, which are not,
are used here only). The callers hold DOLFINx and PETSc objects as opaque handles and give them
back to these functions. Nothing here knows about scales: meshes, spaces, matrices and vectors
carry whatever units the caller's forms give them.
"""
