"""The two install stacks side by side: Debian 12's (DOLFINx 0.5.2, PETSc 3.18, gmsh 4.8,
numpy 1.24) and the wheels' (DOLFINx 0.11, PETSc 3.25, gmsh 4.15, numpy 2).

Run it once on each stack, then compare (docs/fem.md, "Two install stacks"):

    .venv/bin/python benchmarks/stacks.py --out OUT/debian --mesh-cache OUT/meshes
    .venv-wheel/bin/python benchmarks/stacks.py --out OUT/wheel
    .venv-wheel/bin/python benchmarks/stacks.py --out OUT/wheel-same-mesh \
        --mesh OUT/meshes/KEY.msh
    python benchmarks/stacks.py --compare OUT/debian OUT/wheel OUT/wheel-same-mesh

A run (one process, compliance cache off) builds the example's FE solids (steel on glass,
delta = 0.047, 240 film nodes), condenses their axisymmetric and mode-1 compliances, opens
the solids under a Hertz-like film pressure (the field values: the pole's displacement, the
largest von Mises stress and hydrostatic pressure) and runs the FE collision of `ehdfem
collide --example --model fem` on those compliances, timing each part; it writes the matrices
(NPZ) and the rest (JSON) to OUT. With ``--mesh``, a gmsh file (the other stack's mesh, from
its ``--mesh-cache``) replaces the meshing, so that only DOLFINx, PETSc and numpy differ. The
comparison prints, per pair, the largest difference of each compliance matrix relative to its
largest entry, and the relative differences of the collision's outputs and the field values;
it writes benchmarks/results/stacks.json.
"""

import argparse
import json
import os
import sys
import time
from pathlib import Path

import numpy as np

MATRICES = ("gap", "shear", "surface_sum", "mode_one")
OUTPUTS = ("e_n", "min_film_thickness", "contact_time", "max_force", "e_t", "spin_change")


def _stack() -> dict:
    """The versions of the libraries this run computes with."""
    import gmsh

    from ehdfem.fenicsx import libraries

    return {
        "dolfinx": libraries.dolfinx_version(),
        "petsc": libraries.petsc_version(),
        "gmsh": gmsh.__version__,
        "numpy": np.__version__,
        "python": sys.version.split()[0],
    }


def _fields(solids, radii, eps) -> dict:
    """Field values of the solids under p = sqrt(1 - (r / r_c)^2), r_c half the film's
    extent: the pole's (the sphere's vertex on the axis at the contact) u_z, and the largest
    von Mises stress and hydrostatic pressure of either body."""
    contact = radii[-1] / 2
    pressure = np.sqrt(np.clip(1 - (radii / contact) ** 2, 0.0, None))
    field = solids.deformation(pressure, eps)
    axis = np.flatnonzero(field.upper & (field.points[:, 0] == 0.0))
    pole = axis[np.argmin(field.points[axis, 1])]
    return {
        "pole_displacement": float(field.displacement[pole, 1]),
        "max_von_mises": float(field.von_mises.max()),
        "max_hydrostatic": float(np.abs(field.hydrostatic).max()),
    }


