"""LIGGGHTS (3.8) on one wet collision: two equal spheres through a liquid layer, with the
Hertz contact and the liquid bridge ``cohesion easo/capillary/viscous`` (its wall version is dry
only, hence two spheres).

The law, in SI (LIGGGHTS's cohesion_model_easo_capillary_viscous.h): the bridge forms at
contact and, while the gap h between the surfaces is below its rupture distance (the smaller
of (maxSeparationDistanceRatio - 1)(R1 + R2) and Lian's (1 + theta/2) V_bond^(1/3)), the
viscous force is

    F = 6 pi mu R*^2 v / max(h, minSeparationDistanceRatio R*),   R* = R1 R2 / (R1 + R2),

with the capillary force (zero here: surface tension 0, since the full model has none), and
the tangential viscous force -6 pi mu R* (8/15 ln(R*/h) + 0.9588) v_t on the relative
tangential velocity v_t of the surfaces at the contact (h capped alike), with its torque about
each centre at the sphere's radius. No liquid force acts while the spheres approach: the
bridge does not exist before contact. The dry contact is Hertz's with Mindlin's tangential
spring (``tangential history``) up to Coulomb's limit at the collision's friction coefficient.
The liquid volume is set so that Lian's rupture distance is beyond the cut-off; the cut-off's
default, maxSeparationDistanceRatio = 1 + x0 / (2 R), breaks the bridge at the layer's
thickness x0.

The spheres, each of the collision's radius R, material and mass (e.g. 4/3 pi R^3 rho), meet
at the relative normal speed V0 (the collision's normal speed) along x, starting at the gap
x0, and, obliquely, with the relative tangential speed U0 = |v| sin(angle) along y; sphere 1
(at -x) is ehdfem's upper sphere and carries the initial spin. ehdfem's axes are then
z = -x (the normal from sphere 2 to sphere 1), x = y (the tangential motion) and y = -z, so
that its spin about y, rolling sense positive, is -omega_z of sphere 1 (its contact point
moves at v_y + R omega_z, ehdfem's U - a Omega); e_t = (v_1 - v_2).t / U0 (t the tangent)
and the spin change
-R (omega_z1 - omega_z1(0)) / U0 are read at the exit (or the run's end if they stick).
The relative velocity is split along the line of centres as it stands at each moment (the gap
is the distance of the centres less 2R): obliquely it turns during the collision by about
x0 tan(angle) / R, and the normal force's share along the first tangent would otherwise count
as a tangential impulse. The full model's counterpart
(:func:`ehdfem.dem.engines.compare.full_model_collision`) is the half-space model at the
reduced radius R/2 and mass m/2 (Davis, Serayssol & Hinch 1986).

The input (in.collision) is written into a folder and run there with
``liggghts -in in.collision``; LIGGGHTS writes history.txt (t [s], gap [m], relative normal
velocity [m/s], force on the first sphere [N], the relative tangential velocity of sphere 1
[m/s] and both spins omega_z [rad/s]); ehdfem reads it and writes rebound.json.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ... import checks
from ...exact import hertz
from ...inputs.scales import PhysicalCollision
from ...settings import setting, validate
from .rebound import EngineRebound, read_rebound, run_binary

SCRIPT = "in.collision"
RERUN = f"liggghts -in {SCRIPT}"  # by hand, in the folder
LOG = "log.liggghts"
LAYER_TIMES = 40.0  # the run ends after 40 x0/V0 (+ 10 Hertz contact times): then stuck
GAP_BY_ROUGHNESS = 3.0  # the smallest gap by sigma closest to the full model's impact model
# (e_n within 0.05 for sigma / x0 = 0.01-0.1, St 10-170; docs/validation.md, "DEM engines")


@dataclass(frozen=True)
class LiggghtsLaw:
    """The settings of LIGGGHTS's liquid bridge that a DEM user chooses (see the module
    docstring); the viscosity, moduli and radius come from the collision."""

    liggghts_min_separation: float = setting(
        0.01, help="minSeparationDistanceRatio: the smallest gap in the viscous force (1.01 "
        "is LIGGGHTS's recommended value)", unit="by R*", lower=0.0, upper=2.0, lower_open=True,
        default_text="0.01 on smooth surfaces, 3 sigma / R* on rough ones (the surfaces' "
        "combined rms roughness sigma)",
    )  # fmt: skip
    liggghts_max_separation: float | None = setting(
        None, help="maxSeparationDistanceRatio: the bridge breaks at the gap (ratio - 1) 2 R",
        lower=1.0, lower_open=True, default_text="1 + x0 / (2 R), the layer's thickness",
    )  # fmt: skip
    liggghts_time_step: float = setting(
        0.01, help="LIGGGHTS's time step", unit="by the Hertz contact time", lower=0.0,
        upper=0.1, lower_open=True,
    )  # fmt: skip

    def __post_init__(self):
        validate(self)


def min_separation_of(collision: PhysicalCollision, factor: float = GAP_BY_ROUGHNESS) -> float:
    """minSeparationDistanceRatio of the surfaces' combined rms roughness sigma [m]: the viscous
    force's smallest gap minSeparationDistanceRatio R* is ``factor`` sigma, the ratio
    factor sigma / R* with R* = R / 2."""
    return factor * collision.roughness / (collision.radius / 2.0)


def hertz_contact_time(collision: PhysicalCollision) -> float:
    """Duration [s] of the dry Hertz contact of two equal spheres at the relative speed V0:
    2.87 (m*^2 / (R* E*^2 V0))^(1/5), m* = m/2, R* = R/2, 1/E* = 2 (1 - nu^2) / E."""
    material = collision.sphere
    e_star = material.young_modulus / (2.0 * (1.0 - material.poisson_ratio**2))
    return hertz.contact_time(
        collision.mass / 2.0, collision.radius / 2.0, e_star, collision.normal_speed
    )


def cut_off(collision: PhysicalCollision, law: LiggghtsLaw) -> float:
    """maxSeparationDistanceRatio: the given one, or 1 + x0 / (2 R)."""
    if law.liggghts_max_separation is not None:
        return law.liggghts_max_separation
    return 1.0 + collision.layer_thickness / (2.0 * collision.radius)


def liquid_content(collision: PhysicalCollision, law: LiggghtsLaw) -> float:
    """surfaceLiquidContentInitial c such that Lian's rupture distance (V_bond)^(1/3), with
    V_bond = (4/3) pi R^3 c (1 - sqrt(3)/2) for two equal spheres (contact angle 0), is 1.5
    times the cut-off's gap (ratio - 1) 2 R, so that the cut-off breaks the bridge."""
    gap = 1.5 * (cut_off(collision, law) - 1.0) * 2.0 * collision.radius
    return gap**3 / (4.0 / 3.0 * math.pi * collision.radius**3 * (1.0 - math.sqrt(3.0) / 2.0))


