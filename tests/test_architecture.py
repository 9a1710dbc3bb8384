"""The package's structure (docs/architecture.md): packages in layers whose imports point down,
no import cycle between modules, no file over 600 lines, no function over 80 lines, every use of
DOLFINx, basix and PETSc objects in the seam ehdfem.fenicsx, one class per lower body, no name
of a viscosity law or cavitation model outside ehdfem/film/, and the bounce's options generated
from its inputs. These read the source, not run it (the bounce's options: its parser). Each
check is a function of a package folder; test_each_check_fails_on_a_planted_violation runs it
on a small package that breaks it."""

import ast
import re
from pathlib import Path

import pytest

pytestmark = pytest.mark.serial  # no parallel path: the MPI pass leaves it out

PACKAGE = Path(__file__).resolve().parent.parent / "ehdfem"

# Bottom to top. A module may import from its own package and from the layers below.
LAYERS = (
    ("checks", "version", "console", "threads", "lapack", "kept"),
    ("settings",),
    ("fenicsx",),
    ("exact",),
    ("film",),
    ("inputs",),
    ("solids",),
    ("motion",),
    ("tangential",),
    ("outputs",),
    ("config",),
    ("collision",),
    ("dem",),
    ("study", "bounce"),
    ("cli",),
    ("__init__", "__main__"),
)
LONGEST_FUNCTION = 80  # lines, decorators excluded
LONGEST_FILE = 600  # lines
SEAM = "ehdfem.fenicsx"  # the package that holds every use of DOLFINx (docs/architecture.md)
SEAM_LIBRARIES = ("dolfinx", "basix", "petsc4py")  # imported, or loaded by name, only there
SEAM_MODULES = {path.stem for path in (PACKAGE / "fenicsx").glob("*.py")}
# UFL is the physics modules' form language and the same on both DOLFINx releases; its element
# constructors are not (basix.ufl's from 0.7): used only in the seam.
UFL_ELEMENTS = {"FiniteElement", "VectorElement", "TensorElement", "MixedElement"}
# Attributes that only DOLFINx's and PETSc's objects have in this package: used on an object,
# only in the seam. Elsewhere a name of this set may only be a seam function (spaces.vtk_mesh).
DOLFINX_ATTRIBUTES = {
    "petsc_vec": "Function.x.petsc_vec",
    "vector": "Function.vector",
    "scatter_forward": "Function.x.scatter_forward",
    "scatter_reverse": "Function.x.scatter_reverse",
    "interpolate": "Function.interpolate",
    "eval": "Function.eval",
    "function_space": "Function.function_space",
    "function_spaces": "Form.function_spaces",
    "dofmap": "FunctionSpace.dofmap, Geometry.dofmap",
    "dofmaps": "Geometry.dofmaps",
    "index_map": "DofMap.index_map, Topology.index_map",
    "index_map_bs": "DofMap.index_map_bs",
    "size_local": "IndexMap.size_local",
    "size_global": "IndexMap.size_global",
    "num_ghosts": "IndexMap.num_ghosts",
    "tabulate_dof_coordinates": "FunctionSpace.tabulate_dof_coordinates",
    "collapse": "FunctionSpace.collapse",
    "interpolation_points": "FiniteElement.interpolation_points",
    "geometry": "Mesh.geometry",
    "topology": "Mesh.topology",
    "create_connectivity": "Topology.create_connectivity",
    "ufl_cell": "Mesh.ufl_cell",
    "basix_cell": "Mesh.basix_cell",
    "find": "MeshTags.find",
    "FunctionSpace": "fem.FunctionSpace",
    "VectorFunctionSpace": "fem.VectorFunctionSpace",
    "functionspace": "fem.functionspace",
    "gmshio": "io.gmshio",
    "create_vtk_mesh": "plot.create_vtk_mesh",
    "vtk_mesh": "plot.vtk_mesh",
    "BoundingBoxTree": "geometry.BoundingBoxTree",
    "bb_tree": "geometry.bb_tree",
    "getArray": "PETSc Vec",
    "getDenseArray": "PETSc Mat",
    "getValuesCSR": "PETSc Mat",
    "ghostUpdate": "PETSc Vec",
    "localForm": "PETSc Vec",
    "duplicate": "PETSc Vec, Mat",
    "destroy": "PETSc objects",
    "matMult": "PETSc Mat",
    "transposeMatMult": "PETSc Mat",
    "setOption": "PETSc Mat",
    "setUp": "PETSc KSP, Mat",
    "getPC": "PETSc KSP",
    "getKSP": "PETSc SNES",
    "setType": "PETSc KSP, PC, SNES",
    "setTolerances": "PETSc KSP, SNES",
    "setFactorSolverType": "PETSc PC",
    "getConvergedReason": "PETSc KSP, SNES",
}
# The same attribute names on the package's own objects are fine: these only on such bases, or
# only when not called (a lower body's geometry(...) is its gmsh generator).
NOT_CALLED = {"geometry"}
ON_BASES = {
    "value": ("assigned", "Constant.value (functions.set_constant)"),
    "mesh": ("space", "FunctionSpace.mesh (spaces.mesh_of)"),
    "comm": ("mesh", "Mesh.comm (domain.communicator)"),
}


