"""A second, free sphere below the film, in both elasticity models."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from meshes import contact

from ....settings import setting
from .base import FreeBody, LowerBody, register


@register
@dataclass(frozen=True)
class LowerSphere(LowerBody):
    """A second, free sphere of the wall's material below the film: a is the reduced radius
    a1 a2 / (a1 + a2) and m the reduced mass m1 m2 / (m1 + m2), in both elasticity models;
    ``radius_ratio`` = a1/a2 (upper over lower): a1 = a (1 + ratio), a2 = a (1 + 1/ratio). For
    its tangential motion (:mod:`ehdfem.tangential.pair`): its density over the upper sphere's,
    its inertia factor k2 = I2 / (m2 a2^2) and its initial spin a2 Omega2 / V0, counted about
    the same axis as the upper sphere's (its surface at the contact then moves at U2 + a2
    Omega2 along x)."""

    kind: ClassVar[str] = "sphere"
    description: ClassVar[str] = (
        "a second free sphere: St, eps, delta by the reduced radius and mass"
    )
    models: ClassVar[tuple[str, ...]] = ("halfspace", "fem")
    radius_ratio: float = setting(
        1.0, help="upper sphere radius / lower sphere radius a1/a2", lower=0.0, lower_open=True
    )
    density_ratio: float = setting(
        1.0, help="lower sphere density / upper sphere density rho2/rho1 (mean densities)",
        lower=0.0, lower_open=True,
    )  # fmt: skip
    lower_inertia_factor: float = setting(
        0.4, help="lower sphere inertia I2 / (m2 a2^2) (2/5 solid, 2/3 thin shell)", lower=0.0,
        upper=2 / 3, lower_open=True,
    )  # fmt: skip
    lower_spin: float = setting(
        0.0, help="lower sphere's initial spin about the upper sphere's spin axis (its surface "
        "at the contact moves at a2 Omega2 along the tangential velocity)", unit="a2 Omega2 / V0",
    )  # fmt: skip

    @property
    def mass_ratio(self) -> float:
        """m1 / m2 = (a1/a2)^3 / (rho2/rho1)."""
        return self.radius_ratio**3 / self.density_ratio

    @property
    def sphere_radius(self):
        return 1 + self.radius_ratio

    @property
    def radius(self):
        return 1 + 1 / self.radius_ratio

    def materials(self, wall):
        return {contact.LOWER: wall}

    def free_body(self):
        return FreeBody(contact.LOWER, contact.LOWER_CONTACT, -2 * self.radius, 1.0, self.radius)

    def geometry(self, gap, contact_radii, size):
        arguments = (gap, contact_radii, self.kind, size, self.sphere_radius, self.radius, None)
        return contact.build, arguments
