"""Finite-element solids (DOLFINx 0.5.2 or 0.11, gmsh): the bodies and their mesh, the
condensation to the film nodes, the mode-1 solids, and every DOLFINx call in dolfinx_compat."""
