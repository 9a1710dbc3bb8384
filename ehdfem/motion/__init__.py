"""The sphere's normal motion through the film: the equation of motion and its forces, one implicit
step, the BDF time stepper, the time loop with its events and the histories. Scaled: time by x0/V0,
gap by x0, velocity by V0."""
