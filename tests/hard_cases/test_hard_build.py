"""No NaN or infinity reaches results.json, the note or a sheet: a full build (without running LaTeX)
of hard cases, every output file scanned for ``nan``/``inf`` as a word."""
from __future__ import annotations

import json
import math
import re
import sys
from pathlib import Path

import pytest

from reportgen.cli import main

sys.path.insert(0, str(Path(__file__).resolve().parent))
from test_hard_stages import four_bar, slotted_lever  # noqa: E402

NONFINITE = re.compile(r"(?<![\\A-Za-z])(nan|inf|infinity)(?![A-Za-z])", re.IGNORECASE)
GEARS_9 = '\n[gears]\nz1 = 9\nz2 = 18\nmodule = 5.0\nx1 = "auto"\nx2 = "auto"\n'


def _near_toggle() -> str:
    s, l, p = 0.1, 0.35, 0.25
    q = (s + l) / 0.999 - p            # s + l = 0.999·(p + q): μ_min ≈ 5°
    return four_bar(s, p, q, l) + GEARS_9


def _scan(out: Path) -> list[str]:
    bad = []
    for f in sorted(out.rglob("*")):
        if f.suffix not in (".tex", ".dxf", ".json"):
            continue
        for n, line in enumerate(f.read_text(encoding="utf-8", errors="replace").splitlines(), 1):
            if NONFINITE.search(line):
                bad.append(f"{f.name}:{n}: {line.strip()[:120]}")
    return bad


@pytest.mark.slow
@pytest.mark.parametrize("text", [
    _near_toggle(),
    slotted_lever(0.1, 0.101),
    slotted_lever(0.1, 0.1001),
], ids=["near-toggle+z9", "slotted-1.01r", "slotted-1.001r"])
def test_no_nan_or_inf_in_any_output(tmp_path, capsys, text):
    task = tmp_path / "task.toml"
    task.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    code = main(["build", str(task), "-o", str(out), "--quiet", "--no-pdf"])
    assert code == 0, capsys.readouterr().err
    assert (out / "report.tex").is_file() and list((out / "sheets").glob("*.dxf"))
    assert _scan(out) == []

    def finite(x):
        if isinstance(x, float):
            assert math.isfinite(x)
        elif isinstance(x, dict):
            for v in x.values():
                finite(v)
        elif isinstance(x, list):
            for v in x:
                finite(v)
    finite(json.loads((out / "results.json").read_text(encoding="utf-8")))


def test_the_scan_finds_what_it_looks_for(tmp_path):
    (tmp_path / "a.tex").write_text("x = nan\n\\infty is fine, so is information\n", encoding="utf-8")
    (tmp_path / "b.dxf").write_text("10\ninf\n20\n-INF\n", encoding="utf-8")
    assert len(_scan(tmp_path)) == 3
