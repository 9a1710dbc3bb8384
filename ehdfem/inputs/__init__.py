"""The inputs of a collision: dimensionless groups and their physical scales (scales), material and
liquid presets (presets), input checks that name the parameter and its range (checks), and
published experiments (literature)."""
