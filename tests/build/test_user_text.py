"""Issue 11, LaTeX escaping: every text field of the task holds TeX's special characters, quotes,
ligature pairs, Cyrillic, Ukrainian and Greek letters; the press builds and the PDF shows each as typed.

Was: a `%` ended the introduction at "100" (a TeX comment) and `& _ < >` failed the LaTeX run; the
mechanism name went through ``Markup.format`` (HTML escaping: ``<`` → ``&lt;``).
"""
from __future__ import annotations

import json
import re
import shutil
import subprocess
import sys
import unicodedata
from pathlib import Path

import pytest

from latex_templates.render import Tex, escape_latex

ROOT = Path(__file__).resolve().parents[2]
PRESS = ROOT / "examples" / "press" / "task.toml"
PIECES = (r"\ { } $ & # ^ _ ~ % < > |", '"двойные"', "'одинарные'", "«ёлочки»", "-- ---", "`` ''", "<< >>",
          "Пресс на 100% нагрузки;", "Київ, ґанок, є, ї;", "Ωμέγα αβγ")
TEXT = " ".join(PIECES)
FIELDS = ("title", "author", "group", "supervisor", "organization", "city")


def hostile_press() -> str:
    text = PRESS.read_text(encoding="utf-8")
    for key in FIELDS:
        text, n = re.subn(rf'^{key} = ".*"$', lambda _m, k=key: f"{k} = {json.dumps(k.upper() + ': ' + TEXT, ensure_ascii=False)}",
                          text, count=1, flags=re.M)
        assert n == 1, key
    text, n = re.subn(r'^name = ".*"$', lambda _m: f"name = {json.dumps('NAME: ' + TEXT, ensure_ascii=False)}",
                      text, count=1, flags=re.M)
    assert n == 1
    return text


def flat(pdf_text: str) -> str:
    """One line: TeX's hyphenation of words undone, line breaks as spaces, spaces collapsed; NFKC
    (the PDF's text layer gives U+037E for ';')."""
    t = re.sub(r"(?<=[^\W\d_])-\n(?=[^\W\d_])", "", pdf_text)
    return re.sub(r"\s+", " ", unicodedata.normalize("NFKC", t))


def test_tex_combines_like_markup_but_escapes_for_latex():
    assert Tex("{name}: 1").format(name="a<b & 100%") == r"a<b \& 100\%: 1"
    assert Tex("; ").join(["x_1", Tex(r"\alpha")]) == r"x\_1; \alpha"
    assert Tex("a ") + "$5" == r"a \$5"
    assert escape_latex("--") == "-{}-" and escape_latex('"') == r"\textquotedbl{}"


@pytest.mark.slow
def test_every_text_field_prints_literally(tmp_path):
    if shutil.which("latexmk") is None:
        pytest.fail("latexmk is not installed: run `make test` (it installs TeX Live)")
    task = tmp_path / "task.toml"
    task.write_text(hostile_press(), encoding="utf-8")
    out = tmp_path / "out"
    r = subprocess.run([sys.executable, "-m", "reportgen", "build", str(task), "-o", str(out), "--quiet"],
                       capture_output=True, text=True, cwd=ROOT, timeout=900)
    assert r.returncode == 0, r.stderr
    raw = subprocess.run(["pdftotext", str(out / "report.pdf"), "-"], capture_output=True, text=True,
                         check=True).stdout
    text = flat(raw)
    for field in [f.upper() for f in FIELDS] + ["NAME"]:
        assert f"{field}: " + PIECES[0] in text, field
    for piece in PIECES:
        # the title page, the assignment and the introduction print the fields: each piece at least 5 times (pdftotext joins a line that ends in "-" with the next)
        assert text.count(piece) >= 5, (piece, text.count(piece))
    assert "&lt;" not in text and "&amp;" not in text and "textbackslash" not in text
    # the introduction names the mechanism in full, not cut at the % (was: "... на 100")
    assert "NAME: " + TEXT[:40] in text and "Пресс на 100% нагрузки; Київ" in text
