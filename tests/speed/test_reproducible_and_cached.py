"""Issue 16: the same task gives the same bytes whatever PYTHONHASHSEED, the working directory or
the moment of the build, and the build cache never changes an output (cached = uncached, byte for
byte, for an unchanged task and for a task with one changed number: δ, a mass, a number of the
gear pair, each edited in the same task file as a student iterating on a variant does)."""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PRESS = ROOT / "examples" / "press" / "task.toml"

pytestmark = pytest.mark.slow
#: What the build says when LaTeX's first pass began on the last build's preamble (docs/build.md).
KEPT_PREAMBLE = "(the first begun on the kept preamble)"


def build(task: Path, out: Path, *, seed: str, cwd: Path, cache: Path | str, extra: tuple[str, ...] = ()):
    env = dict(os.environ, PYTHONHASHSEED=seed, REPORTGEN_CACHE=str(cache))
    r = subprocess.run([sys.executable, "-m", "reportgen", "build", str(task), "-o", str(out), *extra],
                       cwd=cwd, env=env, capture_output=True, text=True, timeout=900)
    assert r.returncode == 0, r.stderr + r.stdout
    return r


def files(out: Path) -> dict[str, bytes]:
    """Every output a user gets (LaTeX's working folder aside: its log names the folder; the
    manifest is compared without its lines of that folder)."""
    found = {p.relative_to(out).as_posix(): p.read_bytes() for p in sorted(out.rglob("*"))
             if p.is_file() and "latex-build" not in p.parts}
    from reportgen.commands.outdir import MANIFEST_NAME
    if MANIFEST_NAME in found:
        found[MANIFEST_NAME] = b"\n".join(line for line in found[MANIFEST_NAME].splitlines()
                                          if b"latex-build" not in line)
    return found


def assert_same(a: dict[str, bytes], b: dict[str, bytes]) -> None:
    assert sorted(a) == sorted(b)
    differ = [name for name in a if a[name] != b[name]]
    assert not differ, f"different bytes: {differ}"


@pytest.fixture(scope="module")
def builds(tmp_path_factory):
    if shutil.which("latexmk") is None:
        pytest.fail("latexmk is not installed: run `make test` (it installs TeX Live)")
    base = tmp_path_factory.mktemp("repro")
    cache = base / "cache"
    work = base / "work"
    work.mkdir()
    task = work / "task.toml"
    shutil.copyfile(PRESS, task)
    out = {}
    # an uncached build from the source tree, hash seed 1
    build(PRESS, base / "plain", seed="1", cwd=ROOT, cache="off")
    out["plain"] = files(base / "plain")
    # a cold build that fills the cache, seed 4 (which orders sets of names unlike seed 1), from another folder
    r = build(task, base / "cold", seed="4", cwd=work, cache=cache)
    out["cold"] = files(base / "cold")
    out["cold_stdout"] = r.stdout
    # unchanged task: from the cache
    r = build(task, base / "warm", seed="3", cwd=base, cache=cache)
    out["warm"] = files(base / "warm")
    out["warm_stdout"] = r.stdout
    # one number changed: δ 0.05 → 0.04; cached (LaTeX's aux files and the unchanged previews reused) …
    task.write_text(task.read_text(encoding="utf-8").replace("delta = 0.05", "delta = 0.04"), encoding="utf-8")
    r = build(task, base / "changed-cached", seed="4", cwd=work, cache=cache)
    out["changed-cached"] = files(base / "changed-cached")
    out["changed_stdout"] = r.stdout
    # … and again with the whole output's entry gone: everything else from the cache, LaTeX from the
    # aux files of this very document (a fixed point: one pass, whatever δ did to the pages)
    shutil.rmtree(cache / "builds")
    r = build(task, base / "changed-again", seed="2", cwd=work, cache=cache)
    out["changed-again"] = files(base / "changed-again")
    out["again_stdout"] = r.stdout
    # … and uncached
    build(task, base / "changed-plain", seed="5", cwd=ROOT, cache="off")
    out["changed-plain"] = files(base / "changed-plain")
    # the mass of link 5 (the slider) changed in the same task file (δ 0.04 still): cached — LaTeX's
    # first pass started on the kept preamble —, then uncached
    text = PRESS.read_text(encoding="utf-8")
    assert text.count("mass = 45.0") == 1                # link 5's mass in examples/press/task.toml
    task.write_text(task.read_text(encoding="utf-8").replace("mass = 45.0", "mass = 46.0"), encoding="utf-8")
    r = build(task, base / "mass-cached", seed="6", cwd=work, cache=cache)
    out["mass-cached"] = files(base / "mass-cached")
    out["mass_stdout"] = r.stdout
    build(task, base / "mass-plain", seed="7", cwd=ROOT, cache="off")
    out["mass-plain"] = files(base / "mass-plain")
    # a number of the gear pair changed in the same file (x1 0.63 → 0.6): only section 4 and sheet 4
    # reach it
    assert text.count("x1 = 0.63") == 1
    task.write_text(task.read_text(encoding="utf-8").replace("x1 = 0.63", "x1 = 0.6"), encoding="utf-8")
    r = build(task, base / "gear-cached", seed="10", cwd=work, cache=cache)
    out["gear-cached"] = files(base / "gear-cached")
    out["gear_stdout"] = r.stdout
    build(task, base / "gear-plain", seed="11", cwd=ROOT, cache="off")
    out["gear-plain"] = files(base / "gear-plain")
    # the note's language changed (Ukrainian) in the same file: cached (every key names the language;
    # LaTeX's first pass, started on the last build's Russian preamble, is stopped and started on the
    # note), then uncached
    assert text.count('language = "ru"') == 1
    task.write_text(task.read_text(encoding="utf-8").replace('language = "ru"', 'language = "uk"'), encoding="utf-8")
    r = build(task, base / "lang-cached", seed="8", cwd=work, cache=cache)
    out["lang-cached"] = files(base / "lang-cached")
    out["lang_stdout"] = r.stdout
    build(task, base / "lang-plain", seed="9", cwd=ROOT, cache="off")
    out["lang-plain"] = files(base / "lang-plain")
    out["cache"] = cache
    return out


