"""Bad input (issue #8): every one is refused with exit status 2, a message that names the key or
option and says what is valid, no traceback, and nothing left behind in the output's folder.

The commands run in-process through ``reportgen.cli.main`` (fast); two tests spawn the real program
to prove that no traceback reaches the terminal.
"""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from reportgen import zoo
from reportgen.cli import main

ROOT = Path(__file__).resolve().parents[2]


def slider_crank(r: float = 0.1, l: float = 0.3, e: float = 0.0, phi_deg: float = 30.0, extra: str = "") -> str:
    return zoo.slider_crank(r, l, e, phi_deg=phi_deg, omega=10.0, extra=extra)


FOUR_BAR = zoo.linkage(
    ground=("O", "C"), points={"O": (0.0, 0.0), "C": (0.4, 0.0), "A": (0.1, 0.0), "B": (0.3, 0.3), "X": (0.4, 0.1)},
    links=[{"id": 1, "kind": "crank", "points": ["O", "A"], "length": 0.1},
           {"id": 2, "kind": "coupler", "points": ["A", "B"]},
           {"id": 3, "kind": "rocker", "points": ["C", "B"]}], omega=10.0)

SC = slider_crank()


def _five_bar() -> str:
    """Two cranks in series with a coupler: the rocker C–B replaced by C–X–B (W = 2)."""
    return FOUR_BAR.replace('points = ["C", "B"]', 'points = ["X", "B"]') + """
[[mechanism.link]]
id = 4
kind = "crank"
points = ["C", "X"]
"""


def _overconstrained() -> str:
    """A four-bar with a fourth bar B–D to the frame: W = 0."""
    return FOUR_BAR.replace('ground = ["O", "C"]', 'ground = ["O", "C", "D"]').replace(
        "X = [0.4, 0.1]", "D = [0.6, 0.5]") + """
[[mechanism.link]]
id = 4
kind = "rocker"
points = ["D", "B"]
"""


SLOTTED = zoo.linkage(
    ground=("O", "C"), points={"C": (0.0, 0.0), "O": (0.0, 0.2), "A": (0.1, 0.2), "E": (0.4, 0.8)},
    links=[{"id": 1, "kind": "crank", "points": ["O", "A"]}, {"id": 2, "kind": "block", "points": ["A"]},
           {"id": 3, "kind": "slotted", "points": ["C", "E"]}],
    slides=[{"link": 2, "point": "A", "guide": 3, "along": ["C", "Z"]}], omega=10.0)

GEARS = "[gears]\nz1 = {z1}\nz2 = 26\nmodule = 9.0\nx1 = 0.0\nx2 = 0.0\n"

