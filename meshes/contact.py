"""gmsh generators for the FE solids: axisymmetric (r, z) meshes graded at the contact.

Lengths are in units of the (reduced) radius a. The upper sphere's lowest point is at z = gap;
below it, chosen by ``build(lower=...)``, is one of

- "wall": a wall block [0, size] x [-size, 0], clamped at its bottom;
- "coated": the same block with a bonded coating of thickness t on top (own material);
- "sphere": a second, free sphere whose highest point is at z = 0.

The film radii (by a) are vertices of both contact faces, with elements as small as the local
film spacing there (so a pressure linear between film nodes is represented exactly), growing
to ``size``/8 away from the contact.

Physical groups: surfaces SPHERE (upper), LOWER (wall, substrate or lower sphere), COATING;
curves SPHERE_CONTACT, SPHERE_AXIS, LOWER_CONTACT, LOWER_AXIS, LOWER_BOTTOM (clamped wall base),
and OTHER for the remaining free faces.

The mesh is gmsh's Frontal-Delaunay. Where the film spacing is 1e-6 of the far size, it can
leave a sliver whose three vertices lie on a contact face (seen at delta = 1e-3, 120 nodes, a
dry compression of 0.03 x0), which makes the stiffness singular; such a mesh is made again with
gmsh's Delaunay algorithm, and a mesh that is still degenerate is refused (:class:`MeshError`).
"""

from __future__ import annotations

import numpy as np

SPHERE, LOWER, COATING = 1, 2, 3
SPHERE_CONTACT, SPHERE_AXIS, LOWER_CONTACT, LOWER_AXIS, LOWER_BOTTOM, OTHER = 11, 12, 21, 22, 23, 30


FRONTAL_DELAUNAY, DELAUNAY = 6, 5  # gmsh's Mesh.Algorithm numbers
SLIVER = 1e-3  # a triangle's area over its longest side squared below which it is degenerate


class MeshError(RuntimeError):
    """gmsh made a degenerate triangle with both its algorithms."""


def worst_shape(model) -> float:
    """The smallest area / (longest side)^2 of the model's triangles (sqrt(3)/4 equilateral)."""
    tags, coords, _ = model.mesh.getNodes()
    position = np.zeros((int(tags.max()) + 1, 2))
    position[tags.astype(int)] = coords.reshape(-1, 3)[:, :2]
    worst = np.inf
    for kind, _, nodes in zip(*model.mesh.getElements(2), strict=True):
        corners = position[nodes.astype(int)].reshape(
            -1, model.mesh.getElementProperties(kind)[3], 2
        )
        a, b, c = corners[:, 0], corners[:, 1], corners[:, 2]
        ab, ac = b - a, c - a  # the 2-D cross product by hand: numpy 2 takes 3-D vectors only
        area = 0.5 * np.abs(ab[:, 0] * ac[:, 1] - ab[:, 1] * ac[:, 0])
        longest = np.max(
            [np.sum((b - a) ** 2, 1), np.sum((c - b) ** 2, 1), np.sum((a - c) ** 2, 1)], 0
        )
        worst = min(worst, float(np.min(area / longest)))
    return worst


def _local_spacing(r):
    spacing = np.diff(r)
    return np.minimum(
        np.concatenate([[spacing[0]], spacing]), np.concatenate([spacing, [spacing[-1]]])
    )


def _sphere(occ, centre_z, radius, r, local, coarse, facing_down):
    """Half-disc of a sphere; its contact face passes through the film radii. Returns
    (surface, contact curves, axis curve, other curves, contact pole point)."""
    sign = -1.0 if facing_down else 1.0
    centre = occ.addPoint(0, centre_z, 0)
    contact = [
        occ.addPoint(x, centre_z + sign * np.sqrt(radius**2 - x**2), 0, h)
        for x, h in zip(r, local, strict=True)
    ]
    equator = occ.addPoint(radius, centre_z, 0, coarse)
    far_pole = occ.addPoint(0, centre_z - sign * radius, 0, coarse)
    arcs = [
        occ.addCircleArc(a, centre, b)
        for a, b in zip(contact, [*contact[1:], equator], strict=True)
    ]
    far_arc = occ.addCircleArc(equator, centre, far_pole)
    axis = occ.addLine(far_pole, contact[0])
    surface = occ.addPlaneSurface([occ.addCurveLoop([*arcs, far_arc, axis])])
    return surface, arcs, axis, [far_arc], contact[0]


