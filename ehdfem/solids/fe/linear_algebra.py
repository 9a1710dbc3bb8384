"""Linear interpolation between film nodes as a sparse matrix: the film's nodal values on the FE
solids' faces (the PETSc side of the solids' linear algebra is :mod:`ehdfem.fenicsx.matrices`).

Nothing here knows about scales: results carry the units of the values given.
"""

from __future__ import annotations

import numpy as np


def interpolation_matrix(nodes, points):
    """The sparse (len(points), len(nodes)) matrix of linear interpolation from values at the
    increasing ``nodes`` to ``points`` (the same length unit): constant before the first node,
    zero beyond the last (as ``np.interp(points, nodes, values, right=0.0)``). Its columns are
    the hat functions of the nodes at the points."""
    import scipy.sparse

    nodes, points = np.asarray(nodes, dtype=float), np.asarray(points, dtype=float)
    right = np.clip(np.searchsorted(nodes, points, side="right"), 1, len(nodes) - 1)
    weight = np.clip((points - nodes[right - 1]) / (nodes[right] - nodes[right - 1]), 0.0, 1.0)
    inside = points <= nodes[-1]
    rows = np.flatnonzero(inside)
    return scipy.sparse.csr_matrix(
        (
            np.concatenate([1 - weight[inside], weight[inside]]),
            (np.concatenate([rows, rows]), np.concatenate([right[inside] - 1, right[inside]])),
        ),
        shape=(len(points), len(nodes)),
    )