def test_same_bytes_whatever_the_hash_seed_and_the_folder(builds):
    assert_same(builds["plain"], builds["cold"])
    assert any(name.endswith(".dxf") for name in builds["plain"])   # the sheets are compared too


def test_an_unchanged_task_comes_from_the_cache_with_the_same_bytes(builds):
    assert "from the cache" in builds["warm_stdout"]
    assert_same(builds["plain"], builds["warm"])


def test_a_changed_number_rebuilt_with_the_cache_equals_an_uncached_build(builds):
    assert builds["changed-plain"]["results.json"] != builds["plain"]["results.json"]
    assert_same(builds["changed-plain"], builds["changed-cached"])
    # the kinematics sheet does not depend on δ: its preview came from the cache, the same bytes
    assert builds["changed-cached"]["sheets/sheet1-kinematics.png"] == builds["plain"]["sheets/sheet1-kinematics.png"]
    # δ reaches the dynamics only: sheets 1, 2, 4 come from the cache, sheet 3 is drawn again; the
    # note's sections 1, 2, 4 are taken from the cache, section 3 is composed again
    assert sheets_line(builds["changed_stdout"]) == (3, 4)
    assert sections_line(builds["changed_stdout"]) == (3, 4)
    assert "sheet 3: sheet3-dynamics (from the cache)" not in builds["changed_stdout"]
    # LaTeX starts from the aux files of the build before (the same task file): two passes where δ
    # moved the pages, one where it did not; rebuilt from its own aux files and kept figures, one
    assert re.search(r"xelatex passes: [12]\b", builds["changed_stdout"]), builds["changed_stdout"]
    assert KEPT_PREAMBLE in builds["changed_stdout"]
    assert_same(builds["changed-plain"], builds["changed-again"])
    assert sheets_line(builds["again_stdout"]) == (4, 4)
    assert sections_line(builds["again_stdout"]) == (4, 4)
    assert re.search(r"figures: 25 from the cache, 0 saved and kept", builds["again_stdout"]), builds["again_stdout"]
    assert re.search(r"xelatex passes: 1\b", builds["again_stdout"]), builds["again_stdout"]


def figures_line(stdout: str) -> tuple[int, int]:
    """(reused, saved) from the build's line «figures: N from the cache, M saved and kept»."""
    m = re.search(r"figures: (\d+) from the cache, (\d+) saved and kept", stdout)
    assert m, f"no figures line in the build's output:\n{stdout}"
    return int(m.group(1)), int(m.group(2))


def sections_line(stdout: str) -> tuple[int, int]:
    """(from the cache, sections) from the build's line «…; sections: J of T from the cache»."""
    m = re.search(r"sections: (\d+) of (\d+) from the cache", stdout)
    assert m, f"no sections line in the build's output:\n{stdout}"
    return int(m.group(1)), int(m.group(2))


def sheets_line(stdout: str) -> tuple[int, int]:
    """(from the cache, sheets) from the build's line «…; sheets: K of S from the cache»."""
    m = re.search(r"sheets: (\d+) of (\d+) from the cache", stdout)
    assert m, f"no sheets line in the build's output:\n{stdout}"
    return int(m.group(1)), int(m.group(2))


