"""Tables of a benchmark run: text for the terminal and Markdown for docs/performance.md."""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field


@dataclass
class Table:
    """One table: ``rows`` are already formatted strings; ``notes`` are printed under it."""
    key: str
    title: str
    headers: list[str]
    rows: list[list[str]] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)

    def add(self, *cells) -> None:
        self.rows.append([str(c) for c in cells])

    def text(self) -> str:
        widths = [max(len(h), *(len(r[i]) for r in self.rows)) if self.rows else len(h)
                  for i, h in enumerate(self.headers)]
        fmt = "  ".join(f"{{:<{w}}}" if i == 0 else f"{{:>{w}}}" for i, w in enumerate(widths))
        out = [self.title, fmt.format(*self.headers), "  ".join("-" * w for w in widths)]
        out += [fmt.format(*r) for r in self.rows]
        out += [f"  {n}" for n in self.notes]
        return "\n".join(out) + "\n"

    def markdown(self) -> str:
        out = [f"### {self.title}", "", "| " + " | ".join(h.replace("|", "\\|") for h in self.headers) + " |",
               "|" + "|".join("---" if i == 0 else "---:" for i in range(len(self.headers))) + "|"]
        out += ["| " + " | ".join(c.replace("|", "\\|") for c in r) + " |" for r in self.rows]
        if self.notes:
            out.append("")
            out += [f"- {n}" for n in self.notes]
        return "\n".join(out) + "\n"


def best_time(fn, repeat: int = 3):
    """(shortest wall time of ``repeat`` calls, s; the last result)."""
    best, out = math.inf, None
    for _ in range(max(1, repeat)):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


def ms(t: float) -> str:
    return f"{t * 1e3:.2f}" if t < 0.1 else f"{t * 1e3:.0f}"


def sec(t: float) -> str:
    return f"{t:.2f}"


def rel(x: float) -> str:
    """A relative error as a number with its exponent (1.2e-05) or 0."""
    if x == 0:
        return "0"
    if not math.isfinite(x):
        return "—"
    return f"{x:.1e}"


def pct(x: float, nd: int = 2) -> str:
    if not math.isfinite(x):
        return "—"
    return f"{100 * x:.{nd}f} %"
