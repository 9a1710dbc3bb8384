"""Progress bars for long work (FE compliance builds, sweeps, critical Stokes numbers).

A bar (tqdm: count, rate and estimated time left) is drawn on standard error by MPI rank 0
only, and only when standard error is a terminal and the environment variable
``EHDFEM_PROGRESS`` is not "0". Anywhere else (a pipe, a log file, CI, ranks > 0) nothing at
all is written and the work runs unchanged. tqdm (Debian's python3-tqdm) is imported only
when a bar is drawn; without it, there is simply no bar.
"""

from __future__ import annotations

import contextlib
import os
import sys

RANK_VARIABLES = ("OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK")


def rank() -> int:
    """This process's MPI rank: mpi4py's if it is loaded already, else the launcher's
    environment (mpirun sets it), else 0. Never initialises MPI itself."""
    mpi = sys.modules.get("mpi4py.MPI")
    if mpi is not None:
        return mpi.COMM_WORLD.rank
    for name in RANK_VARIABLES:
        if os.environ.get(name, "").isdigit():
            return int(os.environ[name])
    return 0


def settle_ranks(patience: float = 10.0) -> None:
    """Under an MPI launcher, wait (at most ``patience`` seconds) until every rank has come
    here, before a failing exit: every rank meets the same refused input, rank 0 prints it,
    and a rank that exits first makes mpirun end the job, which could kill rank 0 before its
    line is out. Without a launcher, nothing."""
    if not any(os.environ.get(name, "").isdigit() for name in RANK_VARIABLES):
        return
    import time

    from mpi4py import MPI

    request, start = MPI.COMM_WORLD.Ibarrier(), time.monotonic()
    while not request.Test() and time.monotonic() - start < patience:
        time.sleep(0.01)


def enabled() -> bool:
    """Whether a bar would be drawn here: rank 0, standard error a terminal, EHDFEM_PROGRESS
    not "0", and tqdm importable."""
    if os.environ.get("EHDFEM_PROGRESS", "1") == "0" or rank() != 0:
        return False
    if not (hasattr(sys.stderr, "isatty") and sys.stderr.isatty()):
        return False
    try:
        import tqdm  # noqa: F401
    except ImportError:
        return False
    return True


def _bar(**options):
    from tqdm import tqdm

    return tqdm(file=sys.stderr, dynamic_ncols=True, leave=False, **options)


def progress(iterable, total=None, desc: str = ""):
    """``iterable`` with a progress bar labelled ``desc`` (``total``: its length when it has
    none) where :func:`enabled`; otherwise ``iterable`` itself, unchanged."""
    if not enabled():
        return iterable
    return _bar(iterable=iterable, total=total, desc=desc)


class Counter:
    """A progress bar moved by hand, for work that is not one loop (a sweep shared by MPI
    ranks, a bisection): ``advance_to(count, total)``, ``paused()`` around lines printed while
    the bar is shown, ``close()``; ``unit``: what is counted. Silent (no output, no tqdm) where
    :func:`enabled` is false."""

    def __init__(self, total=None, desc: str = "", initial: int = 0, unit: str = "it"):
        shown = enabled()
        self._bar = _bar(total=total, desc=desc, initial=initial, unit=unit) if shown else None

    def advance_to(self, count: int, total=None) -> None:
        """Show ``count`` items done (of ``total``, if given: a new upper bound)."""
        if self._bar is None:
            return
        if total is not None:
            self._bar.total = total
        self._bar.update(count - self._bar.n)

    def paused(self):
        """A context in which printing to the terminal does not garble the bar."""
        if self._bar is None:
            return contextlib.nullcontext()
        return self._bar.external_write_mode()

    def close(self) -> None:
        if self._bar is not None:
            self._bar.close()
            self._bar = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
