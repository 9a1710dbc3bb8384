"""The lower bodies the FE reciprocity tests run over: FESolids keyword arguments of a wall, a
coated wall (coating E ratio 0.2, nu 0.45, 0.02 a thick) and a lower sphere of twice the
radius."""

LOWER_BODIES = [
    {},
    {"lower": "coated", "coating": (0.2, 0.45), "coating_thickness": 0.02},
    {"lower": "sphere", "radius_ratio": 2.0},
]