def _modules(package: Path = PACKAGE):
    """(module name, path, syntax tree) of every module of the package in folder ``package``."""
    for path in sorted(package.rglob("*.py")):
        parts = path.relative_to(package.parent).with_suffix("").parts
        name = ".".join(parts[:-1] if parts[-1] == "__init__" else parts)
        yield name, path, ast.parse(path.read_text())


def _imports(name, path, tree, annotations=False):
    """The ehdfem modules (or packages) that a module imports, absolute: at run time, and with
    ``annotations`` also those for type annotations only (under ``if TYPE_CHECKING:``)."""
    here = name.split(".") if path.name == "__init__.py" else name.split(".")[:-1]
    root = path.parents[len(name.split(".")) - (path.name != "__init__.py")]
    typing_only = {
        id(inner)
        for node in ast.walk(tree)
        if isinstance(node, ast.If) and ast.unparse(node.test) == "TYPE_CHECKING"
        for inner in ast.walk(node)
        if not annotations
    }
    for node in ast.walk(tree):
        if id(node) in typing_only:
            continue
        if isinstance(node, ast.ImportFrom) and node.level:
            base = here[: len(here) - node.level + 1]
            target = ".".join(base + ([node.module] if node.module else []))
            modules = [  # "from .. import checks": a module of that package
                f"{target}.{alias.name}"
                for alias in node.names
                if (root / f"{target}.{alias.name}".replace(".", "/")).with_suffix(".py").exists()
            ]
            yield from modules or [target]
        elif isinstance(node, ast.ImportFrom) and (node.module or "").startswith("ehdfem"):
            yield node.module


def _layer(module: str) -> int:
    """The layer of a module: that of its top-level package (or of itself, at the top)."""
    top = module.split(".")[1] if "." in module else "__init__"
    for index, names in enumerate(LAYERS):
        if top in names:
            return index
    raise AssertionError(f"{module} is in no layer: add its package to LAYERS")


def upward_imports(package: Path = PACKAGE) -> list[str]:
    """The imports of the package in ``package`` that do not point down (module -> target)."""
    upward = []
    for name, path, tree in _modules(package):
        top = name.split(".")[1] if "." in name else name
        for target in _imports(name, path, tree):
            target_top = target.split(".")[1] if "." in target else target
            if target_top != top and _layer(target) >= _layer(name):
                upward.append(f"{name} -> {target}")
    return upward


def test_imports_point_down():
    upward = upward_imports()
    assert not upward, "imports that do not point down:\n" + "\n".join(upward)


