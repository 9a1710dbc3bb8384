"""gmsh generator: an axisymmetric (r, z) sphere above a wall block, graded at the contact.

Lengths are in units of the sphere radius a. The sphere (radius 1) has its lowest point at
z = gap, the wall block is [0, size] x [-size, 0]. The film radii are vertices of both contact
faces, with elements as small as the film spacing there, growing to size/8 far away.

Physical groups: surfaces SPHERE, WALL; curves SPHERE_CONTACT (lower quarter of the sphere),
SPHERE_AXIS, SPHERE_TOP, WALL_CONTACT (top face), WALL_AXIS, WALL_BOTTOM (supported), WALL_SIDE.
"""

from __future__ import annotations

import gmsh
import numpy as np

SPHERE, WALL = 1, 2
SPHERE_CONTACT, SPHERE_AXIS, SPHERE_TOP = 11, 12, 13
WALL_CONTACT, WALL_AXIS, WALL_BOTTOM, WALL_SIDE = 21, 22, 23, 24


def build(gap: float, contact_radii, size: float = 40.0) -> None:
    """Build the geometry and its 2-D triangle mesh in the current gmsh model.

    ``contact_radii`` (by a, increasing, starting at 0): radii that become mesh vertices on both
    contact faces, with the local spacing as element size, so that a pressure that is linear
    between them is represented exactly; beyond the last one elements grow to size/8.
    """
    occ = gmsh.model.occ
    r = np.asarray(contact_radii, dtype=float)
    spacing = np.diff(r)
    local = np.minimum(
        np.concatenate([[spacing[0]], spacing]), np.concatenate([spacing, [spacing[-1]]])
    )
    centre = occ.addPoint(0, gap + 1, 0)
    sphere_points = [
        occ.addPoint(x, gap + 1 - np.sqrt(1 - x**2), 0, h) for x, h in zip(r, local, strict=True)
    ]
    equator, top = occ.addPoint(1, gap + 1, 0, size / 8), occ.addPoint(0, gap + 2, 0, size / 8)
    lower = [
        occ.addCircleArc(a, centre, b)
        for a, b in zip(sphere_points, [*sphere_points[1:], equator], strict=True)
    ]
    upper_arc = occ.addCircleArc(equator, centre, top)
    sphere_axis = occ.addLine(top, sphere_points[0])
    sphere = occ.addPlaneSurface([occ.addCurveLoop([*lower, upper_arc, sphere_axis])])
    wall_points = [occ.addPoint(x, 0, 0, h) for x, h in zip(r, local, strict=True)]
    corners = [
        occ.addPoint(size, 0, 0, size / 8),
        occ.addPoint(size, -size, 0, size / 8),
        occ.addPoint(0, -size, 0, size / 8),
    ]
    wall_top = [
        occ.addLine(a, b) for a, b in zip(wall_points, [*wall_points[1:], corners[0]], strict=True)
    ]
    wall_side = occ.addLine(corners[0], corners[1])
    wall_bottom = occ.addLine(corners[1], corners[2])
    wall_axis = occ.addLine(corners[2], wall_points[0])
    wall = occ.addPlaneSurface([occ.addCurveLoop([*wall_top, wall_side, wall_bottom, wall_axis])])
    occ.synchronize()
    model = gmsh.model
    for dim, tags, tag in [
        (2, [sphere], SPHERE),
        (2, [wall], WALL),
        (1, lower, SPHERE_CONTACT),
        (1, [sphere_axis], SPHERE_AXIS),
        (1, [upper_arc], SPHERE_TOP),
        (1, wall_top, WALL_CONTACT),
        (1, [wall_axis], WALL_AXIS),
        (1, [wall_bottom], WALL_BOTTOM),
        (1, [wall_side], WALL_SIDE),
    ]:
        model.addPhysicalGroup(dim, tags, tag)
    distance = model.mesh.field.add("Distance")
    model.mesh.field.setNumbers(distance, "PointsList", [sphere_points[0], wall_points[0]])
    threshold = model.mesh.field.add("Threshold")
    model.mesh.field.setNumber(threshold, "InField", distance)
    model.mesh.field.setNumber(threshold, "SizeMin", local.max())
    model.mesh.field.setNumber(threshold, "SizeMax", size / 8)
    model.mesh.field.setNumber(threshold, "DistMin", r[-1])
    model.mesh.field.setNumber(threshold, "DistMax", size / 2)
    model.mesh.field.setAsBackgroundMesh(threshold)
    gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 1)
    gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 1)
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
    model.mesh.generate(2)
