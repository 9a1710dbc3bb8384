"""Cost of the film options: time per collision relative to truncated cavitation at constant
viscosity (half-space model, 240 film nodes, thin layer).

Cases: St = 10, eps = 1e-3, P_cav = -2 (dimensionless), and the main job's physical collision
(steel on glass through 0.3 mm of 100 cSt silicone oil at 1 m/s, 30 degrees), each with cavitation
truncate / mass-conserving and viscosity constant / Barus / Roelands. Each time is the best of
three runs; a run that fails is recorded with its error (the Barus law far outside its
range, the main job's). Writes benchmarks/results/film_options.json.
Run: OPENBLAS_NUM_THREADS=1 .venv/bin/python benchmarks/film_options.py
"""

import json
import time
from pathlib import Path

from ehdfem.collision import collide
from ehdfem.inputs.presets import EXAMPLE
from ehdfem.inputs.scales import CollisionParameters, from_presets
from ehdfem.motion.normal import NormalSolverError

OUT = Path(__file__).resolve().parent / "results" / "film_options.json"
OPTIONS = [
    (cavitation, viscosity)
    for viscosity in ("constant", "barus", "roelands")
    for cavitation in ("truncate", "mass-conserving")
]


def dimensionless(cavitation, viscosity):
    extra = {"constant": {}, "barus": {"alpha": 1e-3}}.get(
        viscosity, {"alpha": 1e-3, "roelands_pressure": 2e3}
    )
    return CollisionParameters.from_settings(
        St=10.0, eps=1e-3, p_cav=-2.0, cavitation=cavitation, viscosity=viscosity, **extra
    )


def physical(cavitation, viscosity):
    return from_presets(**EXAMPLE, cavitation=cavitation, viscosity=viscosity)


def timed(inputs):
    """(best of three seconds, the normal result), or (seconds, the error) of a run that fails."""
    best, result = float("inf"), None
    for _ in range(3):
        start = time.perf_counter()
        try:
            result = collide(inputs).normal
        except NormalSolverError as error:
            return time.perf_counter() - start, error
        best = min(best, time.perf_counter() - start)
    return best, result


def main():
    rows = []
    for case, build in (("St=10, eps=1e-3, P_cav=-2", dimensionless), ("main job", physical)):
        reference = None
        for cavitation, viscosity in OPTIONS:
            seconds, result = timed(build(cavitation, viscosity))
            reference = reference or seconds
            row = {
                "case": case,
                "cavitation": cavitation,
                "viscosity": viscosity,
                "seconds": round(seconds, 3),
                "relative": round(seconds / reference, 2),
            }
            if isinstance(result, NormalSolverError):
                row["failed"] = str(result)
            else:
                row.update(e_n=result.e_n, steps=result.steps, rejected_steps=result.rejected_steps)
            rows.append(row)
            print(json.dumps(row), flush=True)
    OUT.parent.mkdir(parents=True, exist_ok=True)
    OUT.write_text(json.dumps(rows, indent=2) + "\n")
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main()
