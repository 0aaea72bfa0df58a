"""Issue 11, output folders: ``build`` writes only into a new or empty folder or an earlier reportgen
output (its manifest); everything else is refused with exit 2 and every byte of the user's left as it
was. Each case compares the whole tmp folder byte for byte before and after.

A gear-only task with ``--no-pdf --no-sheets`` keeps each build at ~1 s.
"""
from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from reportgen.cli import main
from reportgen.commands.outdir import MANIFEST_FORMAT, MANIFEST_NAME

GEARS = "[gears]\nz1 = 13\nz2 = 26\nmodule = 9.0\nx1 = 0.63\nx2 = 0.67\n"
FAST = ["--quiet", "--no-pdf", "--no-sheets"]


def snapshot(root: Path) -> dict[str, bytes | str]:
    """Every file (its bytes), folder and link below ``root``."""
    found: dict[str, bytes | str] = {}
    for dirpath, dirs, files in os.walk(root):
        for name in dirs + files:
            p = Path(dirpath) / name
            rel = p.relative_to(root).as_posix()
            if p.is_symlink():
                found[rel] = "link→" + os.readlink(p)
            elif p.is_dir():
                found[rel] = "dir"
            else:
                found[rel] = p.read_bytes()
    return found


@pytest.fixture
def student(tmp_path):
    """A student's folder: the task and a thesis beside it."""
    d = tmp_path / "work"
    d.mkdir()
    (d / "task.toml").write_text(GEARS, encoding="utf-8")
    (d / "thesis.txt").write_text("три месяца работы\n", encoding="utf-8")
    return d


def build(task: Path, out, capsys, *extra: str) -> tuple[int, str]:
    code = main(["build", str(task), "-o", str(out), *FAST, *extra])
    return code, capsys.readouterr().err


def refused(tmp_path, task, out, capsys, *fragments: str, extra: tuple[str, ...] = ()) -> str:
    before = snapshot(tmp_path)
    code, err = build(task, out, capsys, *extra)
    assert code == 2, err
    assert err.startswith("reportgen build: error: --out") and "Traceback" not in err
    for f in fragments:
        assert f in err, (f, err)
    assert snapshot(tmp_path) == before, "the user's files changed"
    return err


def test_cwd_as_output_is_refused(tmp_path, student, capsys, monkeypatch):
    """Was: `build task.toml -o .` deleted task.toml and thesis.txt, exit 0."""
    monkeypatch.chdir(student)
    refused(tmp_path, Path("task.toml"), ".", capsys, "the folder that holds the task file", "nothing was written")


def test_cwd_without_task_is_refused(tmp_path, student, capsys, monkeypatch):
    """`-o .` in a folder with other files than the task: the current folder is never replaced."""
    here = tmp_path / "here"
    here.mkdir()
    (here / "notes.md").write_text("мои заметки", encoding="utf-8")
    monkeypatch.chdir(here)
    refused(tmp_path, student / "task.toml", ".", capsys, "the current folder")


def test_empty_cwd_is_refused_too(tmp_path, student, capsys, monkeypatch):
    here = tmp_path / "empty"
    here.mkdir()
    monkeypatch.chdir(here)
    refused(tmp_path, student / "task.toml", ".", capsys, "the current folder")


def test_folder_holding_the_task_is_refused(tmp_path, student, capsys):
    refused(tmp_path, student / "task.toml", student, capsys, "the folder that holds the task file")


def test_parent_of_the_task_folder_is_refused(tmp_path, student, capsys):
    refused(tmp_path, student / "task.toml", tmp_path, capsys, "above the task file's folder")


def test_folder_with_other_files_is_refused(tmp_path, student, capsys):
    """Was: `-o d2` deleted everything in d2."""
    d2 = tmp_path / "d2"
    (d2 / "sub").mkdir(parents=True)
    (d2 / "draft.docx").write_bytes(b"PK\x03\x04 draft")
    (d2 / "sub" / "photo.jpg").write_bytes(bytes(range(256)))
    refused(tmp_path, student / "task.toml", d2, capsys, "did not write", "draft.docx")


def test_existing_file_is_refused(tmp_path, student, capsys):
    """Was: `-o thesis.txt` turned the file into the output folder."""
    refused(tmp_path, student / "task.toml", student / "thesis.txt", capsys, "it is a file")


def test_symbolic_link_is_refused(tmp_path, student, capsys):
    target = tmp_path / "real"
    target.mkdir()
    (target / "keep.txt").write_text("keep", encoding="utf-8")
    (tmp_path / "link").symlink_to(target)
    refused(tmp_path, student / "task.toml", tmp_path / "link", capsys, "symbolic link")


