"""The tangential motion and spin during the collision (Couette and sliding-film lubrication) and
the validity check of the sliding film's mode-1 superposition. Scaled: velocities by V0 (slip) or
U0 (e_t), time by x0/V0."""
