"""Yade (2023.02a) on one wet collision: a sphere on a wall (a fixed box) through a liquid layer,
with Yade's implicit lubrication law (``Law2_ScGeom_ImplicitLubricationPhys`` with
``Ip2_FrictMat_FrictMat_LubricationPhys``; Chevremont, Chareyre & Bonnet 2019).

The law, in SI (as in Yade's source, pkg/dem/Lubrication.cpp): the lubricating gap u is in
series with a linear contact spring kn = 2 E1 a1 E2 a2 / (E1 a1 + E2 a2) (kn = E a for equal
moduli; the wall's box takes the sphere's radius),

    F = kn (un - u) = (3/2) pi eta a^2 (du/dt) / u  [+ keps kn (2 eps a - u) when u < 2 eps a],

un the gap between the undeformed surfaces, a = (a1 + a2) / 2 the mean radius (the sphere's
radius on a wall), eps the roughness (asperities touch at u = 2 eps a, then a spring keps kn in
parallel), and tangential, rolling and twist lubrication forces; in the asperities' contact a
tangential spring ks whose force Coulomb's law limits to tan(phi) times the contact's normal
force, phi = atan(mu) of the collision's ``friction_coefficient`` mu. On a wall Yade treats the wall
as a second sphere of the same radius: its rigid force (3/2) pi eta a^2 v / u is a quarter of
the wall's exact 6 pi mu a^2 v / h; ``viscosity_factor`` = 4 (the default) gives Yade eta = 4 mu,
the exact rigid wall force. The interaction starts when the gap is the layer's thickness x0
and ends when it reopens to x0 (Yade's MaxDist = x0 / a): the liquid fills the layer.

The input script (collision.py, its inputs as JSON at its top) is written into a folder and
run there by the Python that Yade's launcher names on its first line (``python3 collision.py``):
the script imports the launcher as a library, the way Yade documents for other Python programs,
so that Yade opens no TCP port (run as ``yade -n -x collision.py``, which the script also
allows, the launcher starts a Python console on port 9000 and an information server on 21000,
listening on every interface). It writes history.csv (t [s], gap [m], normal and tangential
velocity [m/s], spin [rad/s], normal force [N]) and rebound.json
(:class:`ehdfem.dem.engines.rebound.EngineRebound`).
"""

from __future__ import annotations

import json
import math
import shutil
from dataclasses import asdict, dataclass
from pathlib import Path

from ...inputs.scales import PhysicalCollision
from ...settings import setting, validate
from .rebound import EngineError, EngineRebound, read_rebound, run_binary

SCRIPT = "collision.py"
RERUN = f"python3 {SCRIPT}"  # by hand, in the folder: Yade as a library, no TCP port
LOG = "yade.log"
LAYER_TIMES = 40.0  # the run ends after 40 x0/V0 in the layer (or |V| < 1e-2 V0 for x0/V0): stuck


@dataclass(frozen=True)
class YadeLaw:
    """The settings of Yade's lubrication law that a DEM user chooses (see the module
    docstring); the viscosity, moduli and radius come from the collision."""

    yade_roughness: float = setting(
        1e-3, help="Yade's eps: the asperities touch at the film u = 2 eps a", unit="by a",
        lower=0.0, upper=0.1, lower_open=True,
        default_text="1e-3 on smooth surfaces, sigma / (2 a) on rough ones (the surfaces' "
        "combined rms roughness sigma)",
    )  # fmt: skip
    yade_keps: float = setting(
        1.0, help="Yade's keps: the asperities' stiffness by the spring kn", lower=0.0,
        lower_open=True,
    )  # fmt: skip
    yade_stiffness: float = setting(
        1.0, help="the contact spring kn by Yade's own 2 E1 a E2 a / (E1 a + E2 a) (the "
        "moduli given to Yade times this factor)", lower=0.0, lower_open=True,
    )  # fmt: skip
    yade_viscosity_factor: float = setting(
        4.0, help="Yade's eta by the liquid's viscosity (4: the exact rigid wall force "
        "6 pi mu a^2 v/h, 1: the viscosity as it is, a quarter of it on a wall)",
        lower=0.0, lower_open=True,
    )  # fmt: skip
    yade_time_step: float = setting(
        0.02, help="Yade's time step", unit="by sqrt(m / kn)", lower=0.0, upper=0.2,
        lower_open=True,
    )  # fmt: skip

    def __post_init__(self):
        validate(self)


