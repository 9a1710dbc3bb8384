"""Field metadata of the input dataclasses: one home for each setting's help text, unit or
scale, default and allowed values.

``setting(...)`` declares a dataclass field with that metadata; :func:`validate` checks an
instance against it (through :mod:`ehdfem.checks`, so a bad value names the field and
its allowed range), and the command line (:mod:`ehdfem.cli.arguments`) builds its options
from it: a new field appears there with its help, unit and default without further edits.

A physics choice with constants of its own (a viscosity law, a cavitation model) is a
*component*: a small frozen dataclass with a ``name`` (ClassVar) and its fields declared with
``setting(...)``, registered in the :class:`Registry` of its role in the module that implements
it. An input dataclass holds the component in a field declared with :func:`component`; its flat
form (:func:`flat`, :func:`from_flat`, :func:`flat_names`) names the role and the chosen
component by its name (``viscosity = <a law's name>``) and its fields (``alpha = 3.0``): the
keys of the command line, of a study file and of the JSON inputs.
"""

from __future__ import annotations

import dataclasses
import functools
import warnings
from typing import get_type_hints

from . import checks


def setting(
    default=dataclasses.MISSING,
    *,
    help: str,
    unit: str | None = None,
    choices: tuple | None = None,
    lower: float | None = None,
    upper: float | None = None,
    lower_open: bool = False,
    upper_open: bool = False,
    flag: str | None = None,
    default_text: str | None = None,
    checked: bool = True,
    read=None,
    write=None,
):
    """A dataclass field with metadata: ``help`` (what it is in the physics), ``unit`` (SI
    unit or scale, e.g. "Pa" or "by x0"), ``choices`` (allowed strings) or the range
    [lower, upper] (open ends with ``lower_open``/``upper_open``), ``flag``: its command-line
    name when it differs from the field's, ``default_text``: how to show the default.
    ``choices`` may be a :class:`Registry` (its names when asked). ``read`` and ``write``:
    the value from and to a study file or JSON (e.g. None for an infinite limit)."""
    metadata = {
        "help": help,
        "unit": unit,
        "choices": choices,
        "range": (lower, upper, lower_open, upper_open),
        "flag": flag,
        "default_text": default_text,
        "checked": checked,
        "read": read,
        "write": write,
    }
    return dataclasses.field(default=default, metadata=metadata)


def described(cls) -> list[dataclasses.Field]:
    """The scalar fields (bool, int, float, str, maybe None) of the dataclass ``cls``, with
    or without setting metadata (a field without shows its name as help: a new field
    appears on the command line without edits)."""
    return [f for f in dataclasses.fields(cls) if _scalar(cls, f)]


def meta(f: dataclasses.Field, key: str):
    """The setting metadata ``key`` of field ``f``, or its neutral value when ``f`` has none
    (help: the field's name in words)."""
    if key == "choices" and "registry" in f.metadata:
        return f.metadata["registry"].names()
    if "help" in f.metadata:
        value = f.metadata.get(key)
        return value.names() if key == "choices" and isinstance(value, Registry) else value
    neutral = {"help": f.name.replace("_", " "), "range": (None, None, False, False)}
    return neutral.get(key)


def _scalar(cls, f: dataclasses.Field) -> bool:
    try:
        kind(cls, f)
    except TypeError:
        return False
    return True


@functools.cache
def _type_hints(cls) -> dict:
    """The resolved annotations of ``cls`` (resolving them costs 0.3 ms a class, and the
    command line asks for every field's)."""
    return get_type_hints(cls)


def kind(cls, f: dataclasses.Field) -> type:
    """The value type of field ``f`` of ``cls``: bool, int, float or str (None allowed too
    when the annotation says ``| None``; str for a component field, given by its name)."""
    if "registry" in f.metadata:
        return str
    hint = _type_hints(cls)[f.name]
    for base in (bool, int, float, str):
        if hint is base or base in getattr(hint, "__args__", ()):
            return base
    raise TypeError(f"{cls.__name__}.{f.name}: no scalar type in {hint!r}")