def import_cycle(package: Path = PACKAGE) -> list[str]:
    """An import cycle of the package in ``package`` (its modules in order, the first again at
    the end; empty: none), through imports for type annotations too."""
    graph = {name: set(_imports(name, path, tree, True)) for name, path, tree in _modules(package)}
    state = {}

    def visit(module, trail):
        if state.get(module) == "done" or module not in graph:
            return []
        if state.get(module) == "open":
            return trail[trail.index(module) :] + [module]
        state[module] = "open"
        for target in graph[module]:
            cycle = visit(target, trail + [module])
            if cycle:
                return cycle
        state[module] = "done"
        return []

    for module in graph:
        cycle = visit(module, [])
        if cycle:
            return cycle
    return []


def test_no_import_cycles():
    """Not even through imports for type annotations only (a Protocol of what a module reads
    stands in for the class of a module above it)."""
    cycle = import_cycle()
    assert not cycle, "import cycle: " + " -> ".join(cycle)


def long_functions(package: Path = PACKAGE) -> list[str]:
    """The functions over LONGEST_FUNCTION lines of the package in ``package``."""
    return [
        f"{name}.{node.name}: {node.end_lineno - node.lineno + 1} lines"
        for name, _, tree in _modules(package)
        for node in ast.walk(tree)
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef)
        and node.end_lineno - node.lineno + 1 > LONGEST_FUNCTION
    ]


def test_no_function_over_80_lines():
    long = long_functions()
    assert not long, "functions over 80 lines:\n" + "\n".join(long)


def long_files(package: Path = PACKAGE) -> list[str]:
    """The files of the package in ``package`` over LONGEST_FILE lines (Python and the rest)."""
    return [
        f"{path.relative_to(package.parent)}: {lines} lines"
        for path in sorted(package.rglob("*.py"))
        if (lines := len(path.read_text().splitlines())) > LONGEST_FILE
    ]


def test_no_file_over_600_lines():
    long = long_files()
    assert not long, "files over 600 lines:\n" + "\n".join(long)


def lower_body_classes(package: Path = PACKAGE) -> list[str]:
    """Where the classes Wall, CoatedWall and LowerSphere are defined at a module's top level in
    the package in ``package`` (module:line)."""
    return [
        f"{name}:{node.lineno} {node.name}"
        for name, _, tree in _modules(package)
        for node in tree.body
        if isinstance(node, ast.ClassDef) and node.name in ("Wall", "CoatedWall", "LowerSphere")
    ]


def test_one_class_per_lower_body():
    """Issue 46: one definition per lower body, the class that configures the run and builds
    the FE solid (``grep -rn "^class \\(Wall\\|CoatedWall\\|LowerSphere\\)\\b" ehdfem``:
    three lines)."""
    found = lower_body_classes()
    assert sorted(line.split()[-1] for line in found) == ["CoatedWall", "LowerSphere", "Wall"], (
        "the lower bodies' classes:\n" + "\n".join(found)
    )
    assert all(line.startswith("ehdfem.solids.fe.bodies.") for line in found), found


def _outside_the_seam(package: Path = PACKAGE):
    """(module name, syntax tree) of every module outside the seam."""
    for name, _, tree in _modules(package):
        if name != SEAM and not name.startswith(SEAM + "."):
            yield name, tree


def seam_imports_outside(package: Path = PACKAGE) -> list[str]:
    """The imports of dolfinx, basix and petsc4py outside the seam of the package in
    ``package``: imported, or loaded by name (``importlib.import_module("dolfinx.fem")``), and
    UFL's element constructors, which differ between the DOLFINx releases."""
    outside = []
    for name, tree in _outside_the_seam(package):
        for node in ast.walk(tree):
            if isinstance(node, ast.Import | ast.ImportFrom):
                modules = [alias.name for alias in node.names]
                if isinstance(node, ast.ImportFrom):
                    modules = [node.module or ""] if node.level == 0 else []
                    if node.module == "ufl":
                        modules += [f"ufl.{a.name}" for a in node.names if a.name in UFL_ELEMENTS]
            elif isinstance(node, ast.Call):
                modules = [
                    argument.value
                    for argument in node.args
                    if isinstance(argument, ast.Constant) and isinstance(argument.value, str)
                ]
            elif isinstance(node, ast.Attribute) and node.attr in UFL_ELEMENTS:
                modules = [f"ufl.{node.attr}"]
            else:
                continue
            outside += [
                f"{name}:{node.lineno} {module}"
                for module in modules
                if module.split(".")[0] in SEAM_LIBRARIES or module.startswith("ufl.")
            ]
    return outside


