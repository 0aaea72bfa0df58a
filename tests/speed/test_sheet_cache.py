"""Issue 16 item 2: whole sheets and the note's plots kept by the build cache under what they read
(reportgen/read_trace.py, BuildCache.restore_sheet/store_sheet, latex_templates/figures/keyed.py).
The end-to-end check — a changed task rebuilt with the cache equals an uncached build, byte for
byte, with the sheets and plots it reuses counted — is tests/speed/test_reproducible_and_cached.py."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from reportgen.cache import BuildCache
from reportgen.project import Project, UndeclaredStage
from reportgen.read_trace import MASS_FIELDS, Trace, TracedNeeds, masks_masses
from reportgen.taskfile import load_task

ROOT = Path(__file__).resolve().parents[2]
PRESS = ROOT / "examples" / "press" / "task.toml"


def project(tmp_path: Path, old: str = "", new: str = "", name: str = "task") -> Project:
    text = PRESS.read_text(encoding="utf-8")
    if old:
        assert text.count(old) == 1, old
        text = text.replace(old, new)
    path = tmp_path / name / "task.toml"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return Project(load_task(path))


def sheet(p: Project, stem: str):
    from reportgen.commands.pipeline import _sheet_list
    todo = _sheet_list(p)
    i = [s for s, _ in todo].index(stem)
    return i + 1, len(todo), todo[i][1]


@pytest.fixture(scope="module")
def traced(tmp_path_factory):
    """Each press sheet drawn with a trace: stem → (its reads, its DXF bytes)."""
    from reportgen.commands.pipeline import _sheet_list, draw_sheet

    base = tmp_path_factory.mktemp("traced")
    p = project(base)
    out = {}
    todo = _sheet_list(p)
    for i, (stem, mod) in enumerate(todo, start=1):
        trace = Trace()
        s = draw_sheet(p, mod, i, len(todo), trace)
        s.save(base / f"{stem}.dxf")
        out[stem] = (trace, (base / f"{stem}.dxf").read_bytes())
    return out


def test_a_traced_sheet_reads_its_stages_the_title_block_and_its_scenes(traced):
    trace, _ = traced["sheet1-kinematics"]
    assert not trace.opaque
    assert ("task", "document") in trace.reads                  # the title block
    assert ("scenes", "positions") in trace.reads and ("attr", "kinematics") in trace.reads
    assert ("attr", "dynamics") not in trace.reads
    assert masks_masses(trace.reads)                              # no mass stage read
    trace2, _ = traced["sheet2-kinetostatics"]
    assert ("attr", "kinetostatics") in trace2.reads and not masks_masses(trace2.reads)
    trace4, _ = traced["sheet4-gears"]
    assert {("task", "gears"), ("attr", "gears"), ("scenes", "meshing")} <= set(trace4.reads)


def test_a_traced_view_still_refuses_an_undeclared_stage_and_marks_a_method_opaque(tmp_path):
    p = project(tmp_path)
    trace = Trace()
    view = TracedNeeds(p, ("gears",), "test", trace)
    with pytest.raises(UndeclaredStage):
        _ = view.kinematics
    assert view.gears is p.gears and ("attr", "gears") in trace.reads and not trace.opaque
    _ = view.kinematics_at                  # a method: its arguments are not replayed
    assert trace.opaque


def variant(cache: BuildCache, p: Project, reads) -> str | None:
    return cache._variant(p, list(reads))


def test_what_a_sheet_reads_changes_with_its_inputs_and_only_with_them(tmp_path, traced):
    """The variant of each sheet (the digest of the values of its reads) for the press and for
    copies with one number changed: the same exactly where the sheet's DXF is the same."""
    reads = {stem: t.reads for stem, (t, _) in traced.items()}
    base = project(tmp_path)
    edits = {"mass": ("mass = 45.0", "mass = 46.0"), "inertia": ("inertia = 0.21", "inertia = 0.25"),
             "delta": ("delta = 0.05", "delta = 0.04"), "length": ("length = 0.38", "length = 0.39"),
             "module": ("module = 9.0", "module = 10.0"), "author": ('author = "И. И. Иванов"', 'author = "П. П. Петров"')}
    same = {edit: {stem for stem in reads
                   if variant(BuildCache(tmp_path / "c", b"", tmp_path, ""), project(tmp_path, *pair, name=edit), reads[stem])
                   == variant(BuildCache(tmp_path / "c", b"", tmp_path, ""), base, reads[stem])}
            for edit, pair in edits.items()}
    assert same["mass"] == same["inertia"] == {"sheet1-kinematics", "sheet4-gears"}
    assert same["delta"] == {"sheet1-kinematics", "sheet2-kinetostatics", "sheet4-gears"}
    assert same["length"] == {"sheet4-gears"}           # link 2's length reaches every linkage sheet
    assert same["module"] == {"sheet1-kinematics", "sheet2-kinetostatics", "sheet3-dynamics"}
    assert same["author"] == set()                      # the title block of every sheet


def test_a_sheet_unchanged_by_a_mass_draws_the_same_bytes(tmp_path, traced):
    """What masking the masses relies on: sheet 1 of the press with another mass is the same DXF."""
    from reportgen.commands.pipeline import draw_sheet

    p = project(tmp_path, "mass = 45.0", "mass = 46.0")
    number, count, mod = sheet(p, "sheet1-kinematics")
    draw_sheet(p, mod, number, count).save(tmp_path / "s.dxf")
    assert (tmp_path / "s.dxf").read_bytes() == traced["sheet1-kinematics"][1]


