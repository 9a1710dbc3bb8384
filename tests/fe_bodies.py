"""The lower bodies the FE reciprocity tests run over: FESolids keyword arguments of a wall, a
coated wall (coating E ratio 0.2, nu 0.45, 0.02 a thick) and a lower sphere of twice the
radius."""

from ehdfem.solids.fe.bodies import CoatedWall, LowerSphere

LOWER_BODIES = [
    {},
    {"lower": CoatedWall(0.02, 0.2, 0.45)},
    {"lower": LowerSphere(2.0)},
]