def test_dolfinx_basix_and_petsc4py_are_imported_in_the_seam_only():
    outside = seam_imports_outside()
    assert not outside, "FEniCSx libraries used outside the seam:\n" + "\n".join(outside)


def _dolfinx_use(node: ast.Attribute, assigned: bool, called: bool) -> str | None:
    """What ``node`` uses of a DOLFINx or PETSc object (None: nothing): an attribute of
    DOLFINX_ATTRIBUTES (of NOT_CALLED: unless ``called``), ``x.array`` (a function's values),
    or an attribute of ON_BASES on its base (an assignment to ``.value``, the ``.mesh`` of a
    space, the ``.comm`` of a mesh)."""
    base = ast.unparse(node.value)
    if base in SEAM_MODULES or (called and node.attr in NOT_CALLED):
        return None
    if node.attr in DOLFINX_ATTRIBUTES:
        return DOLFINX_ATTRIBUTES[node.attr]
    if node.attr == "array" and base.endswith(".x"):
        return "Function.x.array (functions.local_values)"
    if node.attr in ON_BASES:
        where, what = ON_BASES[node.attr]
        last = base.split(".")[-1].lower()
        if (assigned and where == "assigned") or (where != "assigned" and last.endswith(where)):
            return what
    return None


def dolfinx_uses_outside(package: Path = PACKAGE) -> list[str]:
    """The uses of DOLFINx's and PETSc's objects outside the seam of the package in
    ``package`` (module:line, the use)."""
    outside = []
    for name, tree in _outside_the_seam(package):
        assigned = {
            id(target)
            for node in ast.walk(tree)
            if isinstance(node, ast.Assign | ast.AugAssign | ast.AnnAssign)
            for target in (node.targets if isinstance(node, ast.Assign) else [node.target])
        }
        called = {id(node.func) for node in ast.walk(tree) if isinstance(node, ast.Call)}
        for node in ast.walk(tree):
            if isinstance(node, ast.Name) and node.id == "PETSc":
                outside.append(f"{name}:{node.lineno} PETSc")
            if isinstance(node, ast.Attribute):
                use = _dolfinx_use(node, id(node) in assigned, id(node) in called)
                if use is not None:
                    outside.append(f"{name}:{node.lineno} {ast.unparse(node)} ({use})")
    return outside


def test_no_dolfinx_object_is_used_outside_the_seam():
    """Outside ehdfem.fenicsx, DOLFINx's and PETSc's objects are handles passed back to the
    seam's functions (and to UFL): no attribute of theirs is read, called or set there, and the
    name PETSc does not occur. A change of DOLFINx release then changes the seam alone."""
    outside = dolfinx_uses_outside()
    assert not outside, "DOLFINx or PETSc objects used outside the seam:\n" + "\n".join(outside)


def _model_names() -> list[str]:
    """The names of the registered viscosity laws and cavitation models."""
    from ehdfem.film import cavitation, viscosity

    return [*viscosity.LAWS.names(), *cavitation.MODELS.names()]


def _names_none(node: ast.AST) -> bool:
    """Whether ``node`` is the string "none" (the cavitation model without a limit's name, also
    the off-value of other settings)."""
    return isinstance(node, ast.Constant) and node.value == "none"


def _about_the_liquid(node: ast.AST) -> bool:
    """Whether the source of ``node`` speaks of a viscosity law or cavitation model."""
    return re.search("cavitation|viscosity", ast.unparse(node)) is not None


