"""The half-space collision at the defaults, timed against the code of an earlier commit.

Each case (a head-on collision at the default numerics, 240 film nodes, half-space solids) is
run in a fresh Python process on the current checkout and on a git worktree of COMMIT, in
alternation, REPEATS times each; the fastest run of each counts (runs of about a second vary
by 15 % on a busy machine, and the minimum is the least disturbed). One BLAS thread, as in every
collision, on the machine's BLAS (both sides the same library; but the Newton matrices' LU,
which the code runs on the OpenBLAS the package installs, ehdfem.lapack, since that module
came: a commit before it factorises with the machine's LAPACK). Then, where Linux's ``perf`` is
installed, the current code's collisions are sampled by ``perf record`` and the share of the
samples inside the BLAS and LAPACK libraries (OpenBLAS or the reference ones) is reported per
case: the part of a collision's time that is arithmetic in the dense kernels, against Python and
numpy's small operations. Writes benchmarks/results/against_commit.json (seconds, implicit
steps, Newton iterations, e_n, the thinnest film and the contact time of both, the ratio of the
times, the BLAS share) and prints a line per case.

Run: .venv/bin/python benchmarks/against_commit.py COMMIT [REPEATS]
[--oblique | --table | --angles | --bounce]
(the default cases about 2 minutes at 5 repeats; the table about 10 at 2)
With --angles it times the later points of an angle sweep of the sliding film in one process
(ANGLE_CASES: the same St and eps at 30 and 50 degrees after 10, whose film grid, and so the
half-space's kept matrices, they share), writing benchmarks/results/against_commit_angles.json;
with --bounce the README's bounce (BOUNCE_CASES, its time after a first run in the same
process; "steps" is its number of contacts), writing against_commit_bounce.json.
With --oblique it times the oblique cases of OBLIQUE_CASES instead (the tangential models: Couette,
the sliding film with its mode-1 build, and with the full mode-1 deformation), writing
benchmarks/results/against_commit_oblique.json (commits since the run settings became keywords
of ``collide``). With --table it times TABLE_CASES, the corners and the middle of the closed
forms' DEM fit table (studies/dem_closed_forms.toml: St 10, 1e3, 1e4 x eps 1e-12, 1e-6, 1e-3 x
P_cav -10 and none x both layers, delta 1e-3, 30 degrees, Couette), whose summed time stands for
the table's, and writes benchmarks/results/against_commit_table.json (no BLAS share: the
default cases give it).

The commit's code is imported as it stood (its own ``ehdfem`` package), so the cases use only
the API every version has had: ``collide(CollisionParameters(St=..., eps=..., layer=...,
p_cav=...))``, through ``CollisionParameters.from_settings`` where the commit has it (since
the cavitation model and the viscosity law became components, the flat keys go there).
"""

import json
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

from worktree import commit_checkout, head, run_json

