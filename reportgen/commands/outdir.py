"""Where ``reportgen build`` may write: the output-folder rule and its manifest.

``build`` replaces its output folder OUT as a whole, so it must never replace a folder that holds
anything reportgen did not write. OUT is accepted when it

- does not exist yet (its parent folder must), or
- is an empty folder, or
- is an earlier reportgen output: it holds the manifest ``MANIFEST_NAME`` with the format marker
  ``MANIFEST_FORMAT`` and every file in OUT is listed there with the SHA-256 it had when reportgen
  wrote it (a file changed or added since is the user's, and the folder is refused).

Refused, with exit status 2 and nothing touched: a file or a symbolic link, the folder that holds the
task file or any folder above it, the current folder or any folder above it, and a folder with
anything else in it. The same rule protects ``OUT.failed/``: a failed build replaces an earlier failed
build (it carries a manifest too) and never a folder of the user's; it then picks ``OUT.failed-2/``…
"""
from __future__ import annotations

import hashlib
import json
import os
import shutil
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..errors import OutputFolderError

MANIFEST_NAME = ".reportgen-manifest.json"
MANIFEST_FORMAT = "reportgen-output/1"
_SHOWN = 5  # foreign entries named in a refusal


@dataclass(frozen=True)
class Verdict:
    """Whether a folder may be replaced; ``reason`` says why not (``None``: it may)."""

    reason: str | None
    foreign: tuple[str, ...] = ()

    @property
    def ok(self) -> bool:
        return self.reason is None


def _sha256(path: Path) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


def _entries(folder: Path) -> dict[str, Path]:
    """Every file, link and folder below ``folder`` by its POSIX path relative to it (links not followed)."""
    found: dict[str, Path] = {}
    for root, dirs, files in os.walk(folder, followlinks=False):
        for name in dirs + files:
            p = Path(root) / name
            found[p.relative_to(folder).as_posix()] = p
    return found


def write_manifest(folder: Path) -> Path:
    """List every file reportgen wrote into ``folder`` (with its SHA-256) in the manifest."""
    files: dict[str, str] = {}
    dirs: list[str] = []
    for rel, p in sorted(_entries(folder).items()):
        if rel == MANIFEST_NAME:
            continue
        if p.is_symlink() or not p.is_dir():
            files[rel] = _sha256(p) if p.is_file() and not p.is_symlink() else "link"
        else:
            dirs.append(rel)
    data = {"format": MANIFEST_FORMAT, "written_by": "reportgen build",
            "note": "reportgen replaces this folder as a whole on the next build; "
                    "a file not listed here (or changed since) makes it refuse instead",
            "folders": dirs, "files": files}
    path = folder / MANIFEST_NAME
    path.write_text(json.dumps(data, ensure_ascii=False, indent=1) + "\n", encoding="utf-8")
    return path


def judge_folder(folder: Path) -> Verdict:
    """May ``folder`` (an existing folder) be replaced as a whole? Only if empty or all reportgen's."""
    entries = _entries(folder)
    if not entries:
        return Verdict(None)
    manifest = folder / MANIFEST_NAME
    if not manifest.is_file() or manifest.is_symlink():
        return Verdict("it holds files that reportgen did not write",
                       tuple(sorted(entries))[:_SHOWN])
    try:
        data = json.loads(manifest.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, ValueError):
        return Verdict(f"its {MANIFEST_NAME} cannot be read")
    if not isinstance(data, dict) or data.get("format") != MANIFEST_FORMAT:
        return Verdict(f"its {MANIFEST_NAME} is not of the format {MANIFEST_FORMAT}")
    files_: Any = data.get("files")
    files: dict[str, Any] = files_ if isinstance(files_, dict) else {}
    dirs = set(data.get("folders") or [])
    foreign: list[str] = []
    for rel, p in sorted(entries.items()):
        if rel == MANIFEST_NAME:
            continue
        if rel in files:
            want = files[rel]
            if p.is_symlink() or not p.is_file():
                same = want == "link" and p.is_symlink()
            else:
                same = want != "link" and _sha256(p) == want
            if not same:
                foreign.append(f"{rel} (changed since reportgen wrote it)")
        elif not (rel in dirs and p.is_dir() and not p.is_symlink()):
            foreign.append(rel)
    if foreign:
        return Verdict("it holds files that reportgen did not write", tuple(foreign[:_SHOWN]) +
                       ((f"… {len(foreign) - _SHOWN} more",) if len(foreign) > _SHOWN else ()))
    return Verdict(None)


