#!/usr/bin/env bash
# ehdfem's single entry point: `bash make.sh JOB`. Every job first makes sure the machine is set
# up (Debian's FEniCSx stack by apt, a venv on Debian's python with the rest from PyPI); that
# part is idempotent and takes a second when everything is already there.
#   setup    only the set-up
#   example  the main job: an oblique collision with both models (half-space, FE), results
#            printed, plots, JSON and the FE fields (XDMF) in out/example/
#   test     the test suite: pytest in two processes, then the MPI tests under mpirun -n 2
#   wheel-test  the second install stack, without root or apt: a venv .venv-wheel on Python
#            >= 3.12 with `pip install -e ".[fem,test]"` (DOLFINx 0.11, PETSc, MPICH, numpy 2
#            as wheels), then on it the test files of the FE stack (as `test` does: two
#            processes, then its own mpirun -n 2) and the main job of `example`
#   lint     ruff check and ruff format --check
#   bench    the benchmarks in benchmarks/ (writes benchmarks/results/*.json)
#   study    the shipped study (studies/kantak_davis.toml): sweep, critical St, fits, figures
#   claims   the source's tangential claims along physical sweeps (studies/source_claims.py,
#            2 ranks; its verdicts go into docs/validation.md with `validate`)
#   closed-forms  the closed forms for DEM: the fit and held-back tables on 2 ranks (resumable),
#            then ehdfem fit: JSON, a Python module, a C header and the fitted table
#            (studies/results/dem_closed_forms*; studies/dem_closed_forms.py)
#   validate the validation report docs/validation.md (both models against published results)
#   dem-engines  Yade and LIGGGHTS against the full model (studies/dem_engines.py: its table,
#            figures and the section "DEM engines" of docs/validation.md)
set -euo pipefail
cd "$(dirname "$0")"

APT_PACKAGES=(python3-dolfinx python3-petsc4py python3-mpi4py python3-gmsh gmsh python3-meshio
              python3-scipy python3-matplotlib python3-h5py python3-tqdm python3-venv python3-pip
              openmpi-bin libblas3 liblapack3 libopenblas0-pthread yade liggghts gcc)
VENV=.venv
PY=$VENV/bin/python
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export MPLBACKEND=Agg

# Run "$@" with its output appended to the set-up log $SETUP_LOG (made on first use); if it
# fails, show the end of the log and stop. The terminal gets one line per step, not dpkg's.
quietly() {
    [ -n "${SETUP_LOG:-}" ] || SETUP_LOG=$(mktemp "${TMPDIR:-/tmp}/ehdfem-setup.XXXXXX.log")
    if ! "$@" >>"$SETUP_LOG" 2>&1; then
        echo "setup: failed: $*; the end of its log $SETUP_LOG:" >&2
        tail -n 40 "$SETUP_LOG" >&2
        exit 1
    fi
}

