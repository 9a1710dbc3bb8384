"""Reduced wet-collision models of CFD-DEM codes for a pair of spheres (lubrication forces with
a minimum gap, the EHD minimum film), integrated over the collision to compare with the full
model (docs/validation.md, "Two spheres obliquely: the reduced CFD-DEM models")."""
