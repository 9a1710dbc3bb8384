"""The package's structure (docs/architecture.md): packages in layers whose imports point down,
no import cycle between modules, no function over 80 lines, and every DOLFINx call in the
compatibility seam. These read the source, not run it."""

import ast
import re
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parent.parent / "ehdfem"

# Bottom to top. A module may import from its own package and from the layers below.
LAYERS = (
    ("checks", "version", "console", "threads"),
    ("settings",),
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
DOLFINX_SEAM = "ehdfem.solids.fe.dolfinx_compat"
# Attributes of DOLFINx objects whose name or form differs between Debian's 0.5.2 and 0.11
# (the seam's docstrings): used on a DOLFINx object, only in the seam; the seam's own functions
# of these names are called as dolfinx_compat.NAME.
DIFFERING = {
    "vector": "Function.vector / .x.petsc_vec",
    "petsc_vec": "Function.vector / .x.petsc_vec",
    "interpolation_points": "a method in 0.5, a property in 0.10",
    "FunctionSpace": "fem.FunctionSpace / fem.functionspace",
    "VectorFunctionSpace": "fem.VectorFunctionSpace / fem.functionspace",
    "functionspace": "fem.FunctionSpace / fem.functionspace",
    "create_vtk_mesh": "plot.create_vtk_mesh / plot.vtk_mesh",
    "vtk_mesh": "plot.create_vtk_mesh / plot.vtk_mesh",
    "BoundingBoxTree": "geometry.BoundingBoxTree / geometry.bb_tree",
    "bb_tree": "geometry.BoundingBoxTree / geometry.bb_tree",
    "gmshio": "io.gmshio / io.gmsh",
    "VectorElement": "UFL's elements / basix.ufl",
    "MixedElement": "UFL's elements / basix.ufl",
    "list": "dofmap.list: an AdjacencyList / a 2-D array",
    "dofmap": "geometry.dofmap: an AdjacencyList / geometry.dofmaps[0]",
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


def test_every_dolfinx_call_in_the_seam():
    outside = [
        f"{name}:{node.lineno}"
        for name, _, tree in _modules()
        if name != DOLFINX_SEAM
        for node in ast.walk(tree)
        if isinstance(node, ast.Import | ast.ImportFrom)
        and any(
            (getattr(node, "module", None) or alias.name).split(".")[0] == "dolfinx"
            for alias in node.names
        )
    ]
    assert not outside, "DOLFINx imported outside the seam:\n" + "\n".join(outside)


def test_what_differs_between_dolfinx_versions_is_in_the_seam():
    """The attributes that differ between DOLFINx 0.5.2 and 0.11 (DIFFERING) are used only in
    the seam, which handles both forms; elsewhere only as calls of the seam's own functions
    (``dolfinx_compat.vtk_mesh``) or, for ``list`` and ``dofmap``, on other objects than a
    dofmap or a geometry (``space.dofmap.index_map`` is the same in both)."""
    outside = []
    for name, _, tree in _modules():
        if name == DOLFINX_SEAM:
            continue
        for node in ast.walk(tree):
            if not isinstance(node, ast.Attribute) or node.attr not in DIFFERING:
                continue
            base = ast.unparse(node.value)
            if base in ("dolfinx_compat", "compat"):
                continue
            if node.attr == "list" and not base.endswith("dofmap"):
                continue
            if node.attr == "dofmap" and not base.endswith("geometry"):
                continue
            outside.append(f"{name}:{node.lineno} {base}.{node.attr} ({DIFFERING[node.attr]})")
    assert not outside, "version-dependent DOLFINx uses outside the seam:\n" + "\n".join(outside)


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