setup() {
    local missing=() sudo=""
    [ "$(id -u)" -eq 0 ] || sudo=sudo
    for package in "${APT_PACKAGES[@]}"; do
        dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" \
            || missing+=("$package")
    done
    if ((${#missing[@]})); then
        echo "setup: updating the Debian package lists (apt-get update)"
        quietly $sudo apt-get update
        echo "setup: installing Debian packages: ${missing[*]} (log: $SETUP_LOG)"
        quietly $sudo env DEBIAN_FRONTEND=noninteractive \
            apt-get install -y --no-install-recommends "${missing[@]}"
    fi
    if [ ! -x "$PY" ]; then
        echo "setup: creating the venv $VENV on Debian's python (system site packages)"
        quietly /usr/bin/python3 -m venv --system-site-packages "$VENV"
    fi
    local stamp="$VENV/.ehdfem-installed" want
    want=$(cat pyproject.toml constraints.txt | sha256sum | cut -d' ' -f1)
    if [ "$(cat "$stamp" 2>/dev/null)" != "$want" ]; then
        echo "setup: installing ehdfem and its Python dependencies into $VENV"
        quietly "$PY" -m pip install --disable-pip-version-check -c constraints.txt -e ".[test]"
        echo "$want" > "$stamp"
    fi
    "$PY" -c 'import numpy, sys; sys.exit(numpy.__version__.startswith("1.") == False)' \
        || { echo "setup: numpy >= 2 found in $VENV; Debian's compiled modules need numpy 1.x" >&2; exit 1; }
}

run_tests() {
    # run_tests PYTHON MPIRUN [pytest arguments]: the tests in two processes (pytest-xdist, a
    # test file per process at a time: the files share nothing but the FE caches, which are
    # written atomically), one per core; then on two MPI ranks, without the tests marked
    # serial. Rank 0 reports (OpenMPI and MPICH name the rank differently); the other rank's
    # report goes to a log (mpirun fails if any rank fails).
    local python=$1 launcher=$2 status=0
    shift 2
    "$python" -m pytest -q -n 2 --dist loadfile "$@"
    "$launcher" -n 2 bash -c 'if [ "${OMPI_COMM_WORLD_RANK:-${PMI_RANK:-0}}" = 0 ]; then exec "$@"; else exec "$@" > .pytest-rank1.log 2>&1; fi' \
        _ "$python" -m pytest -q --color=no -p no:cacheprovider -m "not serial" "$@" || status=$?
    [ "$status" -eq 0 ] || cat .pytest-rank1.log
    [ "$status" -eq 0 ] || [ "$status" -eq 5 ] || exit "$status"   # 5: no MPI test selected
}

run_example() {
    # run_example VENV OUT [collide options]: the main job (both models, plots, JSON, the FE
    # fields, a picture and the film animation) with VENV's ehdfem, written to OUT.
    local bin=$1/bin out=$2
    shift 2
    mkdir -p "$out/halfspace" "$out/fem"
    echo "== half-space model (asymptotic theory)"
    "$bin/ehdfem" collide --example --plots "$out/halfspace" --json "$out/halfspace.json" "$@"
    echo "== FE model (DOLFINx solids)"
    "$bin/ehdfem" collide --example --model fem --plots "$out/fem" --json "$out/fem.json" \
        --fields "$out/fem/fields.xdmf" "$@"
    echo "== picture of the deformed solids and film animation (FE model)"
    "$bin/ehdfem" render --example --out "$out/fem/render.png" --animation "$out/fem/film.gif" "$@"
}

# The wheel stack: its own venv on a Python >= 3.12 found on PATH or under pyenv, nothing from
# the system's site packages, ehdfem with the extras fem and test from the package registry.
WHEEL_VENV=.venv-wheel
WHEEL_PY=$WHEEL_VENV/bin/python
# The test files of the FE stack: those that import DOLFINx, UFL, gmsh, meshio, pyvista or
# mpi4py, or the seam ehdfem.fenicsx, or build the FE model, its outputs or the bounce's resolved
# flows; and the stored table of 23 collisions (FE and half-space: Debian's results, at its 1e-8
# on numpy 2 too).
WHEEL_TABLE=tests/test_regression.py::test_outputs_equal_the_stored_table
WHEEL_TESTS='^\s*(import|from) (dolfinx|ufl|gmsh|meshio|pyvista|mpi4py)\b|solids\.fe|"fem"|ehdfem\.bounce|ehdfem\.outputs\.(render|fields)|tangential\.disk|from ehdfem\.fenicsx'

wheel_python() {
    # The first Python >= 3.12: python3.12, 3.13 or 3.14 on PATH, else one of pyenv's.
    local candidate
    for candidate in $(command -v python3.12 python3.13 python3.14) \
            "${PYENV_ROOT:-$HOME/.pyenv}"/versions/3.1[2-9]*/bin/python; do
        # (pyenv's shims exist for every version and fail, noisily, for one not selected)
        if [ -x "$candidate" ] && "$candidate" -c 'import sys; sys.exit(sys.version_info < (3, 12))' 2>/dev/null; then
            echo "$candidate"
            return
        fi
    done
    return 1
}

wheel_setup() {
    if [ ! -x "$WHEEL_PY" ]; then
        local python
        python=$(wheel_python) || {
            echo "wheel-test: no Python >= 3.12 found (python3.12 on PATH, or under ${PYENV_ROOT:-$HOME/.pyenv}/versions/): install one" >&2
            exit 1
        }
        echo "setup: creating the venv $WHEEL_VENV on $python (no system site packages)"
        quietly "$python" -m venv "$WHEEL_VENV"
    fi
    local stamp="$WHEEL_VENV/.ehdfem-installed" want
    want=$(sha256sum pyproject.toml | cut -d' ' -f1)
    if [ "$(cat "$stamp" 2>/dev/null)" != "$want" ]; then
        echo "setup: installing ehdfem[fem,test] and its dependencies into $WHEEL_VENV (wheels)"
        quietly "$WHEEL_PY" -m pip install --disable-pip-version-check -e ".[fem,test]"
        echo "$want" > "$stamp"
    fi
    "$WHEEL_PY" -c 'import sys, mpi4py.MPI, dolfinx, numpy
print(f"setup: {sys.prefix}: DOLFINx {dolfinx.__version__}, numpy {numpy.__version__}")'
}

wheel_test() {
    wheel_setup
    local files
    mapfile -t files < <(grep -lE "$WHEEL_TESTS" tests/test_*.py)
    echo "== wheel stack: ${#files[@]} test files (${files[*]#tests/}) and ${WHEEL_TABLE#tests/}"
    files+=("$WHEEL_TABLE")
    run_tests "$WHEEL_PY" "$WHEEL_VENV/bin/mpirun" "${files[@]}" "$@"
    echo "== wheel stack: the main job (bash make.sh example)"
    run_example "$WHEEL_VENV" out/example-wheel
}

run_study() {
    # The source's results end to end: sweep on 2 ranks, St_c per eps, fits, figures.
    local results=studies/results
    mpirun -n 2 "$VENV/bin/ehdfem" sweep studies/kantak_davis.toml
    for eps in 1e-6 1e-5 1e-4 1e-3 1e-2; do
        "$VENV/bin/ehdfem" critical --eps "$eps" --p-cav=-10 --json "$results/critical_$eps.json"
    done
    "$VENV/bin/ehdfem" fit "$results/kantak_davis.csv" --json "$results/kantak_davis_fit.json"
    "$PY" studies/kantak_davis_figures.py
}

job=${1:-}
shift || true
case "$job" in
    setup) setup ;;
    example) setup; run_example "$VENV" out/example "$@" ;;
    test) setup; run_tests "$PY" mpirun "$@" ;;
    wheel-test) wheel_test "$@" ;;
    lint) setup; "$VENV/bin/ruff" check . && "$VENV/bin/ruff" format --check . ;;
    bench) setup
        "$PY" benchmarks/normal_collision.py "$@"
        "$PY" benchmarks/sweep.py "$@"
        "$PY" benchmarks/film_options.py
        "$PY" benchmarks/accuracy.py
        mpirun -n 2 "$PY" benchmarks/fem_collision.py "$@" ;;
    study) setup; run_study ;;
    claims) setup; mpirun -n 2 "$PY" studies/source_claims.py ;;
    closed-forms) setup
        "$PY" studies/dem_closed_forms.py "$@" ;;
    validate) setup; "$PY" studies/validation.py ;;
    dem-engines) setup; nice -n 10 "$PY" studies/dem_engines.py ;;
    *) echo "usage: bash make.sh setup|example|test|wheel-test|lint|bench|study|claims|closed-forms|validate|dem-engines [args]" >&2; exit 2 ;;
esac
