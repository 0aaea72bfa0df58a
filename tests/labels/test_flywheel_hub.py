"""The flywheel's hub (issue 12: «the flywheel sketch has no bore»): the bore from the preliminary
torsion estimate d ≥ ∛(10³·T / (0,2·[τ])) rounded up to ГОСТ 6636 Ra 40, the key of ГОСТ 23360-78
for that diameter; both the sheet and the note draw it."""
from __future__ import annotations

import math

import ezdxf
import pytest

from reportgen.dynamics.hub import RA40, bore_outline, hub_of, section_rects


def test_press_shaft_by_hand():
    # 286,7 Н·м: ∛(286 700 / (0,2·20)) = ∛71 675 = 41,54 мм → 42 мм; ГОСТ 23360-78 for d over 38 up
    # to 44 mm: b × h = 12 × 8, t2 = 3,3 mm
    h = hub_of(286.7, 685.0)
    assert h.d_min == pytest.approx(41.539, abs=1e-3)
    assert (h.d, h.key_b, h.key_h, h.t2) == (42.0, 12.0, 8.0, 3.3)
    assert h.hub_d == pytest.approx(1.6 * 42.0)


@pytest.mark.parametrize("torque", [1.0, 50.0, 286.7, 1e3, 2.5e4])
def test_bore_is_the_next_normal_size_and_key_fits(torque):
    h = hub_of(torque, 2000.0)
    assert h.d >= h.d_min or h.d == RA40[-1]
    smaller = [x for x in RA40 if x < h.d]
    assert not smaller or smaller[-1] < h.d_min or h.d == RA40[0]
    assert h.key_b < h.d and h.t2 < h.key_h


def test_section_leaves_the_bore_and_slot_open():
    h = hub_of(286.7, 685.0)
    rects = section_rects(342.5, 0.0, 343.0, h)
    solid = sum((x1 - x0) * (y1 - y0) for x0, y0, x1, y1 in rects)
    assert solid == pytest.approx(343.0 * (685.0 - h.d - h.t2))
    pts = bore_outline(h)
    assert max(y for _, y in pts) == pytest.approx(h.d / 2 + h.t2)
    assert min(math.hypot(x, y) for x, y in pts) == pytest.approx(h.d / 2, rel=1e-3)


def test_sheet3_draws_the_bore(tmp_path):
    from drawings.sheets import dynamics
    from reportgen.project import Project
    from reportgen.taskfile import load_task
    from .conftest import ROOT
    project = Project(load_task(ROOT / "examples" / "press" / "task.toml"))
    dynamics.draw(project, 3, 4).save(tmp_path / "s.dxf")
    texts = {e.dxf.text for e in ezdxf.readfile(tmp_path / "s.dxf").modelspace().query("TEXT")}
    dims = set()
    for d in ezdxf.readfile(tmp_path / "s.dxf").modelspace().query("DIMENSION"):
        dims.add(d.dxf.text)
    assert "Ø42" in dims and "12" in dims and "45,3" in dims, (dims, texts)
