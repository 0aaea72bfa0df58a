"""Section 3 of the note (dynamics): renders for every example with [dynamics], every record
re-evaluates from its printed numbers, the analysed position's M_red and J_red are the solver's, and
the PDF prints J_flywheel and the δ achieved of results.json."""
from __future__ import annotations

import json
import re
import subprocess
from pathlib import Path

import numpy as np
import pytest

from latex_templates import NoteBuilder
from latex_templates.compose import compose
from latex_templates.numbers import num
from latex_templates.parts import dynamics as part
from latex_templates.parts.kinematics import detail_position
from latex_templates.render import Strings
from reportgen.calc import evaluate_displayed
from reportgen.dynamics import ProjectCycle
from reportgen.project import Project
from reportgen.results import build_results, dumps
from reportgen.taskfile import load_task

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
def _russian(path) -> bool:
    """The examples written in Russian (these tests read Russian text; tests/lang covers uk and en)."""
    import tomllib
    return tomllib.loads(path.read_text(encoding="utf-8")).get("document", {}).get("language", "ru") == "ru"


NAMES = sorted(p.parent.name for p in EXAMPLES.glob("*/task.toml")
               if load_task(p).dynamics is not None and _russian(p))


@pytest.fixture(scope="module")
def projects():
    return {n: Project(load_task(EXAMPLES / n / "task.toml")) for n in NAMES}


def _content(project):
    """The part's context (its figures closed: only the numbers are looked at)."""
    import matplotlib.pyplot as plt

    pc = part.content(project)
    for fig in pc.figures.values():
        plt.close(fig)
    return pc.context


def _note(project):
    # section 1 too: section 3 refers to its velocity plan (\ref{sec:kin-vplan})
    sections, _ = compose(project, Strings("ru"), only=("linkage", "dynamics"))
    assert [s.parts for s in sections][-1] == ("dynamics",)
    note = NoteBuilder(project.task.document)
    for s in sections:
        note.add_section(s.section)
    return note


@pytest.mark.parametrize("name", NAMES)
def test_section_renders_and_every_record_reevaluates(name, projects, tmp_path):
    note = _note(projects[name])
    tex = note.render(tmp_path).read_text(encoding="utf-8")
    assert r"\subsection{Диаграмма энергомасс" in tex
    assert len(note.records) > 20
    for rec in note.records:
        assert evaluate_displayed(rec).ok, rec.symbol
    for fig in ("dyn_work", "dyn_wittenbauer", "dyn_omega", "dyn_flywheel"):
        assert (tmp_path / "figures" / f"dynamics-{fig.replace('_', '-')}.pdf").exists()


@pytest.mark.parametrize("name", NAMES)
def test_analysed_position_is_the_solvers(name, projects):
    project = projects[name]
    res = project.dynamics
    c = _content(project)
    i = detail_position(project)
    cycle = ProjectCycle(project, res.crank_inertia)
    r = cycle.reduced(np.array([cycle.theta_of(float(project.kinematics.phi[i]))]))
    # the powers use the angles as printed (to 0,01°, the course's precision): M_пр agrees with the
    # solver far within its printed four digits
    assert c["M_rec"].value == pytest.approx(float(r.M[0]), rel=2e-4, abs=1e-6)
    assert c["J_rec"].value == pytest.approx(float(r.J[0]), rel=1e-12)


@pytest.mark.parametrize("name", NAMES)
def test_numbers_are_the_results(name, projects):
    project = projects[name]
    res = project.dynamics
    c = _content(project)
    assert c["ex"]["J_ex"].value == pytest.approx(res.exact.J_fly, rel=1e-12)
    assert c["tg"]["J_gr"].value == pytest.approx(res.graphical.J_fly, rel=1e-12)
    assert c["mz"]["J_mz"].value == pytest.approx(res.merzalov.J_fly, rel=1e-12)
    assert c["mot"]["delta"].value == pytest.approx(res.delta_achieved, rel=1e-12)
    assert c["drv"]["M_d"].value == pytest.approx(res.M_drive, rel=1e-12)
    assert c["sc"]["mu_A"].value == pytest.approx(res.graphical.mu_A, rel=1e-12)
    assert c["tg"]["psi_max"].value == pytest.approx(res.graphical.psi_max_deg, rel=1e-12)
    if c["fw"]:
        assert c["fw"]["R"].value == pytest.approx(res.flywheel.radius, rel=1e-12)
        assert c["fw"]["m"].value == pytest.approx(res.flywheel.mass, rel=1e-9)
    # the exact method gives the target δ; the others' δ comes from their own flywheel
    rows = {r.key: r for r in c["methods"]}
    assert rows["exact"].delta == pytest.approx(res.delta_target, rel=1e-6)
    for key in ("merzalov", "graphical"):
        more = rows[key].J > rows["exact"].J
        assert (rows[key].delta < res.delta_target) == more


def test_table_rows_are_the_graphs_positions(projects):
    project = projects["press"]
    c = _content(project)
    g = project.dynamics.graphical
    assert len(c["rows"]) == g.theta.size - 1
    assert [r[0] for r in c["rows"]].count("к.р.х.") == 1
    assert [r[3] for r in c["rows"]] == pytest.approx(list(g.M_mm[:-1]))


@pytest.mark.slow
def test_pdf_prints_the_results(projects, tmp_path):
    project = projects["press"]
    note = _note(project)
    report = note.build(tmp_path)
    text = subprocess.run(["pdftotext", "-layout", str(report.pdf), "-"], capture_output=True, text=True,
                          check=True).stdout.replace("\u037e", ";")
    results = json.loads(dumps(build_results(project)))["dynamics"]
    J, delta = (num(results[k]).replace("{,}", ",") for k in ("J_flywheel", "delta_achieved"))
    assert re.search(rf"Точный\s+{re.escape(J)}\s+—\s+{re.escape(delta)}", text), (J, delta)
    assert f"= {J} кг" in text          # the record of the exact J_fly
    # the record of δ achieved: δ′ = (ω′max − ω′min)/ω′m = … = δ   (3.n); pdftotext puts the prime
    # inline or a line above, depending on the horizontal position of the display
    assert re.search(rf"𝛿′? =.*= {re.escape(delta)}\s+\(\d+\.\d+\)", text)
