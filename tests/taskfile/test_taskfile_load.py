"""The valid examples load with the exact values; sections may be left out; file-level errors."""
from __future__ import annotations

import math

import pytest

from reportgen.errors import ReportgenInputError, TaskError, TaskSyntaxError
from reportgen.task import Analysis, Document, Flywheel, Gears, Link, Load, MassRules, Planetary, Slide
from reportgen.taskfile import load_task, loads_task, parse_task

from taskfile_cases import FULL, SLOTTED, edit, example


def test_full_example_exact_values():
    task = load_task(FULL)
    assert task.source == str(FULL)
    assert task.document == Document(
        title="Проектирование и исследование механизма пресса", author="И. И. Иванов", group="ТМ-21",
        supervisor="А. П. Слободюк", organization="Кафедра теории механизмов и машин", city="Белгород",
        year=2026, language="ru")
    m = task.mechanism
    assert m.name == "Механизм пресса" and m.g == 9.81 and m.ground == ("O", "C")
    assert dict(m.points) == {"O": (0.0, 0.0), "C": (0.30, -0.18), "A": (0.0, 0.11),
                              "B": (0.33, 0.08), "D": (0.66, -0.05)}
    assert list(m.points) == ["O", "C", "A", "B", "D"]
    assert m.links == (
        Link(1, "crank", ("O", "A"), (("O", "A", 0.11),), 4.0, 0.02, 0.5, True, True),
        Link(2, "coupler", ("A", "B"), (("A", "B", 0.38),), 8.5, 0.10, None, True, True),
        Link(3, "rocker", ("C", "B"), (("C", "B", 0.26),), 10.0, 0.21, None, True, True),
        Link(4, "coupler", ("B", "D"), (("B", "D", 0.35),), 31.0, 0.10, None, True, True),
        Link(5, "slider", ("D",), (), 45.0, 0.0, None, True, False),
    )
    assert m.drive.link == 1 and m.drive.omega == 18.0
    assert m.slides == (Slide(link=5, point="D", guide=0, through=(0.0, -0.05), angle_deg=0.0),)
    assert m.mass_rules == MassRules(10.0, 6.0, 2.5)
    assert m.loads == (
        Load(kind="resistance", link=5, force=15800.0, law=((0.0, 0.0), (1.0, 1.0)), stroke="working"),
        Load(kind="force", link=5, point="D", vector=(500.0, 0.0)),
        Load(kind="moment", link=3, value=-40.0),
    )
    assert task.analysis == Analysis(8, "extreme", 2)
    assert task.dynamics.delta == 0.05 and task.dynamics.crank_inertia == 2.2
    assert task.dynamics.flywheel == Flywheel("disk", 7860.0, 1.0)
    assert task.gears == Gears(z1=13, z2=26, module=9.0, x1=0.63, x2=0.67)
    assert task.planetary == Planetary(scheme="two-row-ext-int", motor_rpm=1500.0, ratio="auto",
                                       tolerance=0.05, satellites="auto", module=6.4)
    assert isinstance(task.gears.z1, int) and isinstance(task.planetary.motor_rpm, float)


def test_results_are_frozen():
    m = load_task(FULL).mechanism
    with pytest.raises(TypeError):
        m.points["X"] = (0.0, 0.0)  # type: ignore[index]
    assert isinstance(m.links, tuple) and isinstance(m.ground, tuple)
    assert all(isinstance(p, tuple) for p in m.points.values())


def test_every_section_may_be_left_out():
    """... but not all of [mechanism], [gears] and [planetary] (issue 11: nothing to build is refused)."""
    only_gears = parse_task({"gears": {"z1": 13, "z2": 26, "module": 9}})
    assert only_gears.gears == Gears(13, 26, 9.0) and only_gears.mechanism is None
    assert only_gears.document == Document() and only_gears.analysis == Analysis()
    assert only_gears.dynamics is None and only_gears.planetary is None


