"""The elastic solids as seen by the film: the compliance interface (compliance), the half-space
ring-load kernels (halfspace, halfspace_mode_one) and the finite-element solids (fe). A
compliance maps the film pressure (by mu V0 a / x0^2) at the film nodes (by sqrt(a x0)) to the
gap opening (by x0)."""
