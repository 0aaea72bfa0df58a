"""The package's Jinja code compiled when it is installed, as Python's own bytecode is.

Compiling the note's templates and the catalogues' Jinja snippets (~15 templates and ~100 snippets
on the press, most of the snippets several kB) took ≈ 0.3 s of a cold build's CPU, all of it on the
build's critical path (the note's sections). The code Jinja makes of a source depends only on the
source, its name and file name and the environment's syntax options (:mod:`.jinja_cache` keys it
so), so it can be made once when the package is installed: ``python -m latex_templates.precompiled``
(``make venv`` and ``make bench`` run it, with ``compileall`` for the Python modules) compiles every
template under ``templates/`` and every snippet of every language's catalogue into
:data:`STORE`, beside this file. A build looks a source up there first
(:func:`latex_templates.jinja_cache.use_cache`) and compiles whatever is not there — a template
or catalogue edited since, another Jinja or Python version: their keys differ — as before. The
code is the same either way, so the note is the same text (``tests/speed/test_jinja_cache.py``).

The store is not the build cache: ``--no-cache`` does not turn it off, as it does not turn off
Python's ``__pycache__``; it is written only by the command above, never by a build, and a store
that cannot be read is ignored.
"""
from __future__ import annotations

import marshal
import os
import sys
import tempfile
from pathlib import Path
from typing import Any, Iterator

#: The compiled code of the package's templates and snippets: marshal of {key: marshal(code)}.
STORE = Path(__file__).with_name("_precompiled_templates.marshal")
#: Read the store (tests turn it off to count compilations).
enabled = True
_LOADED: dict[str, bytes] | None = None


def lookup(key: str) -> Any:
    """The code kept under ``key`` (:func:`latex_templates.jinja_cache.code_key`), else None."""
    global _LOADED
    if not enabled:
        return None
    if _LOADED is None:
        try:
            data = marshal.loads(STORE.read_bytes())
            _LOADED = data if isinstance(data, dict) else {}
        except (OSError, EOFError, ValueError, TypeError):
            _LOADED = {}
    found = _LOADED.get(key)
    if found is None:
        return None
    try:
        return marshal.loads(found)
    except (EOFError, ValueError, TypeError):
        return None


def _snippets(value: Any) -> Iterator[str]:
    from .render import _SNIPPET_MARKS

    if isinstance(value, str):
        if any(mark in value for mark in _SNIPPET_MARKS):
            yield value
    elif isinstance(value, dict):
        for v in value.values():
            yield from _snippets(v)
    elif isinstance(value, (list, tuple)):
        for v in value:
            yield from _snippets(v)


def write(store: Path = STORE) -> int:
    """Compile every template of the package and every snippet of every catalogue into ``store``
    (written whole, then renamed into place); returns the number of sources compiled."""
    global _LOADED
    from . import jinja_cache
    from .render import LANGUAGES, _load_strings, make_environment

    env = make_environment()
    codes: dict[str, bytes] = {}

    def add(source: str, name: str | None, filename: str | None) -> None:
        key = jinja_cache.code_key(env, source, name, filename, False)
        if key not in codes:
            codes[key] = marshal.dumps(jinja_cache.compile_fresh(env, source, name, filename))

    loader = env.loader
    assert loader is not None
    for name in env.list_templates():
        source, filename, _ = loader.get_source(env, name)
        add(source, name, filename)
    for language in LANGUAGES:
        for snippet in _snippets(_load_strings(language)):
            add(snippet, None, None)
    fd, part = tempfile.mkstemp(dir=store.parent, prefix=f".{store.name}.")
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(marshal.dumps(codes))
        os.chmod(part, 0o644)                  # read by whoever runs the package, as its modules are
        os.replace(part, store)
    except BaseException:
        if os.path.exists(part):
            os.unlink(part)
        raise
    _LOADED = None
    return len(codes)


if __name__ == "__main__":       # pragma: no cover - run by make
    count = write()
    print(f"latex_templates: {count} templates and snippets compiled into {STORE.name}", file=sys.stderr)