# (id, task text, fragments that the message must contain: the key and what is valid)
TASK_CASES = [
    ("malformed-toml", "[mechanism\nname = 1\n", ["line 1, column", "TOML syntax"]),
    ("malformed-value", SC.replace("omega = 10.0", "omega = 10.0.0"), ["line", "TOML"]),
    ("wrong-type-length", SC.replace("length = 0.3", 'length = "0.3"'),
     ["mechanism.link[1].length", "string", "a number in (0, 1000]"]),
    ("wrong-type-points", SC.replace('points = ["A", "B"]', 'points = "AB"'), ["mechanism.link[1].points"]),
    ("wrong-type-id", SC.replace("id = 2", "id = 2.0"), ["mechanism.link[1].id", "integer"]),
    ("wrong-type-section", SC + "\ndynamics = 5\n", ["dynamics"]),
    ("unknown-key", SC.replace("length = 0.3", "lenght = 0.3"),
     ["mechanism.link[1].lenght", "did you mean 'length'", "one of:"]),
    ("unknown-section", SC + "\n[dynamic]\ndelta = 0.05\n", ["dynamic", "did you mean 'dynamics'"]),
    ("zero-length", SC.replace("length = 0.3", "length = 0.0"), ["mechanism.link[1].length", "(0, 1000]"]),
    ("negative-length", SC.replace("length = 0.3", "length = -0.3"), ["mechanism.link[1].length", "(0, 1000]"]),
    ("zero-mass", SC.replace("length = 0.3", "length = 0.3\nmass = 0.0"), ["mechanism.link[1].mass", "> 0"]),
    ("negative-omega-zero", SC.replace("omega = 10.0", "omega = 0.0"), ["mechanism.drive.omega", "≠ 0"]),
    ("triangle-inequality",
     SC.replace('points = ["A", "B"]\nlength = 0.3', 'points = ["A", "B", "E"]\nlengths = { AB = 0.3, AE = 0.1, BE = 0.5 }')
       .replace("[mechanism.points]", "[mechanism.points]\nE = [0.2, 0.2]"),
     ["mechanism.link[1].lengths", "do not form a triangle", "AE + AB = 0.4 < BE = 0.5",
      "each side shorter than the sum of the other two"]),
    ("point-of-one-link-only", FOUR_BAR.replace('points = ["C", "B"]', 'points = ["C", "X"]'),
     ["points listed by one link only: B (link 2), X (link 3)", "both links it joins", "W = 3"]),
    ("no-driver", SC.replace("[mechanism.drive]\nlink = 1\nomega = 10.0\n", ""), ["mechanism.drive", "missing"]),
    ("two-drivers-list", SC.replace("link = 1\nomega", "link = [1, 2]\nomega"),
     ["mechanism.drive.link", "an integer ≥ 1"]),
    ("two-drivers-tables", SC + "\n[mechanism.drive]\nlink = 2\nomega = 5.0\n", ["drive", "twice"]),
    ("driver-not-on-frame", SC.replace("link = 1\nomega", "link = 2\nomega"), ["mechanism.drive"]),
    ("W-is-2", _five_bar(), ["W = 2", "one driver (W = 1)"]),
    ("W-is-0", _overconstrained(), ["W = 0", "links left over: 4"]),
    ("slide-point-not-on-link", SC.replace('point = "B"\nguide', 'point = "A"\nguide'),
     ["mechanism.slide[0].point", 'no point "A" in link 3', "one of: B"]),
    ("slide-along-not-on-guide", SLOTTED, ["mechanism.slide[0].along"]),
    ("slide-guide-missing-link", SC.replace("guide = 0", "guide = 7"), ["mechanism.slide[0].guide"]),
    ("cannot-assemble", slider_crank(0.1, 0.05, phi_deg=90.0),
     ["cannot be assembled at crank angle φ1 =", "exceeds AB = 0.05 m", "it assembles for φ1 in"]),
    ("gear-z-4", GEARS.format(z1=4), ["gears.z1", "5..1000"]),
    ("gear-z-float", GEARS.format(z1="13.0"), ["gears.z1", "the float 13.0"]),
    ("planetary-ratio-too-low",
     '[planetary]\nscheme = "single-row"\nratio = 1.5\ntolerance = 0.05\nsatellites = "auto"\n',
     ["planetary.ratio", "no single-row tooth set gives u = 1.5", "nearest ratios that exist",
      "a ratio this scheme can give"]),
    ("planetary-auto-without-motor", '[planetary]\nscheme = "single-row"\nratio = "auto"\n',
     ["planetary.motor_rpm"]),
    ("dynamics-delta-out-of-range", SC + "\n[dynamics]\ndelta = 1.5\n", ["dynamics.delta"]),
    ("inf-coordinate", SC.replace("O = [0.0, 0.0]", "O = [inf, 0.0]"), ["mechanism.points.O"]),
    ("nan-length", SC.replace("length = 0.3", "length = nan"), ["mechanism.link[1].length"]),
]


def _run(argv, capsys) -> tuple[int, str]:
    code = main(argv)
    err = capsys.readouterr().err
    return code, err


def _left_behind(folder: Path, keep: set[str]) -> list[str]:
    return sorted(p.name for p in folder.iterdir() if p.name not in keep)


@pytest.mark.parametrize("text, fragments", [c[1:] for c in TASK_CASES], ids=[c[0] for c in TASK_CASES])
def test_bad_task_refused_by_build(tmp_path, capsys, text, fragments):
    task = tmp_path / "task.toml"
    task.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    code, err = _run(["build", str(task), "-o", str(out), "--quiet", "--no-pdf"], capsys)
    assert code == 2, err
    assert err.startswith("reportgen build: error: ") and "Traceback" not in err
    for f in fragments:
        assert f in err, f"{f!r} not in {err!r}"
    assert not out.exists()
    assert _left_behind(tmp_path, {"task.toml"}) == []


