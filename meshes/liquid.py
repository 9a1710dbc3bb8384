"""gmsh generator for the liquid around a sphere moving normal to a plane wall: an axisymmetric
(r, z) half-disc of radius ``outer`` with the wall at z = 0 (or, without a wall, a full
half-disc centred on the sphere), the sphere of unit radius removed, its lowest point at
z = gap.

Lengths are by the sphere radius a. Elements are ``fine`` on the sphere and on the wall near the
axis and grow by ``growth`` (GROWTH) per unit distance up to outer/8; in the gap (r < a) there
are at least GAP_ELEMENTS across the local gap gap + r^2/2, so the lubrication flow there is
resolved at any gap.

Physical groups: surface LIQUID; curves AXIS (r = 0), WALL (z = 0), SPHERE, OUTER.
"""

from __future__ import annotations

import math

LIQUID, AXIS, WALL, SPHERE, OUTER = 1, 2, 3, 4, 5
GROWTH = 0.15  # element size added per unit distance from the sphere or the wall
GAP_ELEMENTS = 4  # at least this many elements across the local gap gap + r^2/2 (r < a)


def build(
    gap: float | None, outer: float = 40.0, fine: float = 5e-3, growth: float = GROWTH
) -> None:
    """The liquid's geometry and 2-D mesh in the current gmsh model (module docstring); ``gap``
    None: no wall, the sphere centred in the half-disc; ``growth``: the size added per unit
    distance (GROWTH unless a wake must be resolved)."""
    import gmsh

    occ, field = gmsh.model.occ, gmsh.model.mesh.field
    wall = gap is not None
    centre, bottom = (1.0 + gap, 0.0) if wall else (0.0, -outer)
    disc = occ.addDisk(0, 0, 0, outer, outer)
    box = occ.addRectangle(0, bottom, 0, outer, outer - bottom)
    liquid, _ = occ.intersect([(2, disc)], [(2, box)])
    liquid, _ = occ.cut(liquid, [(2, occ.addDisk(0, centre, 0, 1.0, 1.0))])
    occ.synchronize()
    curves = {AXIS: [], WALL: [], SPHERE: [], OUTER: []}
    for _, tag in gmsh.model.getEntities(1):
        x, z, _ = occ.getCenterOfMass(1, tag)
        if abs(x) < 1e-9:
            curves[AXIS].append(tag)
        elif wall and abs(z) < 1e-9:
            curves[WALL].append(tag)
        elif math.hypot(x, z - centre) < 1.0:  # an arc of the sphere: its centroid is inside
            curves[SPHERE].append(tag)
        else:
            curves[OUTER].append(tag)
    gmsh.model.addPhysicalGroup(2, [tag for _, tag in liquid], LIQUID)
    for group, tags in curves.items():
        if tags:
            gmsh.model.addPhysicalGroup(1, tags, group)
    largest = outer / 8

    def growing(faces, extra=""):
        distance = field.add("Distance")
        field.setNumbers(distance, "CurvesList", faces)
        field.setNumber(distance, "NumPointsPerCurve", 400)
        size = field.add("MathEval")
        field.setString(size, "F", f"Min({fine} + {growth}*(F{distance}{extra}), {largest})")
        return size

    sizes = [growing(curves[SPHERE])]
    if wall:
        sizes.append(growing(curves[WALL], " + 0.5*x"))
        in_gap = field.add("MathEval")  # only below the sphere's centre and inside r < a
        field.setString(
            in_gap,
            "F",
            f"Max({fine}/4, ({gap} + x*x/2)/{GAP_ELEMENTS})"
            f" + 1e3*Step(x - 1) + 1e3*Step(y - {gap} - 0.5)",
        )
        sizes.append(in_gap)
    smallest = field.add("Min")
    field.setNumbers(smallest, "FieldsList", sizes)
    field.setAsBackgroundMesh(smallest)
    for option in ("ExtendFromBoundary", "FromPoints", "FromCurvature"):
        gmsh.option.setNumber(f"Mesh.MeshSize{option}", 0)
    gmsh.model.mesh.generate(2)