def allowed_text(f: dataclasses.Field) -> str:
    """The allowed values of field ``f`` as text: "a | b" or a range "(0, 1]" ("" if free)."""
    if meta(f, "choices") is not None:
        return " | ".join(map(str, meta(f, "choices")))
    lower, upper, lower_open, upper_open = meta(f, "range")
    if lower is None and upper is None:
        return ""
    return checks.range_text(lower, upper, lower_open, upper_open)


def default_text(f: dataclasses.Field) -> str:
    """The default of field ``f`` as text ("required" when there is none, on or off for a
    switch)."""
    if f.metadata.get("default_text") is not None:
        return f.metadata["default_text"]
    if "registry" in f.metadata and f.default is not None:
        return f.default.name
    if f.default is dataclasses.MISSING:
        return "required"
    if f.default is None:
        return "none"
    if isinstance(f.default, bool):
        return "on" if f.default else "off"
    return f"{f.default:g}" if isinstance(f.default, float) else str(f.default)


def validate(instance) -> None:
    """Check every described field of the dataclass ``instance``: its type, and its choices
    or range (None passes where the annotation allows it)."""
    cls = type(instance)
    for f in (f for f in described(cls) if f.metadata.get("checked")):
        value = getattr(instance, f.name)
        hint = _type_hints(cls)[f.name]
        if value is None and type(None) in getattr(hint, "__args__", ()):
            continue
        base = kind(cls, f)
        if meta(f, "choices") is not None:
            checks.choice(f.name, value, meta(f, "choices"))
        elif base is bool:
            if not isinstance(value, bool):
                raise checks.InputError(f"{f.name} must be True or False, got {value!r}", f.name)
        elif base is int:
            lower, upper, _, _ = f.metadata["range"]
            checks.integer(f.name, value, lower=lower, upper=upper)
        elif base is float:
            lower, upper, lower_open, upper_open = f.metadata["range"]
            checks.number(
                f.name,
                value,
                lower=lower,
                upper=upper,
                lower_open=lower_open,
                upper_open=upper_open,
            )


