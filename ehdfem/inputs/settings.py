"""Field metadata of the input dataclasses: one home for each setting's help text, unit or
scale, default and allowed values.

``setting(...)`` declares a dataclass field with that metadata; :func:`validate` checks an
instance against it (through :mod:`ehdfem.checks`, so a bad value names the field and
its allowed range), and the command line (:mod:`ehdfem.cli.arguments`) builds its options
from it: a new field appears there with its help, unit and default without further edits.
"""

from __future__ import annotations

import dataclasses
import functools
from typing import get_type_hints

from .. import checks


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
):
    """A dataclass field with metadata: ``help`` (what it is in the physics), ``unit`` (SI
    unit or scale, e.g. "Pa" or "by x0"), ``choices`` (allowed strings) or the range
    [lower, upper] (open ends with ``lower_open``/``upper_open``), ``flag``: its command-line
    name when it differs from the field's, ``default_text``: how to show the default."""
    metadata = {
        "help": help,
        "unit": unit,
        "choices": choices,
        "range": (lower, upper, lower_open, upper_open),
        "flag": flag,
        "default_text": default_text,
        "checked": checked,
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
    if "help" in f.metadata:
        return f.metadata[key]
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
    when the annotation says ``| None``)."""
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
    """The default of field ``f`` as text ("required" when there is none)."""
    if f.metadata.get("default_text") is not None:
        return f.metadata["default_text"]
    if f.default is dataclasses.MISSING:
        return "required"
    if f.default is None:
        return "none"
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
        if f.metadata["choices"] is not None:
            checks.choice(f.name, value, f.metadata["choices"])
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
