"""Finite-element solids (DOLFINx 0.5.2 or 0.11, gmsh): the bodies and their mesh, the
condensation to the film nodes and the mode-1 solids; DOLFINx is used through
:mod:`ehdfem.fenicsx`."""
