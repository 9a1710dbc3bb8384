"""Real DEM engines run on one wet collision, beside the full model: Yade's implicit
lubrication law (a sphere on a wall, yade.py) and LIGGGHTS's liquid bridge
easo/capillary/viscous (two equal spheres, liggghts.py); what a run gives back (rebound.py)."""