def model_names_outside_the_film(package: Path = PACKAGE, names=None) -> list[str]:
    """The quoted names of viscosity laws and cavitation models (``names``; default: the
    registered ones) in the package in ``package`` outside its film/: every name but "none"
    wherever quoted, and "none" where it stands for a model, compared with, assigned to or
    passed as something that speaks of cavitation or viscosity (``cavitation == "none"``,
    ``viscosity="none"``)."""
    names = _model_names() if names is None else names
    pattern = re.compile("|".join(rf"[\"']{re.escape(n)}[\"']" for n in names if n != "none"))
    found = [
        f"{path.relative_to(package.parent)}:{number}: {line.strip()}"
        for path in sorted(package.rglob("*.py"))
        if "film" not in path.relative_to(package).parts[:1]
        for number, line in enumerate(path.read_text().splitlines(), 1)
        if pattern.search(line)
    ]
    if "none" not in names:
        return found
    for name, _, tree in _modules(package):
        if name.split(".")[1:2] == ["film"]:
            continue
        for node in ast.walk(tree):
            if isinstance(node, ast.Compare):
                sides = [node.left, *node.comparators]
                named = any(map(_names_none, sides)) and any(map(_about_the_liquid, sides))
            elif isinstance(node, ast.keyword):
                named = _names_none(node.value) and re.search(
                    "cavitation|viscosity", node.arg or ""
                )
            elif isinstance(node, ast.Assign | ast.AnnAssign):
                targets = node.targets if isinstance(node, ast.Assign) else [node.target]
                named = _names_none(node.value) and any(map(_about_the_liquid, targets))
            else:
                continue
            if named:
                found.append(f"{name}:{node.lineno}: {ast.unparse(node)[:80]}")
    return found


def test_viscosity_and_cavitation_names_only_in_the_film():
    """No quoted name of a viscosity law or a cavitation model outside ehdfem/film/: the other
    packages read the components (their classes, ``name``, flags such as ``tracks_liquid``),
    never compare or build from the names ("none", also the off-value of other settings, where
    it stands for the cavitation model)."""
    names = _model_names()
    found = model_names_outside_the_film()
    assert len(names) >= 6 and "none" in names and not found, (
        "model names outside film/:\n" + "\n".join(found)
    )


def hand_written_bounce_options(add=None) -> list[str]:
    """The options of ``ehdfem bounce`` (those ``add`` puts on a parser; default: the
    command's) for a field of the bounce's inputs (BounceInputs) or of its numerics
    (BounceRun, and the contacts' film numerics it holds) that are not the generated ones
    (:func:`ehdfem.cli.arguments.add_fields`: their help, unit, range and default from the
    field's metadata), and the fields without an option."""
    import argparse

    from ehdfem import BounceInputs, BounceRun, IntegratorOptions
    from ehdfem.cli import bounce
    from ehdfem.cli.arguments import add_fields
    from ehdfem.cli.inputs import BODIES, add_body_arguments
    from ehdfem.config import Numerics

    parser = argparse.ArgumentParser()
    (add or bounce.add_bounce)(parser)
    generated = argparse.ArgumentParser()
    add_body_arguments(generated)
    add_fields(generated, BounceInputs, names=bounce.START)
    add_fields(generated, BounceInputs, exclude=(*BODIES, *bounce.START), switches=True)
    add_fields(generated, BounceRun)
    add_fields(generated, Numerics, names=bounce.NUMERICS)
    add_fields(generated, IntegratorOptions, names=bounce.INTEGRATOR)
    expected = {a.dest: (a.option_strings, a.help) for a in generated._actions if a.dest != "help"}
    actual = {a.dest: (a.option_strings, a.help) for a in parser._actions}
    return [
        f"{dest}: {actual.get(dest)} instead of {want}"
        for dest, want in expected.items()
        if actual.get(dest) != want
    ]