class Registry:
    """The components of one physical role by name (module docstring): ``role`` is the
    role's flat key (e.g. "viscosity"), ``protocol`` the members every component has. A
    component is registered with ``@REGISTRY.register`` where it is defined (in ehdfem or in
    a user's own module); its fields must carry setting metadata and keep their meaning
    under the same name in every component of the role (Barus's and Roelands's alpha)."""

    def __init__(self, role: str, protocol: type):
        self.role = role
        self.protocol = protocol
        self._classes: dict[str, type] = {}

    def register(self, cls: type) -> type:
        """Add the component class ``cls`` (a frozen dataclass with a unique ``name`` and the
        protocol's members); returns it (a decorator)."""
        name = getattr(cls, "name", None)
        if not (dataclasses.is_dataclass(cls) and cls.__dataclass_params__.frozen):
            raise TypeError(f"{cls.__name__}: a {self.role} component is a frozen dataclass")
        if not isinstance(name, str) or name in self._classes:
            raise TypeError(f"{cls.__name__}: a {self.role} needs a new name, got {name!r}")
        missing = [m for m in _members(self.protocol) if not hasattr(cls, m)]
        own = [f.name for f in dataclasses.fields(cls) if "help" not in f.metadata]
        if missing or own:
            raise TypeError(
                f"{cls.__name__}: {self.role} {name!r} lacks {', '.join(missing)} of "
                f"{self.protocol.__name__} or setting(...) metadata on {', '.join(own)}"
            )
        self._classes[name] = cls
        return cls

    def unregister(self, name: str) -> None:
        """Remove the component ``name`` (one registered for a while, e.g. by a test)."""
        del self._classes[self[name].name]

    def names(self) -> tuple[str, ...]:
        """The registered names, in the order of registration."""
        return tuple(self._classes)

    def __iter__(self):
        return iter(self._classes)

    def __contains__(self, name) -> bool:
        return name in self._classes

    def __getitem__(self, name: str) -> type:
        return self._classes[checks.choice(self.role, name, self.names())]

    def fields(self) -> list[dataclasses.Field]:
        """The fields of every registered component, each name once."""
        seen = {}
        for cls in self._classes.values():
            for f in dataclasses.fields(cls):
                seen.setdefault(f.name, (cls, f))
        return list(seen.values())

    def check(self, component, optional: bool = False) -> None:
        """Refuse a value that is not an instance of a registered component (nor None, when
        the role is ``optional``)."""
        if optional and component is None:
            return
        cls = self._classes.get(getattr(component, "name", None))
        if cls is None or not isinstance(component, cls):
            raise checks.InputError(
                f"{self.role} must be one of the registered {self.role} components "
                f"({', '.join(self.names())}), got {component!r}",
                self.role,
            )

    def build(self, name: str | None, values: dict, read: bool = False):
        """The component ``name`` with the given field ``values`` (flat keys; ``read``: from a
        study file or JSON, through each field's ``read``); None for ``name`` None (an optional
        role left to its default). A value for another component's field is warned of and left
        out: it cannot act with this one."""
        own = {} if name is None else {f.name: f for f in dataclasses.fields(self[name])}
        for key in self.foreign(name, values):
            warnings.warn(
                f"{key} has no effect with {self.role} = {name!r} (a setting of "
                f"{self.role} = {' or '.join(map(repr, self.owners(key)))})",
                stacklevel=4,
            )
        if name is None:
            return None
        cls = self[name]
        given = {k: v for k, v in values.items() if k in own}
        for key, f in own.items():
            if key not in given and f.default is dataclasses.MISSING:
                raise checks.InputError(f"{self.role} = {name!r} needs {key}", key)
            if read and key in given and f.metadata.get("read") is not None:
                given[key] = f.metadata["read"](given[key])
        return cls(**given)

    def of_inputs(self, name: str, values: dict):
        """The component ``name`` from the physical inputs' ``values`` (flat keys, scaled; the
        physical inputs hold the constants of every component of the role): its own fields from
        them. A constant of another component of the role cannot act with this one: refused,
        by its key, when it differs from its default (given on purpose), else left out."""
        own = {f.name for f in dataclasses.fields(self[name])}
        defaults = {f.name: f.default for _, f in self.fields()}
        for key in self.foreign(name, values):
            if values[key] != defaults[key]:
                owners = " or ".join(map(repr, self.owners(key)))
                raise checks.InputError(
                    f"{key} = {values[key]!r} acts only with {self.role} = {owners}: it cannot "
                    f"act with {self.role} = {name!r}",
                    key,
                )
        return self[name](**{k: v for k, v in values.items() if k in own})

    def foreign(self, name: str | None, values) -> list[str]:
        """The keys of ``values`` that are fields of other components of the role but not of
        the component ``name`` (None: of none): they cannot act with it."""
        own = set() if name is None else {f.name for f in dataclasses.fields(self[name])}
        return [k for k in values if k not in own and self.owners(k)]

    def owners(self, key: str) -> list[str]:
        """The names of the components that have the field ``key``."""
        return [
            n for n, c in self._classes.items() if key in {f.name for f in dataclasses.fields(c)}
        ]

    def flat(self, value, written: bool = False) -> dict:
        """The flat settings of the component ``value``: its role's name and its fields
        (``written``: for a study file or JSON, through each field's ``write``); the role None
        for None (an optional role left to its default)."""
        out = {self.role: None if value is None else value.name}
        for f in dataclasses.fields(value) if value is not None else ():
            item = getattr(value, f.name)
            out[f.name] = f.metadata["write"](item) if written and f.metadata["write"] else item
        return out


def _members(protocol) -> list[str]:
    """The members a Protocol declares (its methods, properties and annotations)."""
    names = set(getattr(protocol, "__annotations__", {}))
    names |= {k for k in vars(protocol) if not k.startswith("_")}
    return sorted(names)


