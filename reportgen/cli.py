"""Command line: ``reportgen build | solve | gear | planetary | bench``.

Each sub-command lives in ``reportgen/commands/<name>.py`` and provides ``register(subparsers)``,
which adds its parser and sets ``func(args) -> int``. The command modules are presentation: they may
import ``latex_templates`` and ``drawings``; the solvers never import them.

Exit status (RESULTS_FORMAT.md): 0 success, 2 bad input (a ``ReportgenInputError``: the message names
the key or option), 1 a failed stage (any other ``ReportgenError``, or a bug: one line, never a
traceback unless ``REPORTGEN_DEBUG`` is set).
"""
from __future__ import annotations

import argparse
import importlib
import os
import sys
import traceback

from . import __version__
from .errors import ReportgenError, ReportgenInputError

# Sub-command modules, in the order `reportgen --help` lists them.
DEBUG_ENV = "REPORTGEN_DEBUG"  # set to print the traceback of an internal error

#: The BLAS libraries' thread pools, one thread unless the user set a number: reportgen's linear algebra
#: is small (many 2×2…6×6 systems), so a second thread never helps, and OpenBLAS's worker thread
#: spins on a free processor after each call — CPU taken from the build's other processes (the
#: sheets', the figures', xelatex) on a 2-processor machine, and ≈ 10 % of `reportgen solve`'s
#: CPU (docs/build.md «BLAS threads»). Read by the library when numpy is first imported.
BLAS_THREADS_ENV = ("OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")


def single_threaded_blas() -> None:
    """Ask the BLAS library for one thread (:data:`BLAS_THREADS_ENV`), unless the user set it."""
    for name in BLAS_THREADS_ENV:
        os.environ.setdefault(name, "1")


COMMANDS: tuple[str, ...] = ("build", "solve", "new", "batch", "check", "gear", "planetary", "crane", "bench")


def make_parser(argv: list[str] | None = None) -> argparse.ArgumentParser:
    """The parser with every command; with ``argv`` naming one, with that one only (the others'
    modules are not imported: ``reportgen solve`` starts in a fraction of the time)."""
    first = argv[0] if argv else None
    names = (first,) if first in COMMANDS else COMMANDS
    parser = argparse.ArgumentParser(
        prog="reportgen",
        description="ТММ course project: explanatory note (PDF) and drawing sheets (DXF) from a task file.",
    )
    parser.add_argument("--version", action="version", version=f"reportgen {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    for name in names:
        try:
            module = importlib.import_module(f"reportgen.commands.{name}")
        except ModuleNotFoundError as exc:
            if exc.name == f"reportgen.commands.{name}":
                continue  # a command not written yet is simply not offered
            raise
        module.register(sub)
    return parser


def main(argv: list[str] | None = None) -> int:
    if "numpy" not in sys.modules:   # the command modules import numpy: one BLAS thread first
        single_threaded_blas()
    parser = make_parser(sys.argv[1:] if argv is None else argv)
    args = parser.parse_args(argv)
    if not getattr(args, "func", None):
        parser.print_help()
        return 2
    try:
        return int(args.func(args) or 0)
    except ReportgenInputError as exc:
        print(f"reportgen {args.command}: error: {exc}", file=sys.stderr)
        return 2
    except ReportgenError as exc:  # BuildError, InternalError, ComputationError …: a stage failed
        print(f"reportgen {args.command}: error: {exc}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        return 130
    except Exception as exc:  # a bug: one line, the traceback only on request
        if os.environ.get(DEBUG_ENV):
            traceback.print_exc()
        print(f"reportgen {args.command}: internal error: {type(exc).__name__}: {exc} (please report it "
              f"with the task file; set {DEBUG_ENV}=1 to see where it happened)", file=sys.stderr)
        return 1


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
