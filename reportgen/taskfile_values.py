"""Typed readers of TOML values for the task loader (``reportgen.taskfile``).

Every reader takes the raw value and its TOML path and either returns a clean Python value or raises
:class:`~reportgen.errors.TaskError` naming the path and what would be valid. Readers are small
objects (``Spec``) so that the text of "what would be valid" is built once, from the same limits that
are checked, and can be reused for a missing key.

Paths: table keys are joined with dots, array elements get a 0-based index in brackets
(``mechanism.link[0].points[1]``); a key that is not a TOML bare key is quoted (``points."A 1"``).
"""
from __future__ import annotations

import difflib
import json
import math
import re
from typing import Any, Iterable, Mapping, Sequence

from .errors import TaskError, UnknownKeyError

_BARE_KEY = re.compile(r"[A-Za-z0-9_-]+")


# --------------------------------------------------------------------------------------------- paths
def key_repr(key: str) -> str:
    """A key as written in a TOML path: bare if it can be, else double-quoted."""
    return key if _BARE_KEY.fullmatch(key) else json.dumps(key, ensure_ascii=False)


def join(path: str, key: str) -> str:
    """``path.key`` (just ``key`` at the top level)."""
    k = key_repr(key)
    return f"{path}.{k}" if path else k


def index(path: str, i: int) -> str:
    """``path[i]`` with a 0-based index."""
    return f"{path}[{i}]"