def roughness_of(collision: PhysicalCollision, factor: float = 1.0) -> float:
    """Yade's eps of the surfaces' combined rms roughness sigma [m]: its asperities touch at the
    film u = 2 eps a = ``factor`` sigma (a the sphere's radius [m]), eps = factor sigma / (2 a).
    factor 1 (the asperities where the full model's touch) reproduces the full model's mixed
    lubrication (Greenwood-Tripp), as Yade's asperity spring acts in parallel with its film
    (docs/validation.md, "DEM engines")."""
    return factor * collision.roughness / (2.0 * collision.radius)


def contact_stiffness(collision: PhysicalCollision, law: YadeLaw) -> float:
    """Yade's spring kn = 2 E1 a E2 a / (E1 a + E2 a) [N/m] for the sphere (E1) on the wall
    (E2), both of radius a [m], the moduli times ``yade_stiffness``."""
    e1, e2 = (law.yade_stiffness * m.young_modulus for m in (collision.sphere, collision.wall))
    a = collision.radius
    return 2.0 * e1 * a * e2 * a / (e1 * a + e2 * a)


def script_inputs(collision: PhysicalCollision, law: YadeLaw) -> dict:
    """The numbers the script reads (SI): radius, mass, inertia, moduli, Poisson's ratios, the
    friction angle atan(mu) of the collision's friction coefficient, Yade's eta and eps, keps,
    layer x0, velocities, spin, time step and time limit."""
    a, x0, v0 = collision.radius, collision.layer_thickness, collision.normal_speed
    mass = collision.mass
    dt = law.yade_time_step * math.sqrt(mass / contact_stiffness(collision, law))
    return {
        "radius": a,
        "mass": mass,
        "inertia": collision.inertia_factor * mass * a**2,
        "sphere_young": law.yade_stiffness * collision.sphere.young_modulus,
        "sphere_poisson": collision.sphere.poisson_ratio,
        "wall_young": law.yade_stiffness * collision.wall.young_modulus,
        "wall_poisson": collision.wall.poisson_ratio,
        "friction_angle": math.atan(collision.friction_coefficient),
        "eta": law.yade_viscosity_factor * collision.liquid.viscosity,
        "eps": law.yade_roughness,
        "keps": law.yade_keps,
        "layer": x0,
        "normal_speed": v0,
        "tangential_speed": collision.tangential_speed,
        "spin": collision.spin,
        "time_step": dt,
        "time_limit": LAYER_TIMES * x0 / v0,
        "law": asdict(law),
    }