ROOT = Path(__file__).resolve().parent.parent
RESULTS = ROOT / "benchmarks" / "results"
CASES = {  # name: CollisionParameters keywords (scaled inputs, DSH 1986)
    "immersed St=10 eps=6.75e-3 no cavitation": dict(
        St=10.0, eps=6.75e-3, layer="immersed", cavitation="none"
    ),
    "thin St=20 eps=1e-3": dict(St=20.0, eps=1e-3, layer="thin"),
    "thin St=10 eps=1e-3 P_cav=-2": dict(St=10.0, eps=1e-3, layer="thin", p_cav=-2.0),
    "immersed St=50 eps=1e-4": dict(St=50.0, eps=1e-4, layer="immersed"),
    "thin St=1000 eps=1e-6": dict(St=1000.0, eps=1e-6, layer="thin"),
    "immersed St=20 eps=1e-3 P_cav=-2": dict(St=20.0, eps=1e-3, layer="immersed", p_cav=-2.0),
}
OBLIQUE_CASES = {  # name: (CollisionParameters keywords, run settings): the tangential models
    "thin St=20 eps=1e-3 30 deg Couette": (
        dict(St=20.0, eps=1e-3, layer="thin", angle=30.0),
        dict(tangential="couette"),
    ),
    "thin St=20 eps=1e-3 30 deg sliding film": (
        dict(St=20.0, eps=1e-3, layer="thin", angle=30.0),
        dict(tangential="lubrication"),
    ),
    "immersed St=20 eps=1e-3 30 deg sliding film, full": (
        dict(St=20.0, eps=1e-3, layer="immersed", angle=30.0),
        dict(tangential="lubrication", deformation="full"),
    ),
}
TABLE_CASES = {  # name: (CollisionParameters keywords, run settings): the DEM fit table's box
    f"{layer} St={St:g} eps={eps:g} P_cav={p_cav}": (
        dict(St=St, eps=eps, layer=layer, angle=30.0, delta=1e-3)
        | ({} if p_cav == "none" else {"p_cav": p_cav}),
        dict(tangential="couette"),
    )
    for St in (10.0, 1e3, 1e4)
    for eps in (1e-12, 1e-6, 1e-3)
    for p_cav in (-10.0, "none")
    for layer in ("thin", "immersed")
}
SETUP = """
import json, sys, time
from ehdfem import CollisionParameters, collide
build = getattr(CollisionParameters, "from_settings", CollisionParameters)
params, settings = build(**json.loads(sys.argv[1])), json.loads(sys.argv[2])
"""
TIMER = (
    SETUP
    + """
collide(params, **settings)  # the first run pays for imports and caches
import ehdfem.solids.halfspace as halfspace
getattr(halfspace, "_kernels", {}).clear()  # but each timed collision builds its compliance
start = time.perf_counter()
result = collide(params, **settings)
seconds, normal = time.perf_counter() - start, result.normal
print(json.dumps({"seconds": seconds, "steps": normal.steps,
                  "newton_iterations": getattr(normal, "newton_iterations", None),
                  "e_n": normal.e_n, "min_film_thickness": normal.min_film_thickness,
                  "contact_time": normal.contact_time,
                  "e_t": result.tangential.e_t if result.tangential else None}))
"""
)
SAMPLED = (
    SETUP
    + """
import ehdfem.solids.halfspace as halfspace
for _ in range(int(sys.argv[3])):
    getattr(halfspace, "_kernels", {}).clear()  # each collision builds its compliance
    collide(params, **settings)
"""
)
ANGLE_TIMER = (
    SETUP
    + """
collide(params, **settings)  # the first point of an angle sweep: imports, caches, kernels
seconds = []
for angle in (30.0, 50.0):  # later points at the same St and eps: the same film grid
    start = time.perf_counter()
    result = collide(build(**{**json.loads(sys.argv[1]), "angle": angle}), **settings)
    seconds.append(time.perf_counter() - start)
print(json.dumps({"seconds": sum(seconds) / len(seconds), "steps": result.normal.steps,
                  "e_n": result.normal.e_n, "e_t": result.tangential.e_t}))
"""
)
BOUNCE_TIMER = """
import json, sys, time
from ehdfem.bounce.inputs import BounceInputs
from ehdfem.bounce.trajectory import bounce_sphere
inputs = BounceInputs(**json.loads(sys.argv[1]))
bounce_sphere(inputs)  # the first run pays for imports and caches
start = time.perf_counter()
result = bounce_sphere(inputs)
print(json.dumps({"seconds": time.perf_counter() - start, "steps": len(result.contacts),
                  "e": [contact.e for contact in result.contacts]}))
"""
ANGLE_CASES = {  # name: (CollisionParameters keywords at the first angle, run settings)
    "thin St=20 eps=1e-3 sliding film, angles 30 and 50 after 10": (
        dict(St=20.0, eps=1e-3, layer="thin", angle=10.0),
        dict(tangential="lubrication"),
    ),
}
BOUNCE_CASES = {  # name: (BounceInputs keywords,): the README's bounce
    "README bounce (steel on glass, 10 cSt, 1.5 mm, from 2 cm)": (
        dict(
            sphere="steel",
            wall="glass",
            liquid="silicone_oil_10cst",
            radius=1.5e-3,
            release_height=0.02,
            e_dry=0.97,
        ),
    ),
}
TIMERS = {"angles": ANGLE_TIMER, "bounce": BOUNCE_TIMER}  # the others: TIMER
LINEAR_ALGEBRA = ("blas", "lapack")  # the shared objects that count as dense kernels


def run(source: Path, case: tuple, timer: str = TIMER) -> dict:
    """One timed collision (``case``: inputs and run settings) with the ``ehdfem`` package of
    ``source``, in its own process (``timer``: the script that times it)."""
    return run_json(source, [sys.executable, "-c", timer, *map(json.dumps, case)])