def test_the_bounce_options_are_generated_from_its_inputs():
    """Issue 46: cli/bounce.py has no hand-written option for a field of BounceInputs or of the
    bounce's numerics (BounceRun): each field's option is the one generated from its metadata;
    the only options written out are the outputs'."""
    from ehdfem import BounceInputs, BounceRun
    from ehdfem.cli import bounce
    from ehdfem.settings import flat_fields

    assert len(list(flat_fields(BounceInputs))) >= 20 and len(list(flat_fields(BounceRun))) == 5
    wrong = hand_written_bounce_options()
    assert not wrong, "bounce options not generated from BounceInputs:\n" + "\n".join(wrong)
    source = Path(bounce.__file__).read_text()
    written = re.findall(r"add_argument\(\s*\"(--[a-z-]+)\"", source)
    assert sorted(written) == ["--folder", "--json", "--out"], written


def test_the_inputs_hold_components_in_at_most_fifteen_fields():
    """CollisionParameters holds the liquid's laws, the gap and the surfaces' asperity model as
    components (issue 46: at most 15 fields); every component constant's flat key is unique
    across the roles and differs from the inputs' own fields, so a flat key names one thing."""
    import dataclasses

    from ehdfem.inputs.scales import CollisionParameters
    from ehdfem.settings import components, described

    assert len(dataclasses.fields(CollisionParameters)) <= 15
    own = {f.name for f in described(CollisionParameters)}
    roles = components(CollisionParameters)
    assert {f.name for f, _ in roles} == {"viscosity", "cavitation", "gap", "asperities"}
    keys = [{g.name for _, g in registry.fields()} for _, registry in roles]
    for i, mine in enumerate(keys):
        assert not mine & own and not any(mine & other for other in keys[i + 1 :])


PLANTED = {  # a small package breaking every check above, file by file
    "__init__.py": "",
    "checks.py": "from .film import gap\n",  # upward
    "config.py": "class Wall:\n    pass\n",  # a second lower body class
    "film/__init__.py": "",
    "film/gap.py": "from . import grid\n",  # a cycle
    "film/grid.py": "from . import gap\n",
    "solids/__init__.py": "",
    "solids/mesh.py": "import dolfinx\n\n\ndef points(mesh):\n    return mesh.geometry.x\n",
    "collision.py": (
        "def f(params):\n    if params.cavitation == 'none':\n        return 'barus'\n"
        + "    x = 0\n" * 80
    ),
    "study/__init__.py": "\n" * 601,
}


def test_each_check_fails_on_a_planted_violation(tmp_path):
    """The checks above are not vacuous: on a package that breaks each of them once they report
    exactly the planted violations, and the bounce's check reports a hand-written option."""

    for name, text in PLANTED.items():
        (tmp_path / "ehdfem" / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / "ehdfem" / name).write_text(text)
    package = tmp_path / "ehdfem"
    assert upward_imports(package) == ["ehdfem.checks -> ehdfem.film.gap"]
    assert sorted(import_cycle(package)[:-1]) == ["ehdfem.film.gap", "ehdfem.film.grid"]
    assert long_functions(package) == ["ehdfem.collision.f: 83 lines"]
    assert long_files(package) == ["ehdfem/study/__init__.py: 601 lines"]
    assert lower_body_classes(package) == ["ehdfem.config:1 Wall"]
    assert seam_imports_outside(package) == ["ehdfem.solids.mesh:1 dolfinx"]
    assert dolfinx_uses_outside(package) == ["ehdfem.solids.mesh:5 mesh.geometry (Mesh.geometry)"]
    found = model_names_outside_the_film(package, names=("barus", "none"))
    assert [line.split(":")[:2] for line in found] == [["ehdfem/collision.py", "3"]] + [
        ["ehdfem.collision", "2"]
    ]

    def hand_written(parser):  # --e-dry written out, not generated
        from ehdfem import BounceInputs
        from ehdfem.cli.arguments import add_fields

        add_fields(parser, BounceInputs, exclude=("e_dry",))
        parser.add_argument("--e-dry", type=float, help="dry restitution")

    assert any(line.startswith("e_dry:") for line in hand_written_bounce_options(hand_written))