# ----------------------------------------------------------------------------------- value display
def show(value: Any) -> str:
    """A short description of a raw value for an error message: its TOML type and its text."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        text = str(value) if abs(value) < 10**30 else f"a {len(str(abs(value)))}-digit integer"
        return text
    if isinstance(value, float):
        return f"the float {value!r}"
    if isinstance(value, str):
        text = value if len(value) <= 40 else value[:37] + "..."
        return f"the string {json.dumps(text, ensure_ascii=False)}"
    if isinstance(value, dict):
        return "a table"
    if isinstance(value, (list, tuple)):
        return "an array"
    return f"a {type(value).__name__} value"


def fmt(x: float) -> str:
    """A number for a message: shortest round-trip form, integers without '.0'."""
    if isinstance(x, float) and x.is_integer() and abs(x) < 1e15:
        return str(int(x))
    return repr(x)


def suggest(word: str, candidates: Iterable[str]) -> str | None:
    """The nearest candidate to ``word`` (difflib; case-insensitive), or None."""
    cands = [c for c in candidates if isinstance(c, str)]
    lowered = {c.lower(): c for c in cands}
    hit = difflib.get_close_matches(word.lower(), list(lowered), n=1, cutoff=0.6)
    if hit:
        return lowered[hit[0]]
    if len(word) >= 2:  # an abbreviation: "max" for "max-load"
        starts = [c for low, c in lowered.items() if low.startswith(word.lower())]
        if len(starts) == 1:
            return starts[0]
    return None


def check_keys(table: Mapping, path: str, known: Sequence[str]) -> None:
    """Refuse any key of ``table`` not in ``known``, suggesting the nearest known key."""
    for key in table:
        if not isinstance(key, str):
            raise TaskError(path, f"has a key that is not a string ({show(key)})", "string keys")
        if key not in known:
            raise UnknownKeyError(join(path, key), key, list(known), suggest(key, known))


# ------------------------------------------------------------------------------------------- specs
class Spec:
    """A reader of one value: ``read(value, path)``; ``expected`` says what is valid."""
    expected: str = "a value"

    def read(self, value: Any, path: str) -> Any:  # pragma: no cover - abstract
        raise NotImplementedError

    def fail(self, value: Any, path: str, extra: str = "") -> TaskError:
        return TaskError(path, f"got {show(value)}{extra}", self.expected)

    def schema(self) -> dict[str, Any]:
        """The JSON Schema of the values this spec accepts (``reportgen.taskspec`` builds on it)."""
        return {}

    def type_name(self) -> str:
        """The TOML type in words, for the generated reference (``docs/task-format.md``)."""
        return "any"


class Str(Spec):
    """Any string (optionally non-empty)."""

    def __init__(self, nonempty: bool = False) -> None:
        self.nonempty = nonempty
        self.expected = "a non-empty string" if nonempty else "a string"

    def read(self, value: Any, path: str) -> str:
        if not isinstance(value, str) or (self.nonempty and not value.strip()):
            raise self.fail(value, path)
        return value

    def schema(self) -> dict[str, Any]:
        return {"type": "string", "pattern": r"\S"} if self.nonempty else {"type": "string"}

    def type_name(self) -> str:
        return "string"


class Word(Spec):
    """One of a fixed set of words; a near miss gets a suggestion."""

    def __init__(self, *words: str) -> None:
        self.words = tuple(words)
        self.expected = " | ".join(f'"{w}"' for w in words)
        if len(words) > 1:
            self.expected = "one of " + self.expected

    def read(self, value: Any, path: str) -> str:
        if isinstance(value, str) and value in self.words:
            return value
        extra = ""
        if isinstance(value, str):
            near = suggest(value, self.words)
            if near:
                extra = f"; did you mean \"{near}\"?"
        raise self.fail(value, path, extra)

    def schema(self) -> dict[str, Any]:
        return {"enum": list(self.words)}

    def type_name(self) -> str:
        return "string"


def _range_text(gt: float | None, ge: float | None, lt: float | None, le: float | None,
                nonzero: bool) -> str:
    lo = (f"({fmt(gt)}" if gt is not None else f"[{fmt(ge)}" if ge is not None else None)
    hi = (f"{fmt(lt)})" if lt is not None else f"{fmt(le)}]" if le is not None else None)
    if lo and hi:
        text = f" in {lo}, {hi}"
    elif lo:
        text = f" > {fmt(gt)}" if gt is not None else f" ≥ {fmt(ge or 0.0)}"
    elif hi:
        text = f" < {fmt(lt)}" if lt is not None else f" ≤ {fmt(le or 0.0)}"
    else:
        text = ""
    if nonzero:
        text += (" and " if text else " ") + "≠ 0"
    return text


class Number(Spec):
    """A finite real number (TOML integer or float; booleans are not numbers), within limits."""

    def __init__(self, *, gt: float | None = None, ge: float | None = None, lt: float | None = None,
                 le: float | None = None, nonzero: bool = False, unit: str = "") -> None:
        self.gt, self.ge, self.lt, self.le, self.nonzero = gt, ge, lt, le, nonzero
        self.unit = unit
        self.expected = "a number" + _range_text(gt, ge, lt, le, nonzero)
        if unit:
            self.expected += f", in {unit}"

    def read(self, value: Any, path: str) -> float:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self.fail(value, path)
        try:
            x = float(value)
        except OverflowError:
            raise self.fail(value, path) from None
        if not math.isfinite(x):
            raise self.fail(value, path)
        if ((self.gt is not None and not x > self.gt) or (self.ge is not None and not x >= self.ge)
                or (self.lt is not None and not x < self.lt) or (self.le is not None and not x <= self.le)
                or (self.nonzero and x == 0.0)):
            raise self.fail(value, path)
        return x

    def schema(self) -> dict[str, Any]:
        out: dict[str, Any] = {"type": "number"}
        for key, limit in (("exclusiveMinimum", self.gt), ("minimum", self.ge),
                           ("exclusiveMaximum", self.lt), ("maximum", self.le)):
            if limit is not None:
                out[key] = limit
        if self.nonzero:
            out["not"] = {"const": 0}
        return out

    def type_name(self) -> str:
        return "number"


class Int(Spec):
    """A TOML integer (not a float, not a boolean) within limits."""

    def __init__(self, *, ge: int | None = None, le: int | None = None, what: str = "an integer") -> None:
        self.ge, self.le = ge, le
        if ge is not None and le is not None:
            self.expected = f"{what} {ge}..{le}"
        else:
            self.expected = what + _range_text(None, ge, None, le, False)

    def read(self, value: Any, path: str) -> int:
        if isinstance(value, bool) or not isinstance(value, int):
            raise self.fail(value, path)
        if (self.ge is not None and value < self.ge) or (self.le is not None and value > self.le):
            raise self.fail(value, path)
        return int(value)

    def schema(self) -> dict[str, Any]:
        out: dict[str, Any] = {"type": "integer"}
        if self.ge is not None:
            out["minimum"] = self.ge
        if self.le is not None:
            out["maximum"] = self.le
        return out

    def type_name(self) -> str:
        return "integer"


class Bool(Spec):
    expected = "true or false"

    def read(self, value: Any, path: str) -> bool:
        if not isinstance(value, bool):
            raise self.fail(value, path)
        return value

    def schema(self) -> dict[str, Any]:
        return {"type": "boolean"}

    def type_name(self) -> str:
        return "boolean"


class OneOf(Spec):
    """The first of several specs that accepts the value (e.g. ``"auto"`` or a number > 1)."""

    def __init__(self, *specs: Spec) -> None:
        self.specs = specs
        self.expected = " or ".join(s.expected for s in specs)

    def read(self, value: Any, path: str) -> Any:
        for spec in self.specs:
            try:
                return spec.read(value, path)
            except TaskError:
                continue
        extra = ""
        if isinstance(value, str):
            words = [w for s in self.specs if isinstance(s, Word) for w in s.words]
            near = suggest(value, words)
            if near:
                extra = f"; did you mean \"{near}\"?"
        raise self.fail(value, path, extra)

    def schema(self) -> dict[str, Any]:
        return {"anyOf": [s.schema() for s in self.specs]}

    def type_name(self) -> str:
        return " or ".join(dict.fromkeys(s.type_name() for s in self.specs))


class Array(Spec):
    """A TOML array of values read by ``item``, with a length between ``min_len`` and ``max_len``."""

    def __init__(self, item: Spec, min_len: int = 0, max_len: int | None = None, what: str = "") -> None:
        self.item, self.min_len, self.max_len = item, min_len, max_len
        if what:
            self.expected = what
        elif max_len is not None and max_len == min_len:
            self.expected = f"an array of {min_len} × {item.expected}"
        elif max_len is not None:
            self.expected = f"an array of {min_len} to {max_len} × {item.expected}"
        elif min_len:
            self.expected = f"an array of at least {min_len} × {item.expected}"
        else:
            self.expected = f"an array of {item.expected}"

    def read(self, value: Any, path: str) -> tuple:
        if not isinstance(value, list):
            raise self.fail(value, path)
        n = len(value)
        if n < self.min_len or (self.max_len is not None and n > self.max_len):
            raise TaskError(path, f"has {n} element{'s' if n != 1 else ''}", self.expected)
        return tuple(self.item.read(v, index(path, i)) for i, v in enumerate(value))

    def schema(self) -> dict[str, Any]:
        out: dict[str, Any] = {"type": "array", "items": self.item.schema()}
        if self.min_len:
            out["minItems"] = self.min_len
        if self.max_len is not None:
            out["maxItems"] = self.max_len
        return out

    def type_name(self) -> str:
        return f"array of {self.item.type_name()}"


class NameMap(Spec):
    """A TOML table of free names → values read by ``item`` (at least ``min_len`` entries)."""

    def __init__(self, item: Spec, min_len: int = 0, what: str = "") -> None:
        self.item, self.min_len = item, min_len
        self.expected = what or f"a table of names → {item.expected}"

    def read(self, value: Any, path: str) -> dict[str, Any]:
        if not isinstance(value, dict):
            raise self.fail(value, path)
        if len(value) < self.min_len:
            raise TaskError(path, "is empty", self.expected)
        out: dict[str, Any] = {}
        for name, v in value.items():
            if not isinstance(name, str) or not name.strip():
                raise TaskError(path, "has an empty name", "non-empty names")
            out[name] = self.item.read(v, join(path, name))
        return out

    def schema(self) -> dict[str, Any]:
        out: dict[str, Any] = {"type": "object", "propertyNames": {"pattern": r"\S"},
                               "additionalProperties": self.item.schema()}
        if self.min_len:
            out["minProperties"] = self.min_len
        return out

    def type_name(self) -> str:
        return f"table of {self.item.type_name()}"


def vec2(unit: str = "", limit: float | None = None) -> Array:
    """A spec for ``[x, y]``: two finite numbers (with |x|, |y| ≤ limit if given)."""
    item = Number(ge=-limit, le=limit, unit=unit) if limit is not None else Number(unit=unit)
    what = f"[x, y]: two numbers{f' in {unit}' if unit else ''}"
    if limit is not None:
        what += f" within ±{fmt(limit)}"
    return Array(item, 2, 2, what=what)


# ------------------------------------------------------------------------------------------- tables
class _Required:
    """The default of a key that must be given."""

    def __repr__(self) -> str:
        return "REQUIRED"


#: ``Table.get(key, spec, REQUIRED)``: a missing key is an error.
REQUIRED: Any = _Required()


class Table:
    """A TOML table under validation: its data, its path and the keys it may have."""

    def __init__(self, value: Any, path: str, known: Sequence[str], what: str = "a table") -> None:
        if not isinstance(value, dict):
            raise TaskError(path, f"got {show(value)}", what)
        check_keys(value, path, known)
        self.data: dict = value
        self.path = path

    def at(self, key: str) -> str:
        """The TOML path of ``key`` in this table."""
        return join(self.path, key)

    def __contains__(self, key: str) -> bool:
        return key in self.data

    def get(self, key: str, spec: Spec, default: Any = REQUIRED) -> Any:
        """Read ``key`` with ``spec``; a missing key gives ``default`` or, if none, an error."""
        if key not in self.data:
            if default is REQUIRED:
                raise TaskError(self.at(key), "is missing", spec.expected)
            return default
        return spec.read(self.data[key], self.at(key))

    def raw(self, key: str, default: Any = None) -> Any:
        return self.data.get(key, default)


def array_of_tables(value: Any, path: str, header: str) -> list:
    """A TOML array of tables (``[[header]]``); a single table is refused with a hint."""
    if isinstance(value, dict):
        raise TaskError(path, "got a single table", f"an array of tables: write [[{header}]] for each entry")
    if not isinstance(value, list):
        raise TaskError(path, f"got {show(value)}", f"an array of tables ([[{header}]])")
    return value
