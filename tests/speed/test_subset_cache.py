"""The build cache's font subsets (reportgen/commands/subset_cache.py): a figure saved with a
subset read back from the cache is the same PDF as one saved with fontTools run anew."""
from __future__ import annotations

import subprocess
import sys
import textwrap
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

SCRIPT = textwrap.dedent("""
    import io, sys
    from pathlib import Path
    import matplotlib
    matplotlib.use("pdf")
    matplotlib.rcParams["pdf.fonttype"] = 42
    import matplotlib.pyplot as plt
    from reportgen.commands import subset_cache
    from latex_templates.figures.saving import PDF_METADATA, remember_font_subsets

    class Cache:
        root = Path(sys.argv[1])
        code = "test"

    if sys.argv[2] == "cache":
        subset_cache.use(Cache())
    remember_font_subsets()
    fig, ax = plt.subplots()
    ax.set_title("Сила $F_{ур} = 7870,5$ Н, μ = 0,25")
    ax.plot([0, 1], [0, 2])
    out = io.BytesIO()
    fig.savefig(out, format="pdf", metadata=PDF_METADATA)
    sys.stdout.buffer.write(out.getvalue())
""")


def _save(folder: Path, mode: str) -> bytes:
    r = subprocess.run([sys.executable, "-c", SCRIPT, str(folder), mode], cwd=ROOT, capture_output=True,
                       timeout=300)
    assert r.returncode == 0, r.stderr.decode()[-2000:]
    return r.stdout


def test_a_subset_read_from_the_cache_writes_the_bytes_fonttools_writes(tmp_path):
    plain = _save(tmp_path / "none", "plain")
    first = _save(tmp_path / "kept", "cache")        # fontTools run, the subsets kept
    kept = sorted((tmp_path / "kept" / "subsets").iterdir())
    assert kept, "no subset kept"
    second = _save(tmp_path / "kept", "cache")       # every subset read back
    assert first == plain and second == plain
    assert sorted((tmp_path / "kept" / "subsets").iterdir()) == kept
