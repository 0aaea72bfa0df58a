"""Names with indices are lettered as the note prints them (issue 12: sheet 2 printed «Rτ24», «Fи4'»,
«G4» inline where the note prints R^τ_24, F′_и4, G_4; sheet 4 «rb1», «αw»): read back from the DXF
of every example's sheet 2 (the groups, the crank, the polygons, the lever) and sheet 4 (the
meshing picture), each scene name with an index is not one inline TEXT, and its index is a TEXT
of its own one ГОСТ size smaller, below (a subscript) or above (a superscript) its base."""
from __future__ import annotations

import pytest

from drawings.lettering import from_tex
from drawings.words import language, use_catalogue
from latex_templates.render import Strings

from scene_readback import draw_named_sheet, example_project, sheet_cases

from .conftest import EXAMPLES


def _symbols(project, stem: str) -> set[str]:
    """The note's symbols with an index that sheet ``stem`` names (its scenes' labels)."""
    out: set[str] = set()
    if "kinetostatics" in stem:
        from reportgen.scenes.forces import polygon_scene
        from reportgen.scenes.lever import lever_scene
        g = project.kinetostatics.graphical
        scenes = [polygon_scene(gg.polygon) for gg in g.groups] + [polygon_scene(g.crank.polygon)]
        scenes += [fb.scene for fb in project.scenes.free_bodies]
        scenes.append(lever_scene(project.kinetostatics, project.linkage))
        for sc in scenes:
            out |= {lb.text for lb in sc.labels if lb.role == "vector" and not lb.anchor.startswith("arm:")}
    elif "gears" in stem:
        out |= {m.tex for m in project.scenes.meshing.marks.marks if not m.word}
    return {t for t in out if "_" in t or "^" in t}


@pytest.mark.slow
@pytest.mark.parametrize("name,stem", sheet_cases([n for n in EXAMPLES if "crane" not in n],
                                                  lambda stem: "kinetostatics" in stem or "gears" in stem))
def test_names_with_indices_are_lettered_with_indices(name, stem, tmp_path):
    project = example_project(name)
    _sheet, doc = draw_named_sheet(name, stem, tmp_path)
    texts = [(e.plain_text(), float(e.dxf.height), float(e.dxf.insert[1])) for e in doc.modelspace().query("TEXT")]
    use_catalogue(Strings)
    with language(project.task.document.language):
        riches = {tex: from_tex(tex) for tex in _symbols(project, stem)}
    assert riches
    found = []
    for tex, r in sorted(riches.items()):
        inline = r.base + r.sup + r.sub
        if any(t == inline for t, _, _ in texts):
            found.append(f"{tex} lettered inline as «{inline}»")
        bases = [(h, y) for t, h, y in texts if t == r.base]
        for index, sign in ((r.sub, -1.0), (r.sup, 1.0)):
            if not index:
                continue
            small = [(h, y) for t, h, y in texts if t == index]
            if not any(hs < hb and (ys - yb) * sign > 0 for hs, ys in small for hb, yb in bases):
                found.append(f"{tex}: no index «{index}» smaller and {'below' if sign < 0 else 'above'} «{r.base}»")
    assert not found, "\n".join(found)
