"""``reportgen bench [TASK] [--quick] [--out DIR] [--markdown FILE]``: tables of time against error
of every approximation of the project, a plot, and docs/performance.md (see reportgen.commands.benchmarks)."""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..errors import OptionError

ROOT = Path(__file__).resolve().parents[2]
DEFAULT_TASK = ROOT / "examples" / "press" / "task.toml"


def register(sub) -> None:
    p = sub.add_parser("bench", help="time against error of every approximation (benchmarks, not tests)",
                       description="Prints tables of time against error for every approximation of the "
                                   "project (each error against a converged reference in the same run), "
                                   "writes a plot and docs/performance.md.")
    p.add_argument("task", nargs="?", default=None,
                   help="the task file (default: examples/press/task.toml of the source tree)")
    p.add_argument("--quick", action="store_true",
                   help="a short run (few positions, no LaTeX, no sheets): checks that the command works")
    p.add_argument("--out", metavar="DIR", default=None,
                   help="folder for the plot performance.png (default: docs/ of the source tree; "
                        "with --quick, no plot unless given)")
    p.add_argument("--markdown", metavar="FILE", default=None,
                   help="write the tables as Markdown here (default: docs/performance.md of the source "
                        "tree; with --quick, none unless given)")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from .benchmarks import _stderr, markdown, run_bench, text

    task = Path(args.task) if args.task else DEFAULT_TASK
    if not task.is_file():
        raise OptionError("task", f"{task} is not a file",
                          "a task file (TOML); the default examples/press/task.toml exists only in a source tree")
    docs = ROOT / "docs"
    out = Path(args.out) if args.out else (None if args.quick else docs)
    md = Path(args.markdown) if args.markdown else (None if args.quick else docs / "performance.md")
    if out is not None and not out.is_dir() and not out.parent.is_dir():
        raise OptionError("--out", f"neither {out} nor its parent folder exists", "a folder that exists or can be made")
    if md is not None and not md.parent.is_dir() and md.parent != out:
        raise OptionError("--markdown", f"the folder {md.parent} does not exist", "a path in an existing folder")
    rep = run_bench(task, quick=args.quick, progress=_stderr)
    sys.stdout.write(text(rep))
    plot = None
    if out is not None:
        out.mkdir(exist_ok=True)
        plot = write_plot(rep, out / "performance.png")
        print(f"plot: {plot}")
    if md is not None:
        md.write_text(markdown(rep, plot, md), encoding="utf-8")
        print(f"tables: {md}")
    return 0


def write_plot(rep, path: Path) -> Path:
    """Error against positions and error against time for every position-count approximation."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 5), constrained_layout=True)
    floor = 1e-16
    for label, pts in rep.series.items():
        if not pts:
            continue
        n = [p[0] for p in pts]
        e = [max(p[1], floor) for p in pts]
        t = [p[2] * 1e3 for p in pts]
        ax1.loglog(n, e, "o-", label=label, ms=4)
        ax2.loglog(t, e, "o-", label=label, ms=4)
    ax1.set_xlabel("positions per cycle")
    ax1.set_ylabel("relative error against the reference")
    ax2.set_xlabel("time, ms")
    ax2.set_ylabel("relative error against the reference")
    for ax in (ax1, ax2):
        ax.grid(True, which="both", lw=0.3)
    ax1.legend(fontsize=7, loc="best")
    fig.suptitle(f"reportgen bench: {Path(rep.task).parent.name} (errors below 1e-16 drawn at 1e-16)")
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return path
