"""Issue 11: the scheme scales cover ГОСТ 2.302 reductions and enlargements for every length the loader
accepts; the press scaled ×0.001 and ×100 builds (was: the scheme scales stopped at 1:100 and the
message asked the user to change a scale no option sets)."""
from __future__ import annotations

import re
from pathlib import Path

import ezdxf
import pytest

from reportgen import gost_scales
from reportgen.cli import main
from reportgen.taskfile import MAX_LENGTH, MIN_LENGTH

ROOT = Path(__file__).resolve().parents[1]
PRESS = ROOT / "examples" / "press" / "task.toml"
SCHEME_MM = 450.0   # about the room of sheet 1's scheme


def test_the_list_is_gost_2_302():
    labels = [gost_scales.label(s) for s in gost_scales.GOST_2_302]
    assert labels[:9] == ["100:1", "50:1", "40:1", "20:1", "10:1", "5:1", "4:1", "2,5:1", "2:1"]
    assert "1:1" in labels and labels[-1] == "1:50000"
    for r in ("1:2,5", "1:15", "1:75", "1:200", "1:400", "1:800", "1:1000", "1:2000", "1:25000"):
        assert r in labels
    f = [gost_scales.factor(s) for s in gost_scales.GOST_2_302]
    assert f == sorted(f, reverse=True)


@pytest.mark.parametrize("extent_m", [MIN_LENGTH, 3 * MIN_LENGTH, 1e-4, 0.013, 0.7, 12.0, 450.0, 2 * MAX_LENGTH])
def test_every_accepted_length_has_a_scale_that_fits(extent_m):
    s = gost_scales.largest_fitting(SCHEME_MM / (1000.0 * extent_m))
    drawn = 1000.0 * extent_m * gost_scales.factor(s)
    assert drawn <= SCHEME_MM * (1 + 1e-9)
    assert drawn >= SCHEME_MM / 2.5 - 1e-9, (gost_scales.label(s), drawn)   # not needlessly small
    if s not in gost_scales.GOST_2_302:
        assert s[1] == 1 and s[0] % 100 == 0                                    # (100·n):1


def similar_press(k: float) -> str:
    """The press scaled ×k with dynamic similarity (masses k³, inertias k⁵, forces k⁴, q k², no
    gravity): every diagram keeps its proportions, only the lengths (and so the drawing scales) change."""
    t = PRESS.read_text(encoding="utf-8")
    def sc(x: str, p: int) -> str:
        return repr(float(x) * k ** p)
    t = re.sub(r"^([A-Z]) = \[([-\d.e]+), ([-\d.e]+)\]",
               lambda m: f"{m.group(1)} = [{sc(m.group(2), 1)}, {sc(m.group(3), 1)}]", t, flags=re.M)
    t = re.sub(r"through = \[([-\d.e]+), ([-\d.e]+)\]",
               lambda m: f"through = [{sc(m.group(1), 1)}, {sc(m.group(2), 1)}]", t)
    for key, p in (("length", 1), ("mass", 3), ("inertia", 5), ("crank_inertia", 5), ("force", 4), ("q", 2)):
        t, n = re.subn(rf"^{key} = ([\d.e]+)", lambda m, key=key, p=p: f"{key} = {sc(m.group(1), p)}", t, flags=re.M)
        assert n, key
    return re.sub(r"^g = [\d.]+", "g = 0.0", t, flags=re.M)


@pytest.mark.slow
@pytest.mark.parametrize("k, scheme", [(0.001, "400:1"), (100.0, "1:400")])
def test_scaled_press_builds(tmp_path, capsys, k, scheme):
    task = tmp_path / "task.toml"
    task.write_text(similar_press(k), encoding="utf-8")
    out = tmp_path / "out"
    code = main(["build", str(task), "-o", str(out), "--quiet", "--no-pdf"])
    assert code == 0, capsys.readouterr().err
    sheets = sorted((out / "sheets").glob("*.dxf"))
    assert len(sheets) == 4
    texts = [e.dxf.text for e in ezdxf.readfile(sheets[0]).modelspace().query("TEXT")]
    assert f"схема, М {scheme}" in texts
    listed = {gost_scales.label(s) for s in gost_scales.GOST_2_302}
    fly = [t for t in (e.dxf.text for e in ezdxf.readfile(sheets[2]).modelspace().query("TEXT"))
           if t.startswith("Эскиз маховика")]
    assert fly and fly[0].split("М ")[-1] in listed


def test_a_scale_prints_its_ratio_in_a_given_decimal_mark():
    """One home for a scale's ratio in the document's mark (issue 12: the English note printed the
    meshing's «2,5:1»; the note, the sheets and the |ratio filter each patched the core's text with
    their own ``replace``): Scale.text, and every factor/text the core holds back to its Scale."""
    assert gost_scales.Scale(1, 2.5).text() == "1:2,5" and gost_scales.Scale(1, 2.5).text(".") == "1:2.5"
    assert gost_scales.Scale(2.5, 1).text(".") == "2.5:1" and gost_scales.Scale(200, 1).text(".") == "200:1"
    for s in gost_scales.GOST_2_302:
        assert gost_scales.Scale.of_factor(gost_scales.factor(s)) == s
        for mark in (",", "."):
            text = gost_scales.Scale(*s).text(mark)
            assert gost_scales.Scale.parse(text) == s
            assert ("," if mark == "." else ".") not in text
    for bad in ("2,5", "1:0", ":", "a:b", "1:-2"):
        with pytest.raises(ValueError, match="scale"):
            gost_scales.Scale.parse(bad)
    with pytest.raises(ValueError):
        gost_scales.Scale.of_factor(0.0)


def test_every_renderer_prints_a_ratio_through_the_one_home():
    """No renderer re-marks a scale's text by hand (``.replace(",", …)`` on a ratio): the meshing's
    caption, the polygons' detail headings (note and sheet), the planetary sheet and the |ratio
    filter all go through :meth:`reportgen.gost_scales.Scale.text`."""
    from reportgen.scenes.meshing import DrawingScale
    assert DrawingScale(2.5).text(".") == "2.5:1" and DrawingScale(0.4).text() == "1:2,5"
    assert DrawingScale(0.4).label == "1:2,5"
    root = ROOT
    hand = re.compile(r"(ratio\w*|label|scale\w*)\.replace\(")
    found = [f"{p.relative_to(root)}:{n}" for p in [*root.glob("latex_templates/**/*.py"), *root.glob("drawings/**/*.py")]
             for n, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1) if hand.search(line)]
    assert not found, found