def _samples_by_library(case: tuple, runs: int, tmp: str) -> dict[str, int]:
    """``perf record``'s samples of one process that imports ehdfem and runs ``runs``
    collisions of the current code, by shared object."""
    env = {**os.environ, "OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1"}
    data = str(Path(tmp) / f"perf{runs}.data")
    subprocess.run(
        ["perf", "record", "-q", "-F", "2000", "-o", data, "--"]
        + [sys.executable, "-c", SAMPLED, *map(json.dumps, case), str(runs)],
        env=env,
        cwd=ROOT,
        capture_output=True,
        check=True,
    )
    report = subprocess.run(
        ["perf", "report", "-i", data, "--sort", "dso", "--stdio", "-q", "-n"],
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    rows = [line.split() for line in report.splitlines() if "%" in line]
    return {row[2] if len(row) > 2 else "?": int(row[1]) for row in rows}


def blas_share(case: tuple, runs: int = 10) -> float | None:
    """The share of the collisions' ``perf record`` samples that fall in a BLAS or LAPACK
    library (None without perf): the samples of a process that runs 1 + ``runs`` collisions
    less those of one that runs 1, so that the import, numba's cache load and the first
    collision's kernel builds are not counted."""
    if shutil.which("perf") is None:
        return None
    with tempfile.TemporaryDirectory() as tmp:
        base = _samples_by_library(case, 1, tmp)
        full = _samples_by_library(case, 1 + runs, tmp)
    extra = {name: full[name] - base.get(name, 0) for name in full}
    total = sum(extra.values())
    dense = sum(n for name, n in extra.items() if any(k in name.lower() for k in LINEAR_ALGEBRA))
    return dense / total if total > 0 else None


def blas_libraries() -> list[str]:
    """The BLAS and LAPACK libraries numpy, scipy and the current code load on this machine."""
    import numpy  # noqa: F401
    import scipy.linalg  # noqa: F401

    import ehdfem.lapack  # noqa: F401

    loaded = {Path(line.split()[-1]) for line in Path("/proc/self/maps").read_text().splitlines()}
    return sorted(
        str(path)
        for path in loaded
        if path.name.startswith("lib") and any(name in path.name for name in LINEAR_ALGEBRA)
    )


def main(commit: str, repeats: int = 5, kind: str = "default"):
    rows = {}
    cases = {
        "default": {name: (case, {}) for name, case in CASES.items()},
        "oblique": OBLIQUE_CASES,
        "table": TABLE_CASES,
        "angles": ANGLE_CASES,
        "bounce": BOUNCE_CASES,
    }[kind]
    timer = TIMERS.get(kind, TIMER)
    with tempfile.TemporaryDirectory() as tmp, commit_checkout(commit, Path(tmp) / "old") as old:
        for name, case in cases.items():
            best = {"current": None, "old": None}
            for _ in range(repeats):
                for label, source in (("current", ROOT), ("old", old)):
                    result = run(source, case, timer)
                    if best[label] is None or result["seconds"] < best[label]["seconds"]:
                        best[label] = result
            ratio = best["current"]["seconds"] / best["old"]["seconds"]
            share = blas_share(case) if kind in ("default", "oblique") else None
            rows[name] = {**best, "time_ratio": ratio, "blas_lapack_share": share}
            print(
                f"{name:42s} current {best['current']['seconds']:.3f} s "
                f"({best['current']['steps']} steps), {commit[:10]} "
                f"{best['old']['seconds']:.3f} s ({best['old']['steps']} steps): "
                f"ratio {ratio:.3f}, BLAS/LAPACK share "
                + ("n/a" if share is None else f"{100 * share:.0f} %"),
                flush=True,
            )
    current = head()
    RESULTS.mkdir(exist_ok=True)
    out = RESULTS / ("against_commit.json" if kind == "default" else f"against_commit_{kind}.json")
    blas = blas_libraries()
    summed = {
        label: sum(row[label]["seconds"] for row in rows.values()) for label in ("current", "old")
    }
    print(f"summed: current {summed['current']:.2f} s, {commit[:10]} {summed['old']:.2f} s")
    out.write_text(
        json.dumps(
            {
                "current": current,
                "against": commit,
                "repeats": repeats,
                "blas_libraries": blas,
                "summed_seconds": summed,
                "cases": rows,
            },
            indent=2,
        )
        + "\n"
    )
    print(f"wrote {out}")


if __name__ == "__main__":
    options = ("--oblique", "--table", "--angles", "--bounce")
    kinds = [a[2:] for a in sys.argv[1:] if a in options]
    arguments = [a for a in sys.argv[1:] if not a.startswith("--")]
    if not arguments or len(kinds) > 1:
        sys.exit(f"usage: against_commit.py COMMIT [REPEATS] [{' | '.join(options)}]")
    main(arguments[0], int(arguments[1]) if len(arguments) > 1 else 5, *kinds)
