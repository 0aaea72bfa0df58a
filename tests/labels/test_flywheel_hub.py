"""The flywheel's hub (issue 12: «the flywheel sketch has no bore»): the bore from the preliminary
torsion estimate d ≥ ∛(10³·T / (0,2·[τ])) rounded up to ГОСТ 6636 Ra 40, the key of ГОСТ 23360-78
for that diameter; both the sheet and the note draw it."""
from __future__ import annotations

import math

import ezdxf
import pytest

from reportgen.dynamics.hub import KEYS, RA40, TAU_ALLOWED, bore_outline, hub_of, key_row, section_rects


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


# --- the tables against their sources (reportgen/dynamics/hub.py's docstring) ------------------

#: ISO 3 / ГОСТ 8032-84 R40 mantissas (as tabulated by the ``renard`` package).
R40 = (1.00, 1.06, 1.12, 1.18, 1.25, 1.32, 1.40, 1.50, 1.60, 1.70, 1.80, 1.90, 2.00, 2.12, 2.24, 2.36,
       2.50, 2.65, 2.80, 3.00, 3.15, 3.35, 3.55, 3.75, 4.00, 4.25, 4.50, 4.75, 5.00, 5.30, 5.60, 6.00,
       6.30, 6.70, 7.10, 7.50, 8.00, 8.50, 9.00, 9.50)


def test_ra40_is_r40_rounded():
    # 20…95 are R40 2,00…9,50 of the decade 10…100, 100…500 are R40 1,00…5,00 of the next: one
    # normal size per R40 number, in order, each within 2 % of it
    expected = [m * 10 for m in R40 if m >= 2.0] + [m * 100 for m in R40 if m <= 5.0]
    assert len(RA40) == len(expected)
    for ra, r in zip(RA40, expected):
        assert abs(ra - r) <= 0.02 * r, (ra, r)
    assert 115 not in RA40 and {120, 125} <= set(RA40)     # ГОСТ 6636's decade 100…1000


@pytest.mark.parametrize("d_min, d", [(19.0, 20), (20.0, 20), (20.01, 21), (24.6, 25), (25.2, 26),
                                      (36.4, 38), (41.5, 42), (42.01, 45), (100.5, 105), (110.2, 120)])
def test_bore_rounds_up_to_ra40(d_min, d):
    torque = 0.2 * TAU_ALLOWED * (d_min / 1000.0) ** 3
    assert hub_of(torque, 2000.0).d == d


#: ГОСТ 23360-78 rows (d over, up to: b, h, t1, t2) as the two sources of hub.py print them, for the
#: ranges the examples' bores fall in and their neighbours.
GOLDEN_KEYS = {(17, 22): (6, 6, 3.5, 2.8), (22, 30): (8, 7, 4.0, 3.3), (30, 38): (10, 8, 5.0, 3.3),
               (38, 44): (12, 8, 5.0, 3.3), (44, 50): (14, 9, 5.5, 3.8), (50, 58): (16, 10, 6.0, 4.3),
               (95, 110): (28, 16, 10.0, 6.4), (440, 500): (100, 50, 31.0, 19.5)}


@pytest.mark.parametrize("rng", list(GOLDEN_KEYS))
def test_key_rows_and_their_boundaries(rng):
    lo, hi = rng
    want = GOLDEN_KEYS[rng]
    for d in (lo + 0.01, (lo + hi) / 2, hi):          # «свыше lo до hi»: hi belongs to the row
        assert key_row(d)[2:] == want, d
    if hi < KEYS[-1][1]:                               # the next row starts over hi
        above = key_row(hi + 0.01)
        assert above[0] == hi and above[2] > want[0]


@pytest.mark.parametrize("example, d, key", [("press", 42, (12, 8, 3.3)), ("shaper", 38, (10, 8, 3.3)),
                                             ("conveyor", 25, (8, 7, 3.3)), ("crank-slider", 26, (8, 7, 3.3)),
                                             ("class3", 20, (6, 6, 2.8))])
def test_every_example_hub(example, d, key):
    from reportgen.project import Project
    from reportgen.taskfile import load_task
    from .conftest import ROOT
    res = Project(load_task(ROOT / "examples" / example / "task.toml")).dynamics
    h = hub_of(res.M_drive, 2000.0 * res.flywheel.radius)
    assert (h.d, h.key_b, h.key_h, h.t2) == (d, *key)


def test_key_table_is_contiguous_and_grows():
    for a, b in zip(KEYS, KEYS[1:]):
        assert a[1] == b[0] and b[2] > a[2] and b[3] >= a[3] and b[5] >= a[5]
        assert a[5] < a[3] and a[4] < a[3]           # both slots shallower than the key is high