def check_equal_spheres(collision: PhysicalCollision) -> None:
    """Refuse a collision whose wall differs from its sphere: LIGGGHTS collides two equal
    spheres (its liquid bridge on a wall is dry only)."""
    if collision.wall != collision.sphere:
        raise checks.InputError(
            f"LIGGGHTS collides two equal spheres: the wall ({collision.wall.name}) must be "
            f"the sphere's material ({collision.sphere.name})",
            "wall",
        )


def script(collision: PhysicalCollision, law: LiggghtsLaw) -> str:
    """The LIGGGHTS input of ``collision`` with ``law`` (SI)."""
    check_equal_spheres(collision)
    r, x0, v0 = collision.radius, collision.layer_thickness, collision.normal_speed
    u0 = collision.tangential_speed
    material = collision.sphere
    dt = law.liggghts_time_step * hertz_contact_time(collision)
    duration = LAYER_TIMES * x0 / v0 + 10.0 * hertz_contact_time(collision)
    half = 2.0 * r + x0 + v0 * duration
    density = collision.mass / (4.0 / 3.0 * math.pi * r**3)
    return f"""# Two equal spheres through a liquid layer, LIGGGHTS's easo/capillary/viscous bridge,
# written by ehdfem (ehdfem.dem.engines.liggghts). Rerun: liggghts -in {SCRIPT}
# SI units. Radius {r!r} m, layer {x0!r} m, relative speed {v0!r} m/s.
units si
hard_particles yes
atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
region domain block {-half!r} {half!r} {-2 * r!r} {2 * r!r} {-2 * r!r} {2 * r!r} units box
create_box 1 domain
neighbor {x0 + 0.1 * r!r} bin
neigh_modify delay 0
fix m1 all property/global youngsModulus peratomtype {material.young_modulus!r}
fix m2 all property/global poissonsRatio peratomtype {material.poisson_ratio!r}
fix m3 all property/global coefficientRestitution peratomtypepair 1 {collision.e_dry!r}
fix m4 all property/global coefficientFriction peratomtypepair 1 {collision.friction_coefficient!r}
fix l1 all property/global surfaceLiquidContentInitial scalar {liquid_content(collision, law)!r}
fix l2 all property/global surfaceTension scalar 0.0
fix l3 all property/global fluidViscosity scalar {collision.liquid.viscosity!r}
fix l4 all property/global contactAngle peratomtype 0.0
fix l5 all property/global minSeparationDistanceRatio scalar {law.liggghts_min_separation!r}
fix l6 all property/global maxSeparationDistanceRatio scalar {cut_off(collision, law)!r}
pair_style gran model hertz tangential history cohesion easo/capillary/viscous
pair_coeff * *
timestep {dt!r}
create_atoms 1 single {-(r + x0 / 2)!r} 0 0 units box
create_atoms 1 single {r + x0 / 2!r} 0 0 units box
set atom * diameter {2 * r!r} density {density!r}
velocity all set 0 0 0 units box
set atom 1 vx {v0 / 2!r} vy {u0 / 2!r} omegaz {-collision.spin!r}
set atom 2 vx {-v0 / 2!r} vy {-u0 / 2!r}
fix integrate all nve/sphere
compute spin all property/atom omegaz
variable t equal time
variable dx equal x[2]-x[1]
variable dy equal y[2]-y[1]
variable distance equal sqrt(v_dx*v_dx+v_dy*v_dy)
variable gap equal v_distance-{2 * r!r}
variable vrel equal ((vx[2]-vx[1])*v_dx+(vy[2]-vy[1])*v_dy)/v_distance
variable force equal fx[1]
variable slide equal ((vy[1]-vy[2])*v_dx-(vx[1]-vx[2])*v_dy)/v_distance
variable spin1 equal c_spin[1]
variable spin2 equal c_spin[2]
fix history all print 10 "${{t}} ${{gap}} ${{vrel}} ${{force}} ${{slide}} ${{spin1}} ${{spin2}}" file history.txt screen no title "time_s gap_m separation_velocity_m_s force_N tangential_velocity_m_s omega_z1_rad_s omega_z2_rad_s"
thermo 100000
run {math.ceil(duration / dt)}
"""  # noqa: E501