@pytest.mark.parametrize("text, fragments", [c[1:] for c in TASK_CASES[:8]], ids=[c[0] for c in TASK_CASES[:8]])
def test_bad_task_refused_by_solve_writes_nothing(tmp_path, capsys, text, fragments):
    task = tmp_path / "task.toml"
    task.write_text(text, encoding="utf-8")
    code, err = _run(["solve", str(task), "--json", str(tmp_path / "r.json"), "--quiet"], capsys)
    assert code == 2 and all(f in err for f in fragments), err
    assert _left_behind(tmp_path, {"task.toml"}) == []


def test_an_old_output_folder_survives_bad_input(tmp_path, capsys):
    """Refused input replaces nothing: the output of an earlier build stays as it was."""
    out = tmp_path / "out"
    out.mkdir()
    (out / "results.json").write_text("{}", encoding="utf-8")
    task = tmp_path / "task.toml"
    task.write_text(slider_crank(0.1, 0.05, phi_deg=90.0), encoding="utf-8")
    code, _ = _run(["build", str(task), "-o", str(out), "--quiet", "--no-pdf"], capsys)
    assert code == 2
    assert [p.name for p in out.iterdir()] == ["results.json"]
    assert _left_behind(tmp_path, {"task.toml", "out"}) == []


# command-line options: (argv, fragments)
OPTION_CASES = [
    (["gear", "--z1", "4", "--z2", "20", "--module", "2"], ["--z1", "5..1000"]),
    (["gear", "--z1", "13", "--z2", "1001", "--module", "2"], ["--z2", "5..1000"]),
    (["gear", "--z1", "13", "--z2", "26", "--module", "-1"], ["--module", "> 0"]),
    (["gear", "--z1", "13", "--z2", "26", "--module", "nan"], ["--module", "> 0"]),
    (["gear", "--z1", "13", "--z2", "26", "--module", "9", "--alpha", "inf"], ["--alpha", "5°…40°"]),
    (["gear", "--z1", "13", "--z2", "26", "--module", "9", "--x1", "auto"], ["--x2", "both"]),
    (["gear", "--z1", "6", "--z2", "12", "--module", "2", "--x1", "auto", "--x2", "auto"],
     ["--x1", "no profile shifts", "εα ≥ 1.2", "sa ≥ 0.25·m", "no undercut"]),
    (["planetary", "--scheme", "single-row", "--ratio", "1.5"],
     ["--ratio", "no single-row tooth set gives u = 1.5", "a ratio this scheme can give"]),
    (["planetary", "--scheme", "two-row-ext-int", "--ratio", "nan"], ["--ratio", "finite"]),
    (["planetary", "--scheme", "single-row", "--ratio", "5", "--tolerance", "-1"], ["--tolerance", "0 < tolerance < 1"]),
    (["planetary", "--scheme", "single-row", "--ratio", "5", "--satellites", "0"], ["--satellites", "auto"]),
    (["planetary", "--scheme", "single-row", "--ratio", "5", "--z", "17", "40"], ["--z", "3 integers"]),
    (["planetary", "--scheme", "single-row", "--ratio", "auto"], ["--ratio", "--motor-rpm"]),
]


@pytest.mark.parametrize("argv, fragments", OPTION_CASES, ids=[" ".join(a[:1] + a[3:]) for a, _ in OPTION_CASES])
def test_bad_option(capsys, argv, fragments):
    code, err = _run(argv, capsys)
    assert code == 2, err
    assert err.startswith(f"reportgen {argv[0]}: error: ") and "Traceback" not in err
    for f in fragments:
        assert f in err, f"{f!r} not in {err!r}"


@pytest.mark.parametrize("value", ["nan", "inf", "1e999"])
def test_solve_at_non_finite_angle(tmp_path, capsys, value):
    """Was a traceback (NaN crank angles reached the solver)."""
    task = tmp_path / "task.toml"
    task.write_text(SC, encoding="utf-8")
    out = tmp_path / "r.json"
    code, err = _run(["solve", str(task), "--json", str(out), "--quiet", "--at", "0", value], capsys)
    assert code == 2 and "--at" in err and "finite" in err
    assert not out.exists()


