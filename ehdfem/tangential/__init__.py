"""The tangential motion and spin during the collision (Couette and sliding-film lubrication,
motion), the full 2-D sliding film on the disk at one instant (disk, DOLFINx) and the validity
check of the sliding film's mode-1 superposition against it (superposition). Scaled: velocities
by V0 (slip) or U0 (e_t), time by x0/V0, pressure by mu V0 a / x0^2."""
