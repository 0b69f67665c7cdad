"""Keyword arguments to the library's NAME=VALUE options and the CLI's flags.

The values are only formatted here: the library's one option parser
(plugin/lib/options.cpp) validates them, so that a bad value gets the CLI's
message. Shared by every front end of the package (mcmd.fill, mcmd.fill_file).
"""
from __future__ import annotations

import numbers
import operator
import os
from typing import Any, Iterable, Mapping

# Keyword spellings that are not the option's own name.
_ALIASES = {"THREADS": "NUM_THREADS"}


def format_value(value: Any) -> str:
    """A value as the option parser reads it; floats round-trip exactly."""
    if isinstance(value, bool) or isinstance(value, str):
        return str(value)
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        return repr(float(value))
    return str(value)


def fill_options(options: Mapping[str, Any], named: Mapping[str, tuple[str, Any]] | None = None,
                 caller: str = "fill") -> list[str]:
    """NAME=VALUE strings: `named` (option NAME -> (keyword, value), None =
    the library's default) then `options` (keyword names in any case, None
    left out). An option given twice is a TypeError."""
    given = {name: keyword for name, (keyword, _) in (named or {}).items()}
    values = [(name, value) for name, (_, value) in (named or {}).items()]
    for key, value in options.items():
        name = _ALIASES.get(key.upper(), key.upper())
        if name in given:
            raise TypeError(f"{caller}() got option {name} twice: as {given[name]}= and as {key}=")
        given[name] = key
        values.append((key if name == key.upper() else name, value))  # as spelt, for messages
    return [f"{name}={format_value(value)}" for name, value in values if value is not None]


def band_list(bands: int | Iterable[int] | None) -> list[int]:
    """Band numbers (1-based) from an int, an iterable of ints or None."""
    if bands is None:
        return []
    if isinstance(bands, numbers.Integral):
        return [int(bands)]
    return [operator.index(b) for b in bands]


def creation_option_list(creation_options: Mapping[str, Any] | Iterable[str] | str | None) -> list[str]:
    """Driver creation options as NAME=VALUE strings, from a mapping
    (True/False become YES/NO), an iterable of NAME=VALUE strings, or one."""
    if creation_options is None:
        return []
    if isinstance(creation_options, str):
        return [creation_options]
    if isinstance(creation_options, Mapping):
        return [f"{k}={_yes_no(v)}" for k, v in creation_options.items()]
    return [str(co) for co in creation_options]


def _yes_no(value: Any) -> str:
    if isinstance(value, bool):
        return "YES" if value else "NO"
    return format_value(value)


def path(p: str | os.PathLike[str] | bytes, what: str) -> str:
    """A file name as a str; an empty one is a ValueError."""
    name = os.fsdecode(os.fspath(p))
    if not name:
        raise ValueError(f"{what} is an empty file name")
    return name