def rebound_of_history(history: np.ndarray, collision: PhysicalCollision) -> dict:
    """e_n, e_t, the spin change (module docstring; None head-on), rebounded, time in the
    layer [s] and the thinnest gap [m] from the rows (t, gap, separation velocity, force,
    v_y1 - v_y2, omega_z1, omega_z2): the first row after contact where the gap is back at
    x0, else the last."""
    time, gap, velocity = history[:, 0], history[:, 1], history[:, 2]
    x0, v0 = collision.layer_thickness, collision.normal_speed
    touched = np.argmax(gap <= 0.0) if np.any(gap <= 0.0) else len(gap)
    out = np.flatnonzero((gap[touched:] >= x0) & (velocity[touched:] > 0.0))
    rebounded = out.size > 0
    end = touched + out[0] if rebounded else len(gap) - 1
    u0 = collision.tangential_speed
    oblique = u0 > 0.0
    spin = history[:, 5]
    return {
        "e_n": float(velocity[end] / v0) if rebounded else 0.0,
        "e_t": float(history[end, 4] / u0) if oblique else None,
        "spin_change": float(-collision.radius * (spin[end] - spin[0]) / u0) if oblique else None,
        "rebounded": bool(rebounded),
        "time_in_layer": float(time[end]),
        "thinnest_gap": float(gap.min()),
    }


def run(collision: PhysicalCollision, law: LiggghtsLaw, folder: Path) -> EngineRebound:
    """Write in.collision into ``folder`` (made if missing), run LIGGGHTS there, read its
    history and write and return the rebound."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "rebound.json").unlink(missing_ok=True)
    (folder / SCRIPT).write_text(script(collision, law))
    run_binary(["liggghts", "-in", SCRIPT, "-log", LOG, "-screen", "none"], folder, "screen.txt")
    history = np.loadtxt(folder / "history.txt", comments="#", skiprows=1, ndmin=2)
    rebound = rebound_of_history(history, collision)
    (folder / "rebound.json").write_text(json.dumps(rebound, indent=2) + "\n")
    return read_rebound("liggghts", folder, SCRIPT, LOG)