def _groups(model, groups):
    for dim, tags, tag in groups:
        if tags:
            model.addPhysicalGroup(dim, tags, tag)


def _mesh(model, points, r, local, size):
    """Film-spacing elements at the film points (from the points' sizes) and a background
    field growing from the contact to size/8."""
    import gmsh

    distance = model.mesh.field.add("Distance")
    model.mesh.field.setNumbers(distance, "PointsList", points)
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
    for algorithm in (FRONTAL_DELAUNAY, DELAUNAY):
        gmsh.option.setNumber("Mesh.Algorithm", algorithm)
        model.mesh.clear()
        model.mesh.generate(2)
        worst = worst_shape(model)
        if worst >= SLIVER:
            return
    raise MeshError(
        f"gmsh made a degenerate triangle (area / side^2 = {worst:.1e}) with both its algorithms "
        f"for film radii {r[0]:.3g} ... {r[-1]:.3g} (by a); change the film nodes"
    )


def build(
    gap: float,
    contact_radii,
    lower: str = "wall",
    size: float = 40.0,
    upper_radius: float = 1.0,
    lower_radius: float = 1.0,
    coating: float | None = None,
) -> None:
    """Build one of the geometries (``lower`` = "wall", "coated" or "sphere") and its 2-D mesh
    in the current gmsh model; see the module docstring."""
    import gmsh

    occ = gmsh.model.occ
    r = np.asarray(contact_radii, dtype=float)
    local = _local_spacing(r)
    coarse = size / 8
    sphere, sphere_contact, sphere_axis, sphere_other, pole = _sphere(
        occ, gap + upper_radius, upper_radius, r, local, min(coarse, upper_radius / 4), True
    )
    surfaces, other, bottom = {LOWER: [], COATING: []}, list(sphere_other), []
    if lower == "sphere":
        body, contact, axis, rest, lower_pole = _sphere(
            occ, -lower_radius, lower_radius, r, local, min(coarse, lower_radius / 4), False
        )
        surfaces[LOWER], lower_contact, lower_axis = [body], contact, [axis]
        other += rest
    else:
        points = [occ.addPoint(x, 0, 0, h) for x, h in zip(r, local, strict=True)]
        lower_pole = points[0]
        right_top = occ.addPoint(size, 0, 0, coarse)
        lower_contact = [
            occ.addLine(a, b) for a, b in zip(points, [*points[1:], right_top], strict=True)
        ]
        depth = coating if lower == "coated" else None
        left, right = occ.addPoint(0, -size, 0, coarse), occ.addPoint(size, -size, 0, coarse)
        base = occ.addLine(right, left)
        bottom = [base]
        if depth is None:
            side, axis = occ.addLine(right_top, right), occ.addLine(left, points[0])
            loop = [*lower_contact, side, base, axis]
            surfaces[LOWER] = [occ.addPlaneSurface([occ.addCurveLoop(loop)])]
            lower_axis, other = [axis], [*other, side]
        else:
            mid_left = occ.addPoint(0, -depth, 0, min(local.max(), depth / 2))
            mid_right = occ.addPoint(size, -depth, 0, coarse)
            interface = occ.addLine(mid_right, mid_left)
            coat_side, coat_axis = (
                occ.addLine(right_top, mid_right),
                occ.addLine(mid_left, points[0]),
            )
            sub_side, sub_axis = occ.addLine(mid_right, right), occ.addLine(left, mid_left)
            surfaces[COATING] = [
                occ.addPlaneSurface(
                    [occ.addCurveLoop([*lower_contact, coat_side, interface, coat_axis])]
                )
            ]
            surfaces[LOWER] = [
                occ.addPlaneSurface([occ.addCurveLoop([interface, sub_side, base, sub_axis])])
            ]
            lower_axis, other = [coat_axis, sub_axis], [*other, coat_side, sub_side]
    occ.synchronize()
    model = gmsh.model
    _groups(
        model,
        [
            (2, [sphere], SPHERE),
            (2, surfaces[LOWER], LOWER),
            (2, surfaces[COATING], COATING),
            (1, sphere_contact, SPHERE_CONTACT),
            (1, [sphere_axis], SPHERE_AXIS),
            (1, lower_contact, LOWER_CONTACT),
            (1, lower_axis, LOWER_AXIS),
            (1, bottom, LOWER_BOTTOM),
            (1, other, OTHER),
        ],
    )
    _mesh(model, [pole, lower_pole], r, local, size)
