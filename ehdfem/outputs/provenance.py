"""Where a result comes from: the code, the libraries, the machine's MPI size, the date and the
command line, recorded in a collision's JSON (``"provenance"``), in the histories file and
beside a study's table.

The record (:func:`record`) holds the ehdfem version, the git commit of the source tree and
whether it had uncommitted changes (only when the package is imported from a git checkout;
None otherwise, and never an error without git), the UTC date and time (ISO 8601), the Python
version, the versions of the numerical libraries this process has loaded (numpy, scipy, and
dolfinx, petsc4py, mpi4py and gmsh only where the run imported them: a half-space run lists no
FE library, so the record says which libraries computed the result, and nothing is imported
just to be named), the command line and the MPI size (1 when mpi4py is not loaded).
"""

from __future__ import annotations

import functools
import platform
import subprocess
import sys
from datetime import UTC, datetime
from pathlib import Path

from ..version import __version__

LIBRARIES = ("numpy", "scipy", "dolfinx", "petsc4py", "mpi4py", "gmsh")
SOURCE = Path(__file__).resolve().parents[2]  # the folder holding the ehdfem package
GIT_TIMEOUT = 10.0  # seconds


def record(command: list[str] | None = None) -> dict:
    """The provenance of a result computed now by this process: ehdfem_version, git
    ({"commit", "dirty"} or None), date (UTC, ISO 8601), python, libraries ({name: version}
    of those loaded), command (``command``, default sys.argv) and mpi_size."""
    return {
        "ehdfem_version": __version__,
        "git": git_state(),
        "date": datetime.now(UTC).isoformat(timespec="seconds"),
        "python": platform.python_version(),
        "libraries": library_versions(),
        "command": list(sys.argv if command is None else command),
        "mpi_size": mpi_size(),
    }


@functools.cache
def git_state() -> dict | None:
    """{"commit": the HEAD commit, "dirty": uncommitted changes to tracked files} of the git
    checkout the package was imported from, or None (no git, or not a checkout). Read once per
    process: the code that runs is the code imported at its start."""
    try:
        top = _git("rev-parse", "--show-toplevel")
        if Path(top).resolve() != SOURCE:  # e.g. installed into another project's tree
            return None
        commit = _git("rev-parse", "HEAD")
        dirty = bool(_git("status", "--porcelain", "--untracked-files=no"))
    except (OSError, subprocess.SubprocessError):
        return None
    return {"commit": commit, "dirty": dirty}


def _git(*args: str) -> str:
    """The output of ``git args`` run in the source folder (raises when git fails)."""
    done = subprocess.run(
        ["git", *args],
        cwd=SOURCE,
        capture_output=True,
        text=True,
        timeout=GIT_TIMEOUT,
        check=True,
    )
    return done.stdout.strip()


def library_versions() -> dict:
    """{name: version} of the libraries of LIBRARIES that this process has loaded."""
    out = {}
    for name in LIBRARIES:
        module = sys.modules.get(name)
        if module is not None:
            out[name] = str(getattr(module, "__version__", "unknown"))
    return out


def mpi_size() -> int:
    """The size of MPI's world communicator, 1 when mpi4py's MPI is not loaded."""
    mpi = sys.modules.get("mpi4py.MPI")
    return 1 if mpi is None else mpi.COMM_WORLD.size


def commit_text() -> str:
    """The git commit as one word for a table column: the commit, with "+dirty" when the
    checkout had uncommitted changes; "" outside a git checkout."""
    state = git_state()
    if state is None:
        return ""
    return state["commit"] + ("+dirty" if state["dirty"] else "")