BODY = """
try:  # run by Yade's launcher (yade -n -x collision.py): its names are here already
    O
except NameError:  # run by Python: the launcher imported as a library starts no TCP server
    import importlib.machinery
    import importlib.util
    import shutil
    import sys

    launcher = shutil.which("yade")
    if launcher is None:
        sys.exit("collision.py: yade is not installed")
    loader = importlib.machinery.SourceFileLoader("yadeimport", launcher)
    spec = importlib.util.spec_from_loader("yadeimport", loader)
    yadeimport = importlib.util.module_from_spec(spec)
    sys.modules["yadeimport"], sys.argv = yadeimport, [sys.argv[0], "-n"]  # -n: no window
    loader.exec_module(yadeimport)
    from yadeimport import *

from yade import *  # the engines, functors and O, as in Yade's own scripts
from yade.utils import box, sphere

p = INPUTS
a, x0, v0, u0 = p["radius"], p["layer"], p["normal_speed"], p["tangential_speed"]
wall_material = O.materials.append(FrictMat(young=p["wall_young"], poisson=p["wall_poisson"],
                                            density=1000.0, frictionAngle=p["friction_angle"]))
sphere_material = O.materials.append(FrictMat(young=p["sphere_young"],
                                              poisson=p["sphere_poisson"], density=1000.0,
                                              frictionAngle=p["friction_angle"]))
O.bodies.append(box(center=(0, 0, -a), extents=(20 * a, 20 * a, a), fixed=True,
                    material=wall_material))
ball = O.bodies[O.bodies.append(sphere(center=(0, 0, a + x0), radius=a,
                                       material=sphere_material))]
ball.state.mass = p["mass"]
ball.state.inertia = Vector3(1, 1, 1) * p["inertia"]
ball.state.vel = Vector3(u0, 0, -v0)
ball.state.angVel = Vector3(0, p["spin"], 0)  # rolling sense for a motion along +x
detection = 1.0 + 1.01 * x0 / a  # the interaction starts at the gap x0 ...
O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb(aabbEnlargeFactor=detection), Bo1_Box_Aabb()]),
    InteractionLoop(
        [Ig2_Box_Sphere_ScGeom(interactionDetectionFactor=detection)],
        [Ip2_FrictMat_FrictMat_LubricationPhys(eta=p["eta"], eps=p["eps"], keps=p["keps"])],
        [Law2_ScGeom_ImplicitLubricationPhys(MaxDist=x0 / a)],  # ... and ends at x0
    ),
    NewtonIntegrator(damping=0.0, gravity=(0, 0, 0)),
]
O.dt = p["time_step"]
rows = [(0.0, x0, -v0, u0, p["spin"], 0.0)]
STUCK = 1e-2  # stuck: the normal speed below 1e-2 V0 for x0 / V0 (not a reversal's instant)
slow_since = 0.0
while O.time < p["time_limit"]:
    for _ in range(20):
        O.step()
    gap, velocity = ball.state.pos[2] - a, ball.state.vel
    rows.append((O.time, gap, velocity[2], velocity[0], ball.state.angVel[1],
                 O.forces.f(ball.id)[2]))
    if gap > x0 and velocity[2] > 0:
        break
    slow_since = slow_since if abs(velocity[2]) < STUCK * v0 else O.time
    if O.time - slow_since > x0 / v0:  # slow for the time of crossing the layer: stuck
        break
with open("history.csv", "w") as out:
    out.write("time_s,gap_m,normal_velocity_m_s,tangential_velocity_m_s,spin_rad_s,"
              "normal_force_N\\n")
    out.writelines(",".join(repr(float(x)) for x in row) + "\\n" for row in rows)
time, gap, vn, vt, spin, _ = rows[-1]
rebounded = gap > x0 and vn > 0
oblique = u0 > 0
rebound = {
    "e_n": vn / v0 if rebounded else 0.0,
    "e_t": vt / u0 if oblique else None,
    "spin_change": a * (spin - p["spin"]) / u0 if oblique else None,
    "rebounded": rebounded,
    "time_in_layer": time,
    "thinnest_gap": min(row[1] for row in rows),
}
with open("rebound.json", "w") as out:
    json.dump(rebound, out, indent=2)
"""


def script(inputs: dict) -> str:
    """The Yade script of ``inputs`` (:func:`script_inputs`): its inputs as JSON, then the
    scene."""
    inputs = json.dumps(inputs, indent=2)
    head = (
        '"""A sphere on a wall through a liquid layer with Yade\'s implicit lubrication law, '
        "written by ehdfem\n(ehdfem.dem.engines.yade). Rerun: python3 collision.py (Yade as a "
        "library, no TCP port;\nyade -n -x collision.py also runs it, with Yade's console and "
        'information servers); change the inputs below (SI)."""\n\nimport json\n\n'
    )
    return f"{head}INPUTS = json.loads('''{inputs}''')\n{BODY}"


def launcher_python() -> str:
    """The Python of Yade's launcher (``yade`` on the PATH): the program its first line names,
    the one Yade's library is built for; an :class:`EngineError` when Yade is missing."""
    launcher = shutil.which("yade")
    if launcher is None:
        raise EngineError("yade is not installed (bash make.sh setup installs it with apt)")
    with open(launcher, "rb") as text:
        first = text.readline().decode(errors="replace").strip()
    return first[2:].split()[0] if first.startswith("#!") else "python3"


def run(collision: PhysicalCollision, law: YadeLaw, folder: Path) -> EngineRebound:
    """Write collision.py into ``folder`` (made if missing), run it there by Yade's Python with
    Yade as a library (no TCP port opened), read the rebound."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "rebound.json").unlink(missing_ok=True)
    (folder / SCRIPT).write_text(script(script_inputs(collision, law)))
    run_binary([launcher_python(), SCRIPT], folder, LOG)
    return read_rebound("yade", folder, SCRIPT, LOG)
