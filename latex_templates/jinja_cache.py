"""Jinja's compiled templates and catalogue snippets kept in the build cache's folder
(``<cache>/jinja/``), so that a build does not parse and generate the same ~110 templates again
(≈ 0.5 s of CPU on the press, all on the build's critical path).

A template's compiled code depends only on its source, its name and the environment's syntax
options (delimiters, whitespace control, autoescape, extensions) — filters, globals and the
context are looked up when it runs — so the code is kept under a SHA-256 of those and of the Jinja
and Python versions (``marshal``'s format is Python's). The output is the same text whether the
code was compiled now or read back (``tests/speed/test_jinja_cache.py``). An unreadable entry is
compiled again; an unwritable folder is skipped.

Only a build that uses the cache (``reportgen build`` without ``--no-cache``, ``REPORTGEN_CACHE``
not ``off``) reads or writes it: :func:`active` sets the folder for the duration of the build.
Before it, every compilation looks in the package's own code compiled at install time
(:mod:`latex_templates.precompiled`), cache or not.
"""
from __future__ import annotations

import hashlib
import marshal
import os
import sys
import tempfile
from contextlib import contextmanager
from pathlib import Path
from typing import Any, Iterator

#: Newest compiled templates kept (a note uses ~110).
KEEP = 1000

_ROOT: Path | None = None          # the cache folder of the build running, None: no cache
_PRUNED: set[Path] = set()


@contextmanager
def active(root: Path | None) -> Iterator[None]:
    """Read and write compiled templates under ``root/jinja`` while open (None: neither)."""
    global _ROOT
    previous, _ROOT = _ROOT, root
    try:
        yield
    finally:
        _ROOT = previous


def _signature(env: Any) -> str:
    import jinja2

    return repr((jinja2.__version__, sys.version, sys.implementation.cache_tag,
                 env.block_start_string, env.block_end_string, env.variable_start_string,
                 env.variable_end_string, env.comment_start_string, env.comment_end_string,
                 env.line_statement_prefix, env.line_comment_prefix, env.trim_blocks, env.lstrip_blocks,
                 env.newline_sequence, env.keep_trailing_newline, env.optimized, env.is_async,
                 env.autoescape if isinstance(env.autoescape, bool) else id(env.autoescape),
                 env.finalize is not None, sorted(env.extensions)))


def code_key(env: Any, source: str, name: str | None, filename: str | None, defer_init: bool) -> str:
    """What Jinja's code of ``source`` depends on, as one SHA-256: the environment's syntax options
    and the versions (:func:`_signature`), the name, the file name, ``defer_init`` and the source."""
    return hashlib.sha256("\0".join((_signature(env), repr(name), repr(filename), repr(defer_init),
                                      source)).encode()).hexdigest()


def compile_fresh(env: Any, source: str, name: str | None, filename: str | None,
                  defer_init: bool = False) -> Any:
    """Jinja's own compilation of ``source`` (past :func:`use_cache`'s lookups)."""
    compile_now = getattr(env, "reportgen_compile", env.compile)
    return compile_now(source, name, filename, False, defer_init)


def use_cache(env: Any) -> Any:
    """Let ``env`` compile through the package's precompiled code (:mod:`.precompiled`) and, while a
    build has one :func:`active`, the cache; returns ``env``."""
    from . import precompiled

    compile_now = env.compile

    def compile(source: Any, name: str | None = None, filename: str | None = None, raw: bool = False,
                defer_init: bool = False) -> Any:
        root = _ROOT
        if raw or not isinstance(source, str):
            return compile_now(source, name, filename, raw, defer_init)
        key = code_key(env, source, name, filename, defer_init)
        code = precompiled.lookup(key)
        if code is not None:
            return code
        if root is None:
            return compile_now(source, name, filename, raw, defer_init)
        folder = root / "jinja"
        entry = folder / f"{key}.code"
        try:
            return marshal.loads(entry.read_bytes())
        except (OSError, EOFError, ValueError, TypeError):
            pass
        code = compile_now(source, name, filename, raw, defer_init)
        _store(folder, entry, code)
        return code

    env.reportgen_compile = compile_now
    env.compile = compile
    return env


def _store(folder: Path, entry: Path, code: Any) -> None:
    try:
        folder.mkdir(parents=True, exist_ok=True)
        fd, part = tempfile.mkstemp(dir=folder, prefix=".part-")
        with os.fdopen(fd, "wb") as f:
            f.write(marshal.dumps(code))
        os.replace(part, entry)
    except OSError:
        return
    if folder not in _PRUNED:          # once per process: the newest KEEP entries
        _PRUNED.add(folder)
        from reportgen.cache import _prune
        _prune(folder, KEEP)
