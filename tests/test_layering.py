"""The layers (docs/architecture.md), checked on every import of every module — absolute and
relative, at module level and inside functions, no exemptions:

- the core (``reportgen`` but its command layer: task, solvers, stages, scenes, results) imports
  no presentation (``latex_templates``, ``drawings``) and no plotting or DXF library
  (``matplotlib``, ``ezdxf``), and never the command layer;
- the note (``latex_templates``) and the sheets (``drawings``) import the core, never each other;
- only the command layer (``reportgen/commands``, ``reportgen/cli.py``, ``reportgen/__main__.py``)
  imports both."""
from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
COMMAND_LAYER = ("reportgen/commands/", "reportgen/cli.py", "reportgen/__main__.py")


def _resolve(path: Path, node: ast.ImportFrom) -> str:
    """The absolute dotted name of a ``from … import`` (relative ones resolved against ``path``)."""
    if node.level == 0:
        return node.module or ""
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    package = parts[:-1]                  # a module's package; an __init__'s package is its folder
    base = package[:len(package) - (node.level - 1)]
    return ".".join(base + ([node.module] if node.module else []))


def imports(path: Path) -> set[str]:
    """Every module name ``path`` imports (absolute, dotted; for ``from x import y`` both ``x`` and
    ``x.y``, since y may be a module)."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    names: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.update(a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom):
            mod = _resolve(path, node)
            names.add(mod)
            names.update(f"{mod}.{a.name}" for a in node.names)
    return names


def _top(names: set[str]) -> set[str]:
    return {n.split(".")[0] for n in names if n}


def _files(package: str) -> list[Path]:
    return sorted((ROOT / package).rglob("*.py"))


def _rel(path: Path) -> str:
    return path.relative_to(ROOT).as_posix()


def test_core_imports_no_presentation():
    offenders = []
    for path in _files("reportgen"):
        rel = _rel(path)
        if rel.startswith(COMMAND_LAYER):
            continue
        names = imports(path)
        bad = _top(names) & {"latex_templates", "drawings", "matplotlib", "ezdxf"}
        bad |= {n for n in names if n.startswith("reportgen.commands") or n == "reportgen.cli"}
        if bad:
            offenders.append(f"{rel}: {sorted(bad)}")
    assert not offenders, offenders


@pytest.mark.parametrize("package, other", [("latex_templates", "drawings"), ("drawings", "latex_templates")])
def test_presentation_packages_do_not_import_each_other(package, other):
    offenders = []
    for path in _files(package):
        names = imports(path)
        bad = {n for n in names if n.split(".")[0] == other}
        bad |= {n for n in names if n.startswith("reportgen.commands") or n == "reportgen.cli"}
        if bad:
            offenders.append(f"{_rel(path)}: {sorted(bad)}")
    assert not offenders, offenders


def test_the_scanner_sees_every_kind_of_import():
    """Relative imports resolve, imports inside functions count: the tests above can fail."""
    pkg = ROOT / "reportgen" / "kinematics"
    fake = pkg / "_layering_probe.py"
    text = ("import numpy\n"
            "from ..commands import build\n"
            "def f():\n    from drawings.sheet import Sheet\n    import matplotlib.pyplot as plt\n")
    fake.write_text(text, encoding="utf-8")
    try:
        names = imports(fake)
    finally:
        fake.unlink()
    assert "reportgen.commands" in names and "reportgen.commands.build" in names
    assert {"drawings", "matplotlib"} <= _top(names)
    init = ROOT / "latex_templates" / "parts" / "__init__.py"
    node = ast.parse("from ..figures import scene").body[0]
    assert _resolve(init, node) == "latex_templates.figures"
