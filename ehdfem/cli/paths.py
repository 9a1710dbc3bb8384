"""The files and folders a command reads and writes, checked before any work starts.

- An output file (``--json``, ``--histories``, ``--fields``, ``--python``, render's ``--out``
  and ``--animation``) goes into a folder that must exist already: a missing folder is refused,
  not created, so that a mistyped path is not silently made. ``-`` (where the option allows it)
  is standard output.
- An output folder (``--plots``, bounce's and dem's ``--folder``, a study's table folder) is
  created with its missing parents when the results are written, unless a file stands where a
  folder must be.
- Either must be writable: a file is created and removed in the folder (or in its nearest
  existing parent) to make sure.
- An input file (``--from``, the study file, fit's table) must exist and be a file.

Each refusal is an :class:`ehdfem.checks.InputError` named after the option's destination, so
that the command line shows the option as typed: ``ehdfem collide: error: --json: ...``.
"""

from __future__ import annotations

import tempfile
from pathlib import Path

from .. import checks


def output_file(name: str, target: str | None, stdout: bool = False, formats=None) -> None:
    """Refuse the output file ``target`` of option ``name`` unless its folder exists and is
    writable, ``target`` is not a folder and, where ``formats`` (suffixes such as ".png") are
    given, its suffix is one of them; None (not asked) and, where ``stdout``, ``-`` pass."""
    if target is None or (stdout and target == "-"):
        return
    path = Path(target)
    if formats is not None and path.suffix.lower() not in formats:
        suffix = f"the format {path.suffix!r}" if path.suffix else "a name without a suffix"
        raise checks.InputError(
            f"{target!r} has {suffix}; the allowed formats are {', '.join(sorted(formats))}", name
        )
    if path.is_dir():
        raise checks.InputError(f"{target!r} is a folder, not a file name", name)
    folder = path.parent
    blocking = _blocking_file(folder)
    if blocking is not None:
        raise checks.InputError(f"{str(blocking)!r} is a file, not a folder", name)
    if not folder.is_dir():
        raise checks.InputError(
            f"the folder {str(folder)!r} of {target!r} does not exist (create it first)", name
        )
    _writable(folder, name)


def distinct_outputs(targets: dict) -> None:
    """Refuse two output options (``targets``: option name to path or None) that name the same
    file or folder: the second would overwrite the first."""
    seen = {}
    for name, target in targets.items():
        if target is None or target == "-":
            continue
        key = Path(target).resolve()
        if key in seen:
            raise checks.InputError(
                f"{target!r} is also the path of --{seen[key].replace('_', '-')}; give each "
                "output its own path",
                name,
            )
        seen[key] = name


def output_folder(name: str, target: str | Path | None) -> None:
    """Refuse the output folder ``target`` of option ``name`` if it is a file, if a file stands
    where one of its parents must be, or if it (or its nearest existing parent, in which it
    will be created) is not writable; None (not asked) passes."""
    if target is None:
        return
    path = Path(target)
    blocking = _blocking_file(path)
    if blocking is not None:
        raise checks.InputError(f"{str(blocking)!r} is a file, not a folder", name)
    existing = next(p for p in (path, *path.parents) if p.is_dir())
    _writable(existing, name)


def input_file(name: str, target: str) -> Path:
    """The input file ``target`` of option ``name``, refused unless it exists and is a file."""
    path = Path(target)
    if path.is_dir():
        raise checks.InputError(f"{target!r} is a folder, not a file", name)
    if not path.is_file():
        raise checks.InputError(f"{target!r} does not exist", name)
    return path


def _blocking_file(path: Path) -> Path | None:
    """``path`` or the first of its parents that exists as something else than a folder."""
    for p in reversed((path, *path.parents)):
        if p.exists() and not p.is_dir():
            return p
        if not p.exists():
            return None
    return None


def _writable(folder: Path, name: str) -> None:
    """Refuse ``folder`` unless a file can be created (and is removed again) in it."""
    try:
        with tempfile.TemporaryFile(dir=folder):
            pass
    except OSError as err:
        raise checks.InputError(f"cannot write in {str(folder)!r}: {err.strerror}", name) from err
