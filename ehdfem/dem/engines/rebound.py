"""What a DEM engine's run gives back, read from the files it wrote, and how the engine's binary
is run in a folder the user keeps (its input script, log, history and rebound stay there and
the run can be repeated by hand).

All velocities are those of the relative motion: e_n = V_exit / V0, the normal relative speed
when the gap reopens to the layer thickness x0 over the approach speed V0 (0: the spheres stay
within the layer until the run ends, i.e. they stick); e_t = U_exit / U0 and the spin change
a (Omega - Omega0) / U0 as in :mod:`ehdfem.outputs.registry` (None for a head-on impact or an
engine without tangential motion). Times are in seconds (SI).
"""

from __future__ import annotations

import json
import shutil
import subprocess
from dataclasses import asdict, dataclass
from pathlib import Path


class EngineError(OSError):
    """The engine's binary is missing, failed, or wrote no rebound: the message names the
    binary, the folder and its log."""


@dataclass(frozen=True)
class EngineRebound:
    """One engine run: its name, e_n, e_t and spin change (see the module docstring), whether
    the gap reopened to x0 (``rebounded``), the time spent within the layer [s], the thinnest
    gap between the surfaces [m] (negative: an overlap of the contact springs), the folder and
    its input script's file name."""

    engine: str
    e_n: float
    e_t: float | None
    spin_change: float | None
    rebounded: bool
    time_in_layer: float
    thinnest_gap: float
    folder: str
    script: str

    def summary(self) -> dict:
        """The rebound as a plain dict (JSON)."""
        return asdict(self)


def run_binary(command: list[str], folder: Path, log: str) -> None:
    """Run ``command`` in ``folder`` with its standard output and error in ``folder/log``;
    an :class:`EngineError` when the binary is missing or exits with an error."""
    if shutil.which(command[0]) is None:
        raise EngineError(
            f"{command[0]} is not installed (bash make.sh setup installs it with apt)"
        )
    with open(folder / log, "w") as out:
        status = subprocess.run(command, cwd=folder, stdout=out, stderr=subprocess.STDOUT)
    if status.returncode != 0:
        raise EngineError(
            f"{' '.join(command)} failed in {folder} (exit status {status.returncode}); "
            f"see {folder / log}"
        )


def read_rebound(engine: str, folder: Path, script: str, log: str) -> EngineRebound:
    """The :class:`EngineRebound` from ``folder/rebound.json``, which the engine's script (Yade)
    or ehdfem from the engine's history (LIGGGHTS) wrote."""
    path = folder / "rebound.json"
    if not path.is_file():
        raise EngineError(f"{engine} wrote no {path}; see {folder / log}")
    values = json.loads(path.read_text())
    return EngineRebound(engine=engine, folder=str(folder), script=script, **values)
