"""``reportgen build TASK -o OUT --watch``: build, then build again whenever the task file changes.

The task file is polled (its modification time and size, then its bytes' hash, every
``POLL_SECONDS``): a student editing a variant sees the note and the sheets follow. A bad task
prints its error and waits for the next change; Ctrl-C ends the watch with status 0.
"""
from __future__ import annotations

import argparse
import hashlib
import os
import time
from pathlib import Path
from typing import Callable

from ..errors import BuildError, ReportgenInputError

POLL_SECONDS = 0.5


def _state(path: str) -> tuple[int, int] | None:
    try:
        st = os.stat(path)
    except OSError:
        return None
    return st.st_mtime_ns, st.st_size


def _digest(path: str) -> str | None:
    try:
        return hashlib.sha256(Path(path).read_bytes()).hexdigest()
    except OSError:
        return None


def watch(args: argparse.Namespace, build: Callable[..., object], *, max_builds: int | None = None,
          poll: float = POLL_SECONDS) -> int:
    """Build ``args.task`` into ``args.out`` now and after each change (``max_builds`` ends the
    loop after that many builds: for tests)."""
    out = Path(args.out)
    builds = 0
    last_digest: str | None = None
    try:
        while True:
            state, digest = _state(args.task), _digest(args.task)
            if digest is not None and digest != last_digest:
                last_digest = digest
                t0 = time.perf_counter()
                try:
                    build(args.task, out, quiet=args.quiet, pdf=not args.no_pdf, sheets=not args.no_sheets,
                          latexmk=args.latexmk, cache=not args.no_cache)
                    print(f"built in {time.perf_counter() - t0:.1f} s → {out}/; watching {args.task} "
                          f"(Ctrl-C ends)", flush=True)
                except (ReportgenInputError, BuildError) as exc:
                    print(f"reportgen build: error: {exc}\nwatching {args.task} for the next change "
                          f"(Ctrl-C ends)", flush=True)
                builds += 1
                if max_builds is not None and builds >= max_builds:
                    return 0
            while _state(args.task) == state:
                time.sleep(poll)
    except KeyboardInterrupt:
        print("\nstopped watching", flush=True)
        return 0
