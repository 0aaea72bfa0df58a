"""The solvers are pure: nothing in reportgen/ but the command line imports the presentation
(latex_templates, drawings) or plotting (matplotlib)."""
from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1] / "reportgen"
FORBIDDEN = ("latex_templates", "drawings", "matplotlib")


def _imports(path: Path) -> set[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    names: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.update(a.name.split(".")[0] for a in node.names)
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            names.add(node.module.split(".")[0])
    return names


def test_solvers_import_no_presentation():
    offenders = []
    for path in sorted(ROOT.rglob("*.py")):
        rel = path.relative_to(ROOT).as_posix()
        if rel == "cli.py" or rel.startswith("commands/") or rel.startswith("bench/"):
            continue
        bad = _imports(path) & set(FORBIDDEN)
        if bad:
            offenders.append(f"{rel}: {sorted(bad)}")
    assert not offenders, offenders


def test_the_check_sees_imports():
    """The scanner finds a forbidden import when there is one (so the test above can fail)."""
    import tempfile
    with tempfile.TemporaryDirectory() as d:
        p = Path(d) / "x.py"
        p.write_text("import numpy\nfrom drawings.sheet import Sheet\n", encoding="utf-8")
        assert "drawings" in _imports(p)
