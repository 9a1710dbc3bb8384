"""Quiet runs: hide the chatter of the libraries underneath unless asked for it.

Two sources write lines a user of ehdfem has no use for:

- the form compiler: when DOLFINx compiles a form the first time (an empty JIT cache), cffi
  builds a C extension through setuptools, whose log ("running build_ext", the gcc command
  lines) goes to Python's root logger at level INFO;
- VTK: off-screen rendering without an X display logs "bad X server connection" as a warning
  on standard error (VTK's own logger, not Python's).

:func:`set_quiet` drops records below WARNING on the root logger (warnings and errors still
show) and lowers VTK's standard-error logging to errors; :func:`quiet_vtk` is called by
:mod:`ehdfem.outputs.render` right after it imports VTK. The ``ehdfem`` command is quiet unless
``--verbose``; the Python API leaves logging as it finds it until ``set_quiet()`` is called.
"""

from __future__ import annotations

import logging
import sys


class _BelowWarning(logging.Filter):
    """Let only warnings and errors through."""

    def filter(self, record: logging.LogRecord) -> bool:
        return record.levelno >= logging.WARNING


_FILTER = _BelowWarning()
_state = {"quiet": False, "vtk_cutoff": None}


def set_quiet(quiet: bool = True) -> None:
    """Hide (``quiet``) or show again the form compiler's build log and VTK's warnings."""
    root = logging.getLogger()
    if quiet:
        root.addFilter(_FILTER)
    else:
        root.removeFilter(_FILTER)
    _state["quiet"] = bool(quiet)
    if "vtkmodules.vtkCommonCore" in sys.modules:
        quiet_vtk()


def is_quiet() -> bool:
    """Whether :func:`set_quiet` is in force."""
    return _state["quiet"]


def quiet_vtk() -> None:
    """Apply the quiet setting to VTK's logger (errors only on standard error, or VTK's own
    level back); call after VTK is imported."""
    from vtkmodules.vtkCommonCore import vtkLogger

    if _state["quiet"]:
        if _state["vtk_cutoff"] is None:
            _state["vtk_cutoff"] = vtkLogger.GetCurrentVerbosityCutoff()
        vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_ERROR)
    elif _state["vtk_cutoff"] is not None:
        vtkLogger.SetStderrVerbosity(vtkLogger.ConvertToVerbosity(_state["vtk_cutoff"]))
        _state["vtk_cutoff"] = None
