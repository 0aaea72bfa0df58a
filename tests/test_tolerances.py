"""One home for each tolerance (issue 13 item 3): no bare ``1e-N`` literal in the packages outside
reportgen/tolerances.py, and every name there says what it means in a docstring of its own."""
from __future__ import annotations

import ast
import io
import re
import tokenize
from pathlib import Path

from reportgen import tolerances

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("reportgen", "drawings", "latex_templates")
HOME = ROOT / "reportgen" / "tolerances.py"

#: A float written with a negative exponent (1e-9, 2.5E-4, 1_0e-3) or as a decimal below 1e-3
#: (0.0001): the two spellings of a small number.
EXPONENT = re.compile(r"^[0-9_.]*[eE]-[0-9_]+$")

#: (file, the name the literal is assigned to) → why it is not a tolerance. Nothing else.
ALLOWED = {
    ("reportgen/taskspec.py", "MIN_LENGTH"):
        "the task format's smallest accepted length (1 µm): an input range, documented in docs/task-format.md",
    ("reportgen/calc.py", "SMALL_NUMBER"):
        "a display rule of the note: below this magnitude a number is written as m·10^k",
    ("reportgen/commands/bench.py", "floor"):
        "the log axis of the bench plot starts at 1e-16 (an error of 0 cannot be drawn on it)",
}


def small_literals(path: Path) -> list[tuple[int, str, str]]:
    """(line, literal, the name it is assigned to or "") of every small float literal in ``path``;
    comments and strings (docstrings) are tokens of their own, so they do not count."""
    src = path.read_text(encoding="utf-8")
    targets: dict[int, str] = {}
    for node in ast.walk(ast.parse(src)):
        if isinstance(node, ast.Assign) and len(node.targets) == 1 and isinstance(node.targets[0], ast.Name):
            targets[node.lineno] = node.targets[0].id
    out = []
    for tok in tokenize.generate_tokens(io.StringIO(src).readline):
        if tok.type != tokenize.NUMBER or tok.string.lower().startswith(("0x", "0o", "0b")):
            continue
        text = tok.string.replace("_", "")
        small = bool(EXPONENT.match(text))
        if not small and not text.endswith(("j", "J")):
            value = float(text)
            small = 0 < value < 1e-3
        if small:
            out.append((tok.start[0], tok.string, targets.get(tok.start[0], "")))
    return out


def test_no_bare_small_literal_outside_tolerances():
    found = []
    for pkg in PACKAGES:
        for path in sorted((ROOT / pkg).rglob("*.py")):
            if path == HOME:
                continue
            rel = path.relative_to(ROOT).as_posix()
            for line, literal, name in small_literals(path):
                if (rel, name) not in ALLOWED:
                    found.append(f"{rel}:{line}: {literal}")
    assert not found, ("bare tolerances: give each a name in reportgen/tolerances.py "
                       "(one name per meaning) and import it:\n" + "\n".join(found))


def test_the_allowed_literals_are_still_there():
    """The allow-list names only places that exist: a stale entry would hide a new literal."""
    for (rel, name), _reason in ALLOWED.items():
        assert any(n == name for _, _, n in small_literals(ROOT / rel)), (rel, name)


def test_the_finder_sees_every_spelling(tmp_path):
    probe = tmp_path / "probe.py"
    probe.write_text('"""1e-9 in a docstring"""\n# 1e-9 in a comment\nA = 1e-9\nb = 2.5E-4 + 0.0001 + x[1e-3]\n'
                     "c = 0.001 + 1e3 + 0x1e\n", encoding="utf-8")
    assert [(line, lit) for line, lit, _ in small_literals(probe)] == [
        (3, "1e-9"), (4, "2.5E-4"), (4, "0.0001"), (4, "1e-3")]


def test_every_tolerance_has_a_docstring_and_is_exported():
    tree = ast.parse(HOME.read_text(encoding="utf-8"))
    body = tree.body
    names = []
    for i, node in enumerate(body):
        if isinstance(node, ast.Assign) and isinstance(node.targets[0], ast.Name) \
                and node.targets[0].id.isupper() and node.targets[0].id != "__all__":
            name = node.targets[0].id
            names.append(name)
            doc = body[i + 1] if i + 1 < len(body) else None
            assert isinstance(doc, ast.Expr) and isinstance(doc.value, ast.Constant) \
                and isinstance(doc.value.value, str) and len(doc.value.value) > 20, f"{name} has no docstring"
            assert isinstance(getattr(tolerances, name), float) and getattr(tolerances, name) > 0, name
    assert sorted(names) == sorted(tolerances.__all__)
    assert len(names) == len(set(names))


def test_old_names_still_resolve_to_the_one_value():
    """Modules that named a tolerance before keep the name, bound to the value of tolerances.py."""
    from reportgen import numbers, roots
    from reportgen.kinematics import extremes, positions

    assert numbers.RESIDUE_REL is tolerances.RTOL_EQUAL
    assert roots.EXTREME_XTOL is tolerances.EXTREME_XTOL
    assert extremes.ROOT_XTOL is tolerances.ROOT_XTOL and extremes.CONSTRUCTION_TOL is tolerances.CONSTRUCTION_TOL
    assert positions.NEWTON_REL_TOL is tolerances.NEWTON_REL_TOL