def _is_within(inner: Path, outer: Path) -> bool:
    return inner == outer or outer in inner.parents


def check_output_folder(out: Path, task_path: Path, option: str = "--out") -> Path:
    """The absolute OUT if ``build`` may replace it; else :class:`OutputFolderError`."""
    given = Path(out)
    absolute = Path(os.path.abspath(given))
    if absolute.is_symlink():
        raise OutputFolderError(option, given, "it is a symbolic link",
                                "the real folder, or a new folder name")
    resolved = absolute.resolve()
    if resolved.exists() and not resolved.is_dir():
        raise OutputFolderError(option, given, "it is a file, not a folder",
                                "a new folder name, e.g. " + str(given.with_suffix("")) + "-out")
    if not resolved.parent.is_dir():
        raise OutputFolderError(option, given, f"the folder {resolved.parent} does not exist",
                                "a path in an existing folder")
    task_dir = Path(task_path).resolve().parent
    if _is_within(task_dir, resolved):
        where = "the folder that holds the task file" if task_dir == resolved else \
            f"a folder above the task file's folder {task_dir}"
        raise OutputFolderError(option, given, f"it is {where}; the build replaces OUT as a whole",
                                f"a new folder for the output, e.g. {task_dir / 'out'}")
    cwd = Path.cwd().resolve()
    if _is_within(cwd, resolved):
        where = "the current folder" if cwd == resolved else "a folder above the current folder"
        raise OutputFolderError(option, given, f"it is {where}; the build replaces OUT as a whole",
                                "a new folder for the output, e.g. -o out")
    if resolved.is_dir():
        verdict = judge_folder(resolved)
        if not verdict.ok:
            shown = ", ".join(verdict.foreign)
            raise OutputFolderError(
                option, given, str(verdict.reason) + (f": {shown}" if shown else ""),
                "a new or empty folder, or an earlier reportgen output "
                f"(recognised by its {MANIFEST_NAME}): choose another -o or move your files away")
    return resolved


def replace_folder(tmp: Path, out: Path) -> None:
    """Move the finished build ``tmp`` to ``out``, replacing an earlier output only once it is complete.

    ``out`` is judged again (the build takes a while, the user may have put a file there meanwhile);
    a folder that is no longer reportgen's is left alone and the build is kept beside it.
    """
    write_manifest(tmp)
    old = None
    if out.exists() or out.is_symlink():
        verdict = judge_folder(out) if out.is_dir() and not out.is_symlink() else Verdict("it is not a folder")
        if not verdict.ok:
            kept = _free_name(out, ".new")
            tmp.rename(kept)
            raise OutputFolderError("--out", out, str(verdict.reason) + " (they appeared during the build)",
                                    f"your files are untouched; the new build is in {kept}")
        old = out.with_name(f".{out.name}.old-{os.getpid()}")
        out.rename(old)
    tmp.rename(out)
    if old is not None:
        shutil.rmtree(old, ignore_errors=True)


def keep_failed(tmp: Path, out: Path) -> Path:
    """Keep a failed build as ``OUT.failed/``; returns where it went.

    An earlier failed build there (it has a manifest) is replaced; a folder of the user's is not:
    the build goes to ``OUT.failed-2/`` (or the first of ``-3``, ``-4``… that is free or reportgen's).
    """
    write_manifest(tmp)
    n = 1
    while True:
        failed = out.with_name(out.name + ".failed" + (f"-{n}" if n > 1 else ""))
        if not failed.exists() and not failed.is_symlink():
            tmp.rename(failed)
            return failed
        if failed.is_dir() and not failed.is_symlink() and judge_folder(failed).ok:
            old = failed.with_name(f".{failed.name}.old-{os.getpid()}")
            failed.rename(old)
            tmp.rename(failed)
            shutil.rmtree(old, ignore_errors=True)
            return failed
        n += 1


def _free_name(out: Path, suffix: str) -> Path:
    """``OUT<suffix>-2``, ``-3``… : the first name that is not taken."""
    n = 2
    while True:
        p = out.with_name(f"{out.name}{suffix}-{n}")
        if not p.exists() and not p.is_symlink():
            return p
        n += 1
