"""Reduced models for particle simulations (DEM): published wet-restitution formulas, fits to
computed tables and closed forms to copy into a DEM code (closedform)."""
