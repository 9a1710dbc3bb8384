"""The code of an earlier commit beside the current checkout, for the benchmarks that time the
two side by side (against_commit.py, fem_build_against_commit.py)."""

import contextlib
import json
import os
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


@contextlib.contextmanager
def commit_checkout(commit: str, folder: Path):
    """A git worktree of ``commit`` at ``folder`` (its own ``ehdfem`` package), removed on
    exit; yields the folder."""
    subprocess.run(
        ["git", "worktree", "add", "--detach", str(folder), commit],
        cwd=ROOT,
        check=True,
        capture_output=True,
    )
    try:
        yield folder
    finally:
        subprocess.run(["git", "worktree", "remove", "--force", str(folder)], cwd=ROOT)


def head() -> str:
    """The current checkout's commit."""
    return subprocess.run(
        ["git", "rev-parse", "HEAD"], cwd=ROOT, capture_output=True, text=True
    ).stdout.strip()


def run_json(source: Path, command: list, **env) -> dict:
    """Run ``command`` on the ``ehdfem`` package of ``source`` (the current checkout or a
    worktree) with the BLAS on one thread, as in every collision, and ``env`` added to the
    environment; returns the JSON of its last line of output."""
    environment = {**os.environ, "PYTHONPATH": str(source), **env}
    environment.update(OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
    out = subprocess.run(
        command, env=environment, cwd=source, capture_output=True, text=True, check=True
    )
    return json.loads(out.stdout.strip().splitlines()[-1])