def test_optional_values_and_alternatives():
    data = example()
    edit(data, ("analysis", "start"), -30.5)
    edit(data, ("analysis", "force_position"), "max-load")
    edit(data, ("gears", "x1"), "auto")
    edit(data, ("planetary", "ratio"), 12.272)
    edit(data, ("planetary", "satellites"), 3)
    edit(data, ("planetary", "motor_rpm"))            # not needed for a numeric ratio
    edit(data, ("mechanism", "g"), 0)
    edit(data, ("mechanism", "link", 0, "com"), "A")
    del data["document"]
    task = parse_task(data, "x.toml")
    assert task.analysis.start == -30.5 and task.analysis.force_position == "max-load"
    assert task.gears.x1 == "auto" and task.planetary.ratio == 12.272 and task.planetary.satellites == 3
    assert task.planetary.motor_rpm is None and task.mechanism.g == 0.0
    assert task.mechanism.link(1).com == "A" and task.source == "x.toml"
    assert task.document == Document()


def test_start_as_integer_angle_becomes_float():
    data = example()
    edit(data, ("analysis", "start"), 90)
    start = parse_task(data).analysis.start
    assert start == 90.0 and isinstance(start, float)


def test_slotted_example():
    m = load_task(SLOTTED).mechanism
    assert m.drive.omega == -10.0
    assert m.slides[0] == Slide(link=2, point="B", guide=3, along=("C", "E"))
    assert m.slides[1].point == "F"             # the only point of link 5, taken by default
    assert m.link(3).lengths == (("C", "E", 0.58),) and m.link(3).com == "C"
    assert m.loads[0].law == ((0.0, 0.0), (0.5, 1.0), (1.0, 1.0)) and m.loads[0].stroke == "both"


def test_links_sorted_by_id_and_lengths_key_forms():
    data = example()
    links = data["mechanism"]["link"]
    links.reverse()                                # file order 5, 4, 3, 2, 1
    links[2]["points"] = ["C", "B", "E"]           # link 3 becomes a triangle
    del links[2]["length"]
    links[2]["lengths"] = {"BC": 0.26, "C-E": 0.40, "EB": 0.20}
    data["mechanism"]["points"]["E"] = [0.5, -0.3]
    m = parse_task(data).mechanism
    assert [ln.id for ln in m.links] == [1, 2, 3, 4, 5]
    assert m.link(3).lengths == (("B", "C", 0.26), ("C", "E", 0.40), ("E", "B", 0.20))


def test_bom_and_file_errors(tmp_path):
    f = tmp_path / "task.toml"
    f.write_bytes("\ufeff".encode() + FULL.read_bytes())
    assert load_task(f).mechanism.drive.omega == 18.0

    missing = tmp_path / "nope.toml"
    with pytest.raises(TaskError) as info:
        load_task(missing)
    assert info.value.path == str(missing) and "no such file" in str(info.value)
    with pytest.raises(TaskError, match="is a directory"):
        load_task(tmp_path)

    bad = tmp_path / "bad.toml"
    bad.write_text('[gears]\nz1 = 13\nz2 = = 26\n', encoding="utf-8")
    with pytest.raises(TaskSyntaxError) as info:
        load_task(bad)
    err = info.value
    assert (err.file, err.line, err.column) == (str(bad), 3, 6)
    assert str(bad) in str(err) and "line 3, column 6" in str(err) and "not valid TOML" in str(err)
    assert isinstance(err, ReportgenInputError)

    latin1 = tmp_path / "latin1.toml"
    latin1.write_bytes(b'[document]\ntitle = "\xe9t\xe9"\n')
    with pytest.raises(TaskSyntaxError) as info:
        load_task(latin1)
    assert info.value.line == 2 and "UTF-8" in str(info.value)


def test_syntax_error_at_end_of_document():
    with pytest.raises(TaskSyntaxError) as info:
        loads_task('[gears]\nz1 = [1, 2')
    assert info.value.file == "<string>" and info.value.line >= 2


def test_toml_inf_and_nan_are_refused():
    with pytest.raises(TaskError) as info:
        loads_task("[dynamics]\ndelta = nan\n")
    assert info.value.path == "dynamics.delta"
    with pytest.raises(TaskError) as info:
        loads_task("[gears]\nz1 = 13\nz2 = 26\nmodule = inf\n")
    assert info.value.path == "gears.module"


def test_huge_integer_is_an_input_error_not_overflow():
    data = example()
    edit(data, ("mechanism", "link", 1, "mass"), 10**400)
    with pytest.raises(TaskError) as info:
        parse_task(data)
    assert info.value.path == "mechanism.link[1].mass" and "digit integer" in str(info.value)


def test_math_sanity_of_defaults_is_finite():
    m = load_task(SLOTTED).mechanism
    assert all(math.isfinite(ln.mass) and math.isfinite(ln.inertia) for ln in m.links)
