"""Hat averages over a film grid: what the FE read-out G_i . u / m_i gives of a surface
displacement (docs/fem.md, "Read-out and reciprocity"), for comparing it with closed forms and
with half-space kernels collocated at the nodes."""

import numpy as np


def hat_average(radii, function):
    """int phi_i f R dR / int phi_i R dR over the film grid ``radii`` (phi_i the hat of node i,
    the last one's inner half only), by 8-point Gauss-Legendre per element: what the FE
    read-out G_i . u / m_i gives of a surface displacement f(R) (exact for polynomials up to
    degree 13 in R); the half-space kernels are collocated at the nodes instead."""
    points, weights = np.polynomial.legendre.leggauss(8)
    left, length = radii[:-1, None], np.diff(radii)[:, None]
    xi = (points + 1) / 2
    r = left + length * xi
    weight = length * weights / 2 * r * function(r)
    mass = length * weights / 2 * r
    out, m = np.zeros(len(radii)), np.zeros(len(radii))
    for values, total in ((weight, out), (mass, m)):
        total[:-1] += (values * (1 - xi)).sum(axis=1)
        total[1:] += (values * xi).sum(axis=1)
    return out / m


def averaged(radii, nodal):
    """The hat averages (as :func:`hat_average`) of the linear interpolant of nodal values:
    the consistent mass int phi_i phi_j R dR over the lumped one int phi_i R dR, applied to
    ``nodal``; for comparing the FE read-outs with kernels collocated at the nodes (exact for
    a displacement linear between nodes, as a mode-1 one near the axis)."""
    left, right = radii[:-1], radii[1:]
    length = right - left
    consistent = np.zeros((len(radii), len(radii)))
    index = np.arange(len(left))
    np.add.at(consistent, (index, index), length * (3 * left + right) / 12)
    np.add.at(consistent, (index + 1, index + 1), length * (left + 3 * right) / 12)
    np.add.at(consistent, (index, index + 1), length * (left + right) / 12)
    np.add.at(consistent, (index + 1, index), length * (left + right) / 12)
    return consistent @ nodal / consistent.sum(axis=1)