def test_no_drawing_reads_a_body_mass(tmp_path):
    """The sheets (and the plots keyed with ``MASS_FIELDS`` left out) never read a body's mass or
    moment of inertia themselves; they read stages computed from them, which the trace records.
    Each ``.mass`` / ``.inertia`` below is something else — a new one must be looked at."""
    allowed = {("drawings/scenes/dynamics_diagrams.py", "self.inertia"),        # the J_red view's rectangle
               ("drawings/scenes/dynamics_diagrams.py", "lay.inertia"),
               ("drawings/scenes/dynamics_flywheel.py", "fw.mass"),             # the flywheel (dynamics stage)
               ("drawings/sheet.py", "fl.mass"),                                # the title block's graph 5
               ("drawings/sheets/dynamics.py", "sc.inertia"),                   # the J_red scene
               ("drawings/sheets/crane_hoist.py", "c.inertia")}                 # the crane's coupling
    found = set()
    files = sorted((ROOT / "drawings").rglob("*.py")) + [ROOT / "latex_templates/figures/mechanism.py",
                                                          ROOT / "latex_templates/figures/groups.py"]
    for path in files:
        for m in re.finditer(r"[\w.\]\)]*\.(?:mass|inertia)\b", path.read_text(encoding="utf-8")):
            found.add((path.relative_to(ROOT).as_posix(), m.group(0)))
    assert found - allowed == set()
    assert MASS_FIELDS == {("Body", "mass"), ("Body", "inertia")}


def test_a_kept_sheet_is_copied_when_what_it_read_is_unchanged(tmp_path, traced):
    trace, dxf = traced["sheet4-gears"]
    cache = BuildCache(tmp_path / "cache", b"task", tmp_path / "task.toml", "options")
    made = {"sheet.dxf": tmp_path / "a.dxf", "sheet.png": tmp_path / "a.png"}
    made["sheet.dxf"].write_bytes(dxf)
    made["sheet.png"].write_bytes(b"png")
    p = project(tmp_path)
    cache.store_sheet("sheet4|ru", p, trace.reads, made)
    out = {"sheet.dxf": tmp_path / "b.dxf", "sheet.png": tmp_path / "b.png"}
    fresh = BuildCache(tmp_path / "cache", b"task2", tmp_path / "task.toml", "options")   # another build
    assert fresh.restore_sheet("sheet4|ru", project(tmp_path, "mass = 45.0", "mass = 46.0", "m"), out)
    assert out["sheet.dxf"].read_bytes() == dxf and out["sheet.png"].read_bytes() == b"png"
    other = BuildCache(tmp_path / "cache", b"task3", tmp_path / "task.toml", "options")
    assert not other.restore_sheet("sheet4|ru", project(tmp_path, "module = 9.0", "module = 10.0", "g"), out)
    assert not other.restore_sheet("sheet4|uk", p, out)             # another identity (language)


# -- the plots ---------------------------------------------------------------------------------

def test_a_plot_is_keyed_by_its_data_and_language_and_kept_with_its_size(tmp_path):
    import numpy as np

    from latex_templates.figures import new_figure
    from latex_templates.figures.keyed import keyed_plot
    from latex_templates.figures.saving import KeptFigure, content_key, queued
    from latex_templates.parts import active_strings
    from latex_templates.render import Strings

    @keyed_plot()
    def curve(xs, label: str = "x"):
        from latex_templates.figures import comma_axes
        fig = new_figure(8.0, 5.0)
        ax = fig.add_subplot(1, 1, 1)
        ax.plot(xs, np.sin(xs), label=label)
        comma_axes(ax)
        return fig

    xs = np.linspace(0.0, 3.0, 50)
    one, same, other = curve(xs), curve(xs), curve(xs + 1e-9)
    assert content_key(one) == content_key(same) != content_key(other) is not None
    assert content_key(curve(xs, label="y")) != content_key(one)
    with active_strings(Strings("en")):                 # the decimal mark and the words
        assert content_key(curve(xs)) != content_key(one)

    cache = BuildCache(tmp_path / "cache", b"task", tmp_path / "task.toml", "options")
    with queued(cache) as q:
        made = curve(xs)
    assert not isinstance(made, KeptFigure)
    q.add(made, tmp_path / "first.pdf")
    q.save(cache=cache)
    with queued(cache) as q:
        kept = curve(xs)
    assert isinstance(kept, KeptFigure) and not kept.reportgen_exact     # saved at its tight box
    assert kept.get_figwidth() == made.get_figwidth()                    # what a part may read
    q.add(kept, tmp_path / "second.pdf")
    q.write_placeholders()              # a first LaTeX pass's placeholder: the kept PDF itself
    assert (tmp_path / "second.pdf").read_bytes() == (tmp_path / "first.pdf").read_bytes()
    q.save(cache=cache)
    assert (tmp_path / "second.pdf").read_bytes() == (tmp_path / "first.pdf").read_bytes()
    assert cache.figures_reused == 1


def test_a_plot_whose_data_has_no_canonical_form_is_made_without_a_key():
    from latex_templates.figures import new_figure
    from latex_templates.figures.keyed import keyed_plot
    from latex_templates.figures.saving import content_key

    @keyed_plot()
    def odd(thing):
        return new_figure(4.0, 3.0)

    assert content_key(odd(object())) is None
