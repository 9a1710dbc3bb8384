"""``ehdfem sweep``: a study file (TOML) over the MPI ranks; resumable (docs/studies.md)."""

from __future__ import annotations

from .. import checks
from ..study.sweep import Study, finished_points, run_study
from . import interrupt_says, paths

HELP = "run a study file (TOML) over the MPI ranks; resumable"


def add_sweep(parser) -> None:
    parser.add_argument(
        "study",
        help="study file, e.g. studies/kantak_davis.toml; its table's folder is made if missing",
    )


def sweep_command(args) -> int:
    from mpi4py import MPI

    comm = MPI.COMM_WORLD
    study = Study(paths.input_file("study", args.study))
    try:
        paths.output_folder("study", study.table.parent)
    except checks.InputError as err:
        raise checks.InputError(f"[output] table {str(study.table)!r}: {err}", "study") from err
    if comm.rank == 0:
        print(f"ehdfem sweep {study.name}: {len(study.points)} points on {comm.size} rank(s)")
    with interrupt_says(lambda: saved_points(study)):
        run_study(study, comm, progress=print if comm.rank == 0 else None)
    if comm.rank == 0:
        print(f"wrote {study.table}")
    return 0


def saved_points(study: Study) -> str:
    """What an interrupted sweep saved, and how to compute the rest."""
    keys = {study.key(point) for point in study.points}
    saved = finished_points(study.point_dir, keys)
    return (
        f"stopped by Ctrl-C; {saved} of {len(keys)} points are saved in {study.point_dir}; "
        f"run the same command again to compute the other {len(keys) - saved}"
    )
