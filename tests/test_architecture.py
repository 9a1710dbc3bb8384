"""The package's structure (docs/architecture.md): packages in layers whose imports point down,
no import cycle between modules, no function over 80 lines, and every use of DOLFINx, basix and
PETSc objects in the seam ehdfem.fenicsx. These read the source, not run it."""

import ast
import re
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parent.parent / "ehdfem"

# Bottom to top. A module may import from its own package and from the layers below.
LAYERS = (
    ("checks", "version", "console", "threads"),
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


def _modules():
    """(module name, path, syntax tree) of every module of the package."""
    for path in sorted(PACKAGE.rglob("*.py")):
        parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
        name = ".".join(parts[:-1] if parts[-1] == "__init__" else parts)
        yield name, path, ast.parse(path.read_text())


def _imports(name, path, tree, annotations=False):
    """The ehdfem modules (or packages) that a module imports, absolute: at run time, and with
    ``annotations`` also those for type annotations only (under ``if TYPE_CHECKING:``)."""
    here = name.split(".") if path.name == "__init__.py" else name.split(".")[:-1]
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
                if (PACKAGE.parent / f"{target}.{alias.name}".replace(".", "/"))
                .with_suffix(".py")
                .exists()
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


def test_imports_point_down():
    upward = []
    for name, path, tree in _modules():
        top = name.split(".")[1] if "." in name else name
        for target in _imports(name, path, tree):
            target_top = target.split(".")[1] if "." in target else target
            if target_top != top and _layer(target) >= _layer(name):
                upward.append(f"{name} -> {target}")
    assert not upward, "imports that do not point down:\n" + "\n".join(upward)


def test_no_import_cycles():
    """Not even through imports for type annotations only (a Protocol of what a module reads
    stands in for the class of a module above it)."""
    graph = {name: set(_imports(name, path, tree, True)) for name, path, tree in _modules()}
    state = {}

    def visit(module, trail):
        if state.get(module) == "done" or module not in graph:
            return
        if state.get(module) == "open":
            pytest.fail("import cycle: " + " -> ".join(trail[trail.index(module) :] + [module]))
        state[module] = "open"
        for target in graph[module]:
            visit(target, trail + [module])
        state[module] = "done"

    for module in graph:
        visit(module, [])


def test_no_function_over_80_lines():
    long = [
        f"{name}.{node.name}: {node.end_lineno - node.lineno + 1} lines"
        for name, _, tree in _modules()
        for node in ast.walk(tree)
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef)
        and node.end_lineno - node.lineno + 1 > LONGEST_FUNCTION
    ]
    assert not long, "functions over 80 lines:\n" + "\n".join(long)


def _outside_the_seam():
    """(module name, syntax tree) of every module outside the seam."""
    for name, _, tree in _modules():
        if name != SEAM and not name.startswith(SEAM + "."):
            yield name, tree


def test_dolfinx_basix_and_petsc4py_are_imported_in_the_seam_only():
    """Imported, or loaded by name (``importlib.import_module("dolfinx.fem")``), and UFL's
    element constructors, which differ between the DOLFINx releases."""
    outside = []
    for name, tree in _outside_the_seam():
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


def test_no_dolfinx_object_is_used_outside_the_seam():
    """Outside ehdfem.fenicsx, DOLFINx's and PETSc's objects are handles passed back to the
    seam's functions (and to UFL): no attribute of theirs is read, called or set there, and the
    name PETSc does not occur. A change of DOLFINx release then changes the seam alone."""
    outside = []
    for name, tree in _outside_the_seam():
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
    assert not outside, "DOLFINx or PETSc objects used outside the seam:\n" + "\n".join(outside)


def test_viscosity_and_cavitation_names_only_in_the_film():
    """No quoted name of a viscosity law or a cavitation model outside ehdfem/film/: the other
    packages read the components (their classes, ``name``, flags such as ``tracks_liquid``),
    never compare or build from the names. ("none", also the off-value of other settings,
    is left out of the search.)"""
    from ehdfem.film import cavitation, viscosity

    names = [n for n in (*viscosity.LAWS.names(), *cavitation.MODELS.names()) if n != "none"]
    pattern = re.compile("|".join(rf"[\"']{re.escape(n)}[\"']" for n in names))
    found = [
        f"{path.relative_to(PACKAGE.parent)}:{number}: {line.strip()}"
        for path in sorted(PACKAGE.rglob("*.py"))
        if "film" not in path.relative_to(PACKAGE).parts[:1]
        for number, line in enumerate(path.read_text().splitlines(), 1)
        if pattern.search(line)
    ]
    assert len(names) >= 5 and not found, "model names outside film/:\n" + "\n".join(found)


def test_the_inputs_hold_components_in_at_most_fifteen_fields():
    """CollisionParameters holds the liquid's laws and the surfaces' asperity model as
    components (issue 46: at most 15 fields); every component constant's flat key is unique
    across the roles and differs from the inputs' own fields, so a flat key names one thing."""
    import dataclasses

    from ehdfem.inputs.scales import CollisionParameters
    from ehdfem.settings import components, described

    assert len(dataclasses.fields(CollisionParameters)) <= 15
    own = {f.name for f in described(CollisionParameters)}
    roles = components(CollisionParameters)
    assert {f.name for f, _ in roles} == {"viscosity", "cavitation", "asperities"}
    keys = [{g.name for _, g in registry.fields()} for _, registry in roles]
    for i, mine in enumerate(keys):
        assert not mine & own and not any(mine & other for other in keys[i + 1 :])