def test_missing_task_and_output_folder(tmp_path, capsys):
    code, err = _run(["build", str(tmp_path / "nope.toml"), "-o", str(tmp_path / "o")], capsys)
    assert code == 2 and "nope.toml" in err and "TOML task file" in err
    task = tmp_path / "task.toml"
    task.write_text(SC, encoding="utf-8")
    code, err = _run(["build", str(task), "-o", str(tmp_path / "no" / "such" / "out")], capsys)
    assert code == 2 and "--out" in err and "existing folder" in err
    code, err = _run(["bench", "--quick", "--out", str(tmp_path / "no" / "such" / "dir")], capsys)
    assert code == 2 and "--out" in err


def test_latex_special_characters_print_literally(tmp_path, capsys):
    """A title full of LaTeX special characters is text: escaped in report.tex, never run as TeX."""
    marker = tmp_path / "PWNED"
    title = (r"Title \input{/etc/passwd} \write18{touch " + str(marker) + r"} $x^2$ & 100% #1 _a {b} ~c ^d \\ "
             r"\end{document}")
    task = tmp_path / "task.toml"
    task.write_text(f"[document]\ntitle = '{title}'\nauthor = 'A & B_{{c}}'\n"
                    + GEARS.format(z1=13).replace("x1 = 0.0", "x1 = 0.63").replace("x2 = 0.0", "x2 = 0.67"),
                    encoding="utf-8")
    out = tmp_path / "out"
    code, err = _run(["build", str(task), "-o", str(out), "--quiet", "--no-pdf", "--no-sheets"], capsys)
    assert code == 0, err
    tex = (out / "report.tex").read_text(encoding="utf-8")
    assert (r"Title \textbackslash{}input\{/etc/passwd\} \textbackslash{}write18\{touch" in tex)
    assert r"\$x\textasciicircum{}2\$ \& 100\% \#1 \_a \{b\} \textasciitilde{}c \textasciicircum{}d" in tex
    assert r"A \& B\_\{c\}" in tex
    assert r"\input{/etc/passwd}" not in tex and tex.count(r"\end{document}") == 1
    assert not marker.exists()


def _spawn(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "reportgen", *args], capture_output=True, text=True, cwd=ROOT,
                          timeout=120)


def test_no_traceback_from_the_real_program(tmp_path):
    task = tmp_path / "task.toml"
    task.write_text(FOUR_BAR.replace('points = ["C", "B"]', 'points = ["C", "X"]'), encoding="utf-8")
    r = _spawn("build", str(task), "-o", str(tmp_path / "out"), "--no-pdf")
    assert r.returncode == 2 and "Traceback" not in r.stderr and "one link only" in r.stderr
    assert _left_behind(tmp_path, {"task.toml"}) == []
    r = _spawn("solve", str(task), "--at", "nan")
    assert r.returncode == 2 and "Traceback" not in r.stderr


@pytest.mark.parametrize("text, given", [
    ("", None), ("# только комментарий\n\n# ещё один\n", None),
    ('[document]\ntitle = "Курсовой проект"\n', "[document]"),
    ('[document]\ntitle = "x"\n[analysis]\npositions = 12\n', "[document], [analysis]"),
], ids=["empty", "comments-only", "document-only", "document-and-analysis"])
def test_task_with_nothing_to_build(tmp_path, capsys, text, given):
    """Issue 11: was "done … report.pdf" with a 37-byte results.json; now exit 2 naming the sections."""
    task = tmp_path / "task.toml"
    task.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    for argv in (["build", str(task), "-o", str(out), "--quiet"],
                 ["solve", str(task), "--json", str(tmp_path / "r.json"), "--quiet"]):
        code, err = _run(argv, capsys)
        assert code == 2, err
        assert "nothing to build" in err and "Traceback" not in err
        for section in ("[mechanism]", "[gears]", "[planetary]"):
            assert section in err
        if given:
            assert given in err
        assert _left_behind(tmp_path, {"task.toml"}) == []