def test_a_changed_mass_reuses_the_figures_whose_scene_did_not_change(builds):
    assert builds["mass-plain"]["results.json"] != builds["plain"]["results.json"]
    assert_same(builds["mass-plain"], builds["mass-cached"])
    _, keyed = figures_line(builds["cold_stdout"])            # the scene figures of the press
    reused, saved = figures_line(builds["mass_stdout"])
    # the mechanism's positions, velocity and acceleration plans (two positions) and the kinematic
    # diagrams do not depend on a mass: their six scene figures come from the cache …
    kinematics = [n for n in builds["mass-plain"] if n.startswith("figures/linkage-kin-")]
    assert len(kinematics) == 6
    assert all(builds["mass-plain"][n] == builds["plain"][n] for n in kinematics)
    assert reused >= len(kinematics)
    # … the force polygons and the lever do: those are saved again (and every figure is one or the other)
    assert builds["mass-plain"]["figures/kinetostatics-kst-lever.pdf"] != builds["plain"]["figures/kinetostatics-kst-lever.pdf"]
    assert saved >= 1
    assert reused + saved == keyed
    # every figure of the note has a key now, the plots too (keyed by their data)
    assert keyed == sum(n.startswith("figures/") for n in builds["plain"])
    # the plots that draw no mass — the structural schemes, the gear pair's, the planetary scheme —
    # are copied, not made: each is in the cache by then and the same bytes as before
    plots = ["linkage-structure-scheme", "linkage-structure-group1", "linkage-structure-group2",
             "assignment-assignment-scheme", "gears-gear-pair-meshing", "gears-gear-pair-sliding",
             "gears-planetary-scheme"]
    assert all(builds["mass-plain"][f"figures/{n}.pdf"] == builds["plain"][f"figures/{n}.pdf"] for n in plots)
    assert reused >= len(kinematics) + len(plots)
    # the kinematics and gear sheets do not depend on a mass: copied from the cache, not drawn; the
    # kinetostatics and dynamics sheets are drawn again (and differ)
    assert sheets_line(builds["mass_stdout"]) == (2, 4)
    # the note: the linkage's section (no mass read) and the gears' from the cache; the
    # kinetostatics and dynamics composed again; LaTeX from the last build's aux files and preamble
    assert sections_line(builds["mass_stdout"]) == (2, 4)
    assert re.search(r"xelatex passes: [12]\b", builds["mass_stdout"]), builds["mass_stdout"]
    assert KEPT_PREAMBLE in builds["mass_stdout"]
    for stem in ("sheet1-kinematics", "sheet4-gears"):
        assert f"{stem} (from the cache)" in builds["mass_stdout"]
    for stem in ("sheet2-kinetostatics", "sheet3-dynamics"):
        assert f"{stem} (from the cache)" not in builds["mass_stdout"]
        assert builds["mass-plain"][f"sheets/{stem}.dxf"] != builds["plain"][f"sheets/{stem}.dxf"]


def test_a_changed_gear_number_redoes_only_the_gears_section_and_sheet(builds):
    assert builds["gear-plain"]["results.json"] != builds["mass-plain"]["results.json"]
    assert_same(builds["gear-plain"], builds["gear-cached"])
    assert sheets_line(builds["gear_stdout"]) == (3, 4)
    assert "sheet4-gears (from the cache)" not in builds["gear_stdout"]
    assert sections_line(builds["gear_stdout"]) == (3, 4)
    assert re.search(r"xelatex passes: [12]\b", builds["gear_stdout"]), builds["gear_stdout"]
    assert KEPT_PREAMBLE in builds["gear_stdout"]
    # the figures of sections 1–3 are the mass build's bytes; the gear pair's meshing is drawn again
    same = [n for n in builds["gear-plain"] if n.startswith(("figures/linkage-", "figures/kinetostatics-",
                                                             "figures/dynamics-"))]
    assert same and all(builds["gear-plain"][n] == builds["mass-plain"][n] for n in same)
    assert builds["gear-plain"]["figures/gears-gear-pair-meshing.pdf"] != builds["mass-plain"]["figures/gears-gear-pair-meshing.pdf"]


def test_a_changed_language_reuses_nothing_that_has_words(builds):
    assert_same(builds["lang-plain"], builds["lang-cached"])
    assert sheets_line(builds["lang_stdout"]) == (0, 4)
    assert sections_line(builds["lang_stdout"]) == (0, 4)
    assert KEPT_PREAMBLE not in builds["lang_stdout"]      # another preamble: that pass stopped, one on the note
    reused, _ = figures_line(builds["lang_stdout"])
    same = [n for n in builds["lang-plain"] if n.startswith("figures/") and builds["lang-plain"][n] == builds["plain"].get(n)]
    assert reused <= len(same)          # a figure from the cache is one whose bytes the language does not change


def test_the_cache_holds_only_its_own_folders(builds):
    """jinja/ only where a template or snippet was not in the install-time store (latex_templates/precompiled.py)."""
    from latex_templates.precompiled import STORE

    folders = sorted(p.name for p in builds["cache"].iterdir())
    assert [f for f in folders if f != "jinja"] == ["builds", "figures", "previews", "scenes", "sections", "sheets", "subsets", "tex"]
    if not STORE.is_file():            # every template compiled by the build, and kept
        assert "jinja" in folders
