"""Import a module that may not exist yet (a sheet or a note part still to be written)."""
from __future__ import annotations

import importlib
from types import ModuleType

__all__ = ["optional_module"]


def optional_module(name: str) -> ModuleType | None:
    """The module ``name``, or None if that module itself is missing (an import error inside it is
    raised, so a broken module is never mistaken for an absent one)."""
    try:
        return importlib.import_module(name)
    except ModuleNotFoundError as exc:
        if exc.name == name:
            return None
        raise