def test_new_and_empty_folders_are_accepted_and_get_a_manifest(tmp_path, student, capsys):
    for out in (tmp_path / "new", tmp_path / "empty"):
        if out.name == "empty":
            out.mkdir()
        code, err = build(student / "task.toml", out, capsys)
        assert code == 0, err
        manifest = json.loads((out / MANIFEST_NAME).read_text(encoding="utf-8"))
        assert manifest["format"] == MANIFEST_FORMAT
        written = {p.relative_to(out).as_posix() for p in out.rglob("*") if p.is_file()} - {MANIFEST_NAME}
        assert set(manifest["files"]) == written and "report.tex" in written
    assert sorted(p.name for p in tmp_path.iterdir()) == ["empty", "new", "work"]


def test_earlier_output_is_replaced(tmp_path, student, capsys):
    out = tmp_path / "out"
    assert build(student / "task.toml", out, capsys)[0] == 0
    (out / "report.tex").unlink()  # a file reportgen wrote and the user deleted: still reportgen's folder
    student_before = snapshot(student)
    code, err = build(student / "task.toml", out, capsys)
    assert code == 0, err
    assert (out / "report.tex").is_file()
    assert snapshot(student) == student_before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out", "work"]


def test_earlier_output_with_a_users_file_is_refused(tmp_path, student, capsys):
    out = tmp_path / "out"
    assert build(student / "task.toml", out, capsys)[0] == 0
    (out / "figures" / "my-sketch.png").write_bytes(b"\x89PNG user")
    refused(tmp_path, student / "task.toml", out, capsys, "figures/my-sketch.png")


def test_earlier_output_with_an_edited_file_is_refused(tmp_path, student, capsys):
    out = tmp_path / "out"
    assert build(student / "task.toml", out, capsys)[0] == 0
    with open(out / "report.tex", "a", encoding="utf-8") as f:
        f.write("% my corrections\n")
    refused(tmp_path, student / "task.toml", out, capsys, "report.tex (changed since reportgen wrote it)")


def test_manifest_of_another_format_is_refused(tmp_path, student, capsys):
    out = tmp_path / "out"
    out.mkdir()
    (out / MANIFEST_NAME).write_text('{"format": "something-else/9", "files": {}}', encoding="utf-8")
    (out / "x.txt").write_text("x", encoding="utf-8")
    refused(tmp_path, student / "task.toml", out, capsys, "not of the format")


def test_failed_build_never_replaces_a_users_out_failed(tmp_path, student, capsys):
    """A failed LaTeX run keeps OUT.failed/; a user's OUT.failed/ (no manifest) stays as it was."""
    out = tmp_path / "out"
    mine = tmp_path / "out.failed"
    mine.mkdir()
    (mine / "important.txt").write_text("не трогать", encoding="utf-8")
    before = snapshot(mine)
    code = main(["build", str(student / "task.toml"), "-o", str(out), "--quiet", "--no-sheets",
                 "--latexmk", str(tmp_path / "no-such-latexmk")])
    err = capsys.readouterr().err
    assert code == 1 and "Traceback" not in err
    assert snapshot(mine) == before
    kept = tmp_path / "out.failed-2"
    assert (kept / "report.tex").is_file() and str(kept) in err
    assert not out.exists()
    # a second failure replaces the earlier failed build (it has a manifest), still not the user's folder
    (kept / "report.tex").unlink()
    code = main(["build", str(student / "task.toml"), "-o", str(out), "--quiet", "--no-sheets",
                 "--latexmk", str(tmp_path / "no-such-latexmk")])
    capsys.readouterr()
    assert code == 1 and (kept / "report.tex").is_file()
    assert snapshot(mine) == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.failed", "out.failed-2", "work"]


def test_earlier_failed_build_is_replaced(tmp_path, student, capsys):
    out = tmp_path / "out"
    argv = ["build", str(student / "task.toml"), "-o", str(out), "--quiet", "--no-sheets",
            "--latexmk", str(tmp_path / "no-such-latexmk")]
    assert main(argv) == 1
    assert main(argv) == 1
    capsys.readouterr()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.failed", "work"]


@pytest.mark.parametrize("mask", [0o022, 0o077, 0o002])
def test_outputs_get_the_mode_an_ordinary_write_gives(tmp_path, student, capsys, mask):
    """Outputs are written through temporary files renamed into place; mkstemp/mkdtemp make them
    0600/0700 whatever the umask, which locked a teacher out of a student's note on a shared machine.
    Each output has the mode ``open``/``mkdir`` gives under the umask."""
    old = os.umask(mask)
    try:
        out = tmp_path / "out"
        code, err = build(student / "task.toml", out, capsys)
        assert code == 0, err
        made = tmp_path / "made.json"
        assert main(["solve", str(student / "task.toml"), "--quiet", "--json", str(made)]) == 0
        task = tmp_path / "variant.toml"
        assert main(["new", "--table", "1", "--variant", "1", "-o", str(task)]) == 0
    finally:
        os.umask(old)
    assert out.stat().st_mode & 0o777 == 0o777 & ~mask
    for f in out.rglob("*"):
        assert f.stat().st_mode & 0o777 == (0o777 if f.is_dir() else 0o666) & ~mask, f
    for f in (made, task):
        assert f.stat().st_mode & 0o777 == 0o666 & ~mask, f