def run(out: Path, mesh_file: str | None) -> None:
    from mpi4py import MPI

    from ehdfem.collision import DEFAULT_NODES, collide, film_radii
    from ehdfem.fenicsx import domain
    from ehdfem.inputs.presets import EXAMPLE
    from ehdfem.inputs.scales import from_presets
    from ehdfem.solids.fe import mesh as fem_mesh
    from ehdfem.solids.fe.mode_one import FEModeOne
    from ehdfem.solids.fe.solids import FESolids

    if mesh_file is not None:
        fem_mesh.load_or_build = lambda gmsh, build, arguments: gmsh.open(mesh_file)
    physical = from_presets(**EXAMPLE)
    params = physical.dimensionless()
    radii = film_radii(params, DEFAULT_NODES)
    materials = ((m.young_modulus, m.poisson_ratio) for m in (physical.sphere, physical.wall))
    times, start = {}, time.perf_counter()
    sphere, wall = materials
    solids = FESolids(params.delta, radii, sphere=sphere, wall=wall, comm=MPI.COMM_SELF)
    times["mesh_and_assembly"] = time.perf_counter() - start
    start = time.perf_counter()
    compliance = solids.compliance(params.eps, shear=True)
    times["compliance"] = time.perf_counter() - start
    start = time.perf_counter()
    mode_one = FEModeOne(solids, params.eps)
    times["mode_one_compliance"] = time.perf_counter() - start
    fields = _fields(solids, radii, params.eps)
    start = time.perf_counter()
    result = collide(physical, model="fem", compliance=compliance, mode_one=mode_one).summary()
    times["collision"] = time.perf_counter() - start
    out.mkdir(parents=True, exist_ok=True)
    np.savez(
        out / "compliances.npz",
        gap=compliance.unit_matrix,
        shear=compliance.unit_shear,
        surface_sum=compliance.unit_surface_sum,
        mode_one=mode_one.unit_matrix,
    )
    record = {
        "stack": _stack(),
        "mesh": mesh_file or "own",
        "cells": domain.cell_count(solids.mesh),
        "dofs": solids.dofs,
        "outputs": {name: result[name] for name in OUTPUTS},
        "fields": fields,
        "seconds": times,
    }
    (out / "run.json").write_text(json.dumps(record, indent=1))
    print(json.dumps(record, indent=1))


def _relative(a: float, b: float) -> float:
    return abs(a - b) / max(abs(a), abs(b))


def compare(folders: list[Path]) -> dict:
    """Each later run against the first: matrices, outputs and fields (module docstring)."""
    runs = [json.loads((folder / "run.json").read_text()) for folder in folders]
    arrays = [np.load(folder / "compliances.npz") for folder in folders]
    pairs = []
    for folder, record, matrices in zip(folders[1:], runs[1:], arrays[1:], strict=True):
        mesh = "own" if record["mesh"] == "own" else "the reference's"
        pair = {"against": folders[0].name, "run": folder.name, "mesh": mesh}
        pair["matrices"] = {
            name: float(
                np.abs(matrices[name] - arrays[0][name]).max() / np.abs(arrays[0][name]).max()
            )
            for name in MATRICES
        }
        for part in ("outputs", "fields"):
            pair[part] = {
                name: _relative(value, runs[0][part][name]) for name, value in record[part].items()
            }
        pairs.append(pair)
    for record in runs:
        record["mesh"] = Path(record["mesh"]).name
    summary = {"runs": {f.name: r for f, r in zip(folders, runs, strict=True)}, "pairs": pairs}
    print(json.dumps(summary, indent=1))
    return summary


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", type=Path, help="folder of this run's results")
    parser.add_argument("--mesh", help="a gmsh file to use instead of meshing")
    parser.add_argument("--mesh-cache", help="the mesh cache of this run (to keep its mesh)")
    parser.add_argument(
        "--compare", type=Path, nargs="+", help="run folders, the first the reference"
    )
    args = parser.parse_args()
    missing = [str(f) for f in args.compare or [] if not (f / "run.json").is_file()]
    if args.compare and len(args.compare) < 2:
        parser.error("--compare needs two or more run folders, the first the reference")
    if missing:
        parser.error(f"--compare: no run.json (a run's --out) in {', '.join(missing)}")
    if args.mesh and not Path(args.mesh).is_file():
        parser.error(f"--mesh {args.mesh}: no such file")
    if args.compare:
        summary = compare(args.compare)
        target = Path(__file__).parent / "results" / "stacks.json"
        target.write_text(json.dumps(summary, indent=1) + "\n")
        return
    if args.out is None:
        parser.error("--out or --compare is needed")
    os.environ["EHDFEM_COMPLIANCE_CACHE"] = "off"
    if args.mesh_cache:
        os.environ["EHDFEM_MESH_CACHE"] = args.mesh_cache
    run(args.out, args.mesh)


if __name__ == "__main__":
    main()
