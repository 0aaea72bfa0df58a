"""`reportgen bench --quick` works end to end (a smoke test of the command; speed is never tested)."""
from __future__ import annotations

from reportgen.cli import main


def test_bench_quick_writes_tables_and_plot(tmp_path, capsys):
    md = tmp_path / "perf.md"
    code = main(["bench", "--quick", "--out", str(tmp_path), "--markdown", str(md)])
    out = capsys.readouterr().out
    assert code == 0
    assert (tmp_path / "performance.png").stat().st_size > 10_000
    text = md.read_text(encoding="utf-8")
    for title in ("Kinematic diagrams", "Work of the resistance", "Flywheel J", "Graphical replicas",
                  "Planetary search", "The stages of", "The same four-bar"):
        assert title in out and f"### {title}" in text
    # every Markdown table row has as many cells as its header (pipes in cells are escaped)
    for block in text.split("### ")[1:]:
        rows = [r for r in block.splitlines() if r.startswith("|")]
        cells = {len(r.replace("\\|", "").split("|")) for r in rows}
        assert len(cells) <= 1, block[:200]
    assert "nan" not in text.lower().replace("nanos", "")
