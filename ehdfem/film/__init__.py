"""The liquid film: the axisymmetric Reynolds film (reynolds), the undeformed gap shape (gap),
the cavitation models (cavitation) and the viscosity laws (viscosity). All scaled as in
docs/model.md: film thickness by x0, radius by sqrt(a x0), pressure by mu V0 a / x0^2."""