def component(registry: Registry, default, *, help: str, default_text: str | None = None):
    """A field holding a component of ``registry``'s role (default: the instance ``default``,
    frozen; None: an optional role, whose None another input resolves, described by
    ``default_text``), with ``help``: what the role is."""
    metadata = {"help": help, "registry": registry, "default_text": default_text}
    return dataclasses.field(default=default, metadata=metadata)


def default_name(f: dataclasses.Field) -> str | None:
    """The name of the default component of the component field ``f`` (None: none)."""
    return None if f.default is None else f.default.name


def components(cls) -> list[tuple[dataclasses.Field, Registry]]:
    """The fields of the dataclass ``cls`` that hold components, with their registries."""
    return [
        (f, f.metadata["registry"]) for f in dataclasses.fields(cls) if "registry" in f.metadata
    ]


def flat_fields(cls) -> list[tuple[type, dataclasses.Field]]:
    """(owner, field) of each flat key of ``cls`` (:func:`flat_names`): its scalar fields, each
    component field (its role) and the fields of the registered components of that role."""
    out = [(cls, f) for f in described(cls)]
    for f, registry in components(cls):
        out += [(cls, f), *registry.fields()]
    seen = {}
    for owner, f in out:
        seen.setdefault(f.name, (owner, f))
    return list(seen.values())


def flat_names(cls) -> tuple[str, ...]:
    """The flat keys of ``cls``: its scalar fields, each component's role and the fields of
    every registered component of that role (asked when called: a component registered later
    is included)."""
    return tuple(f.name for _, f in flat_fields(cls))


def flat(instance, written: bool = False) -> dict:
    """The flat settings of the dataclass ``instance``: its scalar fields and, for each
    component, its role's name and its fields (``written``: for a study file or JSON)."""
    out = {}
    for f in dataclasses.fields(instance):
        value = getattr(instance, f.name)
        if "registry" in f.metadata:
            out.update(f.metadata["registry"].flat(value, written))
        elif _scalar(type(instance), f):
            write = f.metadata.get("write")
            out[f.name] = write(value) if written and write else value
    return out


def from_flat(cls, values: dict, read: bool = False):
    """An instance of ``cls`` from flat settings (:func:`flat_names`; ``read``: from a study
    file or JSON); each component is built from its role's name (its default's when not
    given) and its fields' keys. An unknown key is refused, naming the allowed ones."""
    names = flat_names(cls)
    unknown = sorted(set(values) - set(names))
    if unknown:
        raise checks.InputError(
            f"unknown input(s) {', '.join(unknown)}; allowed: {', '.join(names)}", unknown[0]
        )
    rest = dict(values)
    built = {}
    for f, registry in components(cls):
        keys = {g.name for _, g in registry.fields()}
        name = rest.pop(f.name, default_name(f))
        mine = {k: rest.pop(k) for k in list(rest) if k in keys}
        built[f.name] = registry.build(name, mine, read)
    for f in described(cls):
        if read and f.name in rest and f.metadata.get("read") is not None:
            rest[f.name] = f.metadata["read"](rest[f.name])
    return cls(**rest, **built)


def check_components(instance) -> None:
    """Refuse a component field of ``instance`` that holds no registered component."""
    for f, registry in components(type(instance)):
        registry.check(getattr(instance, f.name), optional=f.default is None)


def without_other_components(cls, values: dict) -> dict:
    """``values`` (flat settings of ``cls``) without the fields of the components not chosen:
    the earlier JSON format of the inputs wrote every constant of every law (alpha = 0 with the
    constant viscosity, P_cav with no cavitation model), which cannot act with the one chosen."""
    out = dict(values)
    for f, registry in components(cls):
        name = out.get(f.name, default_name(f))
        own = set() if name is None else {g.name for g in dataclasses.fields(registry[name])}
        for _, g in registry.fields():
            if g.name not in own:
                out.pop(g.name, None)
    return out
