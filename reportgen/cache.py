"""The build cache: outputs kept by content hash, so that an unchanged task is rebuilt in a moment
and a changed one redoes only what its change reaches.

Where: ``$REPORTGEN_CACHE``, else ``$XDG_CACHE_HOME/reportgen``, else ``~/.cache/reportgen`` — never
the output folder, so ``build`` writes nothing there that the build itself did not make.
``REPORTGEN_CACHE=off`` (or ``build --no-cache``) turns it off.

What, each under a key that is a SHA-256 of everything the entry depends on:

- ``builds/<key>/``: the whole output of a build; key = the code (every source file of reportgen,
  latex_templates and drawings, and the versions of the libraries that draw) + the task file's
  bytes + the build options. A hit copies the folder: the same bytes a build would write, since
  the build is a pure function of these (tests check builds with different hash seeds, folders
  and times, and cached against uncached).
- ``previews/<key>.png``: a sheet's PNG preview; key = the DXF's bytes + the code. A sheet drawn
  again renders its preview only when its DXF changed.
- ``sheets/<sheet>/<variant>/``: a whole sheet (DXF + preview); ``<sheet>`` = the code + the sheet
  module, file name, number, count and language; ``<variant>`` = what the sheet read of the
  project when it was drawn (:mod:`reportgen.read_trace`) + the digest of each value read. A
  sheet whose reads digest as before on the new project is copied, not drawn
  (:meth:`BuildCache.restore_sheet`).
- ``tex/<key>/``: LaTeX's auxiliary files of the last build of a task file (key = its absolute
  path): the passes start from them and often need one (:mod:`latex_templates.passes`).
- ``figures/<key>.pdf``: a note's figure — drawn from a scene, or a matplotlib plot; key = the
  code + the figure's content key (:func:`content_digest` of the scene or of the plot's arguments,
  the renderer's options and the note's language: ``latex_templates.figures.scene.figure_key``,
  ``latex_templates.figures.keyed.plot_key``). A hit neither makes nor saves the figure: a stand-in
  with its kept sizes is placed and the PDF copied.
- ``jinja/<key>.code``: the note's templates and catalogue snippets compiled by Jinja (key = the
  source, its name, the syntax options, the Jinja and Python versions; ``latex_templates.jinja_cache``).

"The code" (:func:`code_fingerprint`) is every source file, the drawing libraries' versions, the
xelatex binary and the fonts installed (:func:`fonts_fingerprint`).
Each kind keeps its newest entries only (``KEEP``). A cache that cannot be written is skipped.
"""
from __future__ import annotations

import hashlib
import os
import shutil
import tempfile
from functools import lru_cache
from pathlib import Path
from typing import Callable, Mapping

#: Newest entries kept of each kind.
KEEP = {"builds": 12, "previews": 200, "tex": 12, "figures": 400, "sheets": 60, "sections": 60,
        "scenes": 60}
#: Source files whose bytes make the code's fingerprint.
_SOURCE_SUFFIXES = (".py", ".j2", ".toml", ".tex", ".sty", ".lff", ".ttf", ".otf")
_LIBRARIES = ("numpy", "scipy", "matplotlib", "ezdxf", "shapely", "jinja2", "fonttools", "pyparsing")


def cache_root() -> Path | None:
    """The cache's folder; None when ``REPORTGEN_CACHE=off``."""
    env = os.environ.get("REPORTGEN_CACHE")
    if env and env.strip().lower() in ("off", "0", "no", "false"):
        return None
    if env:
        return Path(env)
    xdg = os.environ.get("XDG_CACHE_HOME")
    return (Path(xdg) if xdg else Path.home() / ".cache") / "reportgen"


@lru_cache(maxsize=1)
def code_fingerprint() -> str:
    """SHA-256 of the project's source files and the drawing libraries' versions."""
    from importlib import metadata

    h = hashlib.sha256()
    root = Path(__file__).resolve().parents[1]
    for package in ("reportgen", "latex_templates", "drawings"):
        base = root / package
        for path in sorted(base.rglob("*")):
            if path.suffix in _SOURCE_SUFFIXES and path.is_file() and "__pycache__" not in path.parts:
                h.update(path.relative_to(root).as_posix().encode())
                h.update(b"\0")
                h.update(path.read_bytes())
                h.update(b"\0")
    for lib in _LIBRARIES:
        try:
            version = metadata.version(lib)
        except metadata.PackageNotFoundError:
            version = "-"
        h.update(f"{lib}={version};".encode())
    tex = shutil.which("xelatex")
    h.update((os.path.realpath(tex) if tex else "no-xelatex").encode())
    h.update(fonts_fingerprint().encode())
    return h.hexdigest()


#: Where the fonts the figures and the sheets' previews are drawn with may come from (fontconfig's
#: folders; matplotlib's own fonts go with its version).
FONT_FOLDERS = ("/usr/share/fonts", "/usr/local/share/fonts", "~/.fonts", "~/.local/share/fonts")


def fonts_fingerprint() -> str:
    """SHA-256 of the font files installed (path, size, modification time): a font installed,
    removed or updated changes every figure and preview the cache keeps."""
    h = hashlib.sha256()
    for folder in FONT_FOLDERS:
        base = Path(folder).expanduser()
        if not base.is_dir():
            continue
        for dirpath, dirnames, filenames in os.walk(base):
            dirnames.sort()
            for name in sorted(filenames):
                try:
                    st = os.stat(os.path.join(dirpath, name))
                except OSError:
                    continue
                h.update(f"{dirpath}/{name}:{st.st_size}:{st.st_mtime_ns};".encode())
    return h.hexdigest()


def content_digest(obj: object, *, skip: "frozenset[tuple[str, str]]" = frozenset()) -> str:
    """SHA-256 of plain data — dataclasses, mappings, sequences, sets, numbers (fractions too),
    strings, numpy arrays — by a canonical walk (type names, field names, float bits), the same in
    every process whatever the hash seed; anything else is an error, so a key never rests on an
    object's ``repr``. ``skip``: (class name, field name) pairs of dataclass fields left out
    (:data:`reportgen.read_trace.MASS_FIELDS`)."""
    h = hashlib.sha256()
    _feed(h, obj, skip)
    return h.hexdigest()


def _feed(h: "hashlib._Hash", obj: object, skip: "frozenset[tuple[str, str]]" = frozenset()) -> None:
    import dataclasses
    import struct
    from fractions import Fraction

    if obj is None or isinstance(obj, bool):
        h.update(f"<{obj!r}>".encode())
    elif isinstance(obj, int):
        h.update(b"i%d;" % obj)
    elif isinstance(obj, float):
        h.update(b"f" + struct.pack("<d", obj))
    elif isinstance(obj, str):
        data = obj.encode()
        h.update(b"s%d:" % len(data) + data)
    elif isinstance(obj, Fraction):
        h.update(b"q%d/%d;" % (obj.numerator, obj.denominator))
    elif dataclasses.is_dataclass(obj) and not isinstance(obj, type):
        name = type(obj).__qualname__
        h.update(f"D{name}(".encode())
        for field_name in _field_names(type(obj)):
            if (name, field_name) in skip:
                continue
            h.update(field_name.encode() + b"=")
            _feed(h, getattr(obj, field_name), skip)
        h.update(b")")
    elif isinstance(obj, (tuple, list)):
        packed = _packed_floats(obj)
        if packed is not None:           # a run of floats, or of points: one update, not one per number
            h.update(packed)
            return
        h.update(b"T%d[" % len(obj))
        for item in obj:
            _feed(h, item, skip)
        h.update(b"]")
    elif isinstance(obj, (set, frozenset)):       # in the order of the items' digests: no hash seed
        items = sorted(content_digest(item, skip=skip) for item in obj)
        h.update(b"S%d{" % len(items) + "".join(items).encode() + b"}")
    elif isinstance(obj, Mapping):
        h.update(b"M%d{" % len(obj))           # insertion order: the scenes build their mappings in a fixed order
        for k in obj.keys():
            _feed(h, k, skip)
            _feed(h, obj[k], skip)
        h.update(b"}")
    elif type(obj).__module__ == "numpy":
        import numpy as np

        a = np.ascontiguousarray(obj)
        if a.dtype == object:
            _feed(h, a.tolist(), skip)
        else:
            h.update(f"A{a.dtype.str}{a.shape}".encode())
            h.update(a.tobytes())
    else:
        from .errors import InternalError

        raise InternalError("content_digest", f"no canonical form for {type(obj).__name__}")


@lru_cache(maxsize=None)
def _field_names(cls: type) -> tuple[str, ...]:
    import dataclasses
    return tuple(f.name for f in dataclasses.fields(cls))


def _packed_floats(seq: tuple | list) -> bytes | None:
    """A sequence of floats (tag ``F``) or of equally long tuples of floats (tag ``P``, points) as
    one run of little-endian doubles with its shape; None for anything else (walked item by item)."""
    import struct

    n = len(seq)
    if n < 2:
        return None
    first = seq[0]
    if type(first) is float:
        if all(type(x) is float for x in seq):
            return b"F%d[" % n + struct.pack(f"<{n}d", *seq)
        return None
    if type(first) is tuple and first and all(type(x) is float for x in first):
        m = len(first)
        if all(type(t) is tuple and len(t) == m and all(type(x) is float for x in t) for t in seq):
            return b"P%dx%d[" % (n, m) + struct.pack(f"<{n * m}d", *(x for t in seq for x in t))
    return None


def _digest(*parts: bytes | str) -> str:
    h = hashlib.sha256()
    for p in parts:
        h.update(p.encode() if isinstance(p, str) else p)
        h.update(b"\0")
    return h.hexdigest()


class BuildCache:
    """One build's view of the cache (see the module's docstring)."""

    def __init__(self, root: Path, task_bytes: bytes, task_path: Path, options: str) -> None:
        self.root = root
        code = code_fingerprint()
        self.code = code
        self.build_key = _digest("build", code, task_bytes, options)
        self.tex_key = _digest("tex", str(task_path))
        self.figures_reused = 0     # figures copied from the cache in this build (the note's figures)
        self.figures_saved = 0      # figures saved and stored in this build
        self.sections_reused = 0    # the note's sections whose text came from the cache
        self.sections = 0           # the note's sections (composed or kept)
        self._read_digests: dict[tuple, str | None] = {}   # a sheet's read → its digest, this build

    # -- whole builds ------------------------------------------------------------------------
    def restore_build(self, tmp: Path) -> bool:
        """Copy a finished build with this key into ``tmp``; False when there is none."""
        entry = self.root / "builds" / self.build_key
        if not (entry / ".complete").is_file():
            return False
        try:
            _copy_tree(entry, tmp)
        except OSError:
            return False
        (tmp / ".complete").unlink(missing_ok=True)
        _touch(entry)
        return True

    def store_build(self, tmp: Path) -> None:
        self._store_dir("builds", self.build_key, tmp)

    # -- LaTeX's auxiliary files ---------------------------------------------------------------
    #: The preamble of the last build's note, kept in its ``tex/`` entry (not copied to the build).
    TEX_PREAMBLE = ".reportgen-preamble"

    def restore_tex(self, build_dir: Path) -> bool:
        entry = self.root / "tex" / self.tex_key
        if not (entry / ".complete").is_file():
            return False
        try:
            build_dir.mkdir(parents=True, exist_ok=True)
            for item in entry.iterdir():
                if item.is_dir():
                    _copy_tree(item, build_dir / item.name)
                elif item.name not in (".complete", self.TEX_PREAMBLE):
                    shutil.copyfile(item, build_dir / item.name)
        except OSError:
            return False
        return True

    def tex_preamble(self) -> str | None:
        """The preamble of the note whose auxiliary files :meth:`restore_tex` restores (through
        its line ``\\begin{document}``), or None when the entry keeps none."""
        entry = self.root / "tex" / self.tex_key
        if not (entry / ".complete").is_file():
            return None
        try:
            return (entry / self.TEX_PREAMBLE).read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError):
            return None

    def store_tex(self, build_dir: Path, preamble: str | None = None) -> None:
        """Keep LaTeX's working folder of this build (and ``preamble``, its note's preamble)."""
        if not build_dir.is_dir():
            return

        def fill(part: Path) -> None:
            _copy_tree(build_dir, part)
            if preamble is not None:
                (part / self.TEX_PREAMBLE).write_text(preamble, encoding="utf-8")

        if _publish(self.root / "tex" / self.tex_key, fill):
            _prune(self.root / "tex", KEEP["tex"])

    # -- sheet previews ------------------------------------------------------------------------
    def _preview_path(self, dxf: Path) -> Path:
        return self.root / "previews" / (_digest("preview", self.code, dxf.read_bytes()) + ".png")

    def restore_preview(self, dxf: Path, png: Path) -> bool:
        src = self._preview_path(dxf)
        try:
            shutil.copyfile(src, png)
        except OSError:
            return False
        _touch(src)
        return True

    def store_preview(self, dxf: Path, png: Path) -> None:
        dst = self._preview_path(dxf)
        try:
            dst.parent.mkdir(parents=True, exist_ok=True)
            _copy_atomic(png, dst)
        except OSError:
            return
        _prune(dst.parent, KEEP["previews"])

    # -- what is kept under what it read: whole sheets, the note's sections -------------------
    def _variants_base(self, kind: str, identity: str) -> Path:
        return self.root / kind / _digest(kind, self.code, identity)

    def _digest_of(self, project: object, read: tuple, mask: bool) -> str | None:
        from .read_trace import read_digest

        memo = (read, mask)
        if memo not in self._read_digests:
            try:
                found = self._scene_digest(project, read, mask) if read[0] == "scenes" else None
                self._read_digests[memo] = found or read_digest(project, read, mask_masses=mask)
                if read[0] == "scenes" and found is None:
                    self._keep_scene_digest(project, read, mask, self._read_digests[memo])
            except Exception:  # noqa: BLE001 - a stage that fails now, or data without a canonical form: no hit
                self._read_digests[memo] = None
        return self._read_digests[memo]

    # -- a scene's digest kept under its inputs' ----------------------------------------------
    _SCENE_INPUTS = ".inputs.json"     # in a scene's entry: what it reads (kept by pruning: a dot)

    def _scene_entry(self, name: str) -> Path:
        return self.root / "scenes" / _digest("scene-inputs", self.code, name)

    def _scene_key(self, project: object, mask: bool, inputs: list[tuple]) -> str | None:
        """The digest of the values of a scene's ``inputs`` on ``project`` (masses never left out:
        a scene may draw them), with the mask its own digest is made with."""
        import json

        digests = [self._digest_of(project, r, False) for r in inputs]
        if any(d is None for d in digests):
            return None
        return _digest("scene", json.dumps(inputs), str(mask), *[d for d in digests if d is not None])

    def _scene_digest(self, project: object, read: tuple, mask: bool) -> str | None:
        """The digest of the scene ``read`` names, kept under the digest of what it reads
        (:func:`reportgen.read_trace.scene_inputs`), when the values it reads on ``project`` are
        those it was kept under: the scene need not be made. None otherwise."""
        import json

        entry = self._scene_entry(read[1])
        try:
            found_inputs = json.loads((entry / self._SCENE_INPUTS).read_text(encoding="utf-8"))
        except (OSError, ValueError):
            return None
        if not isinstance(found_inputs, list):       # a scene not kept by its inputs (opaque)
            return None
        inputs = [tuple(r) for r in found_inputs]
        key = self._scene_key(project, mask, inputs)
        if key is None:
            return None
        try:
            found = (entry / key).read_text(encoding="utf-8").strip()
        except OSError:
            return None
        _touch(entry / key)
        return found or None

    def _keep_scene_digest(self, project: object, read: tuple, mask: bool, digest: str | None) -> None:
        """Keep ``digest`` of the scene ``read`` names under the digest of its inputs (found once
        per code: the scene made again on a recording view of the project)."""
        import json

        from .read_trace import scene_inputs

        if digest is None or len(read) != 2:
            return
        entry = self._scene_entry(read[1])
        try:
            known = json.loads((entry / self._SCENE_INPUTS).read_text(encoding="utf-8"))
        except (OSError, ValueError):
            known = scene_inputs(project, read[1])
            try:                       # null: not kept by its inputs (not tried again with this code)
                entry.mkdir(parents=True, exist_ok=True)
                _write_atomic(entry / self._SCENE_INPUTS, json.dumps(known))
            except OSError:
                return
        if not isinstance(known, list):
            return
        inputs = [tuple(r) for r in known]
        key = self._scene_key(project, mask, inputs)
        if key is None:
            return
        try:
            _write_atomic(entry / key, digest)
        except OSError:
            return
        _prune(entry, 16)                     # a few values of each scene (an edit undone is a hit)
        _touch(entry)
        _prune(entry.parent, KEEP["scenes"])

    def scene_kept(self, project: object, name: str) -> bool:
        """Whether the digest of ``project.scenes.<name>`` is known without making it."""
        return self._scene_digest(project, ("scenes", name), False) is not None \
            or self._scene_digest(project, ("scenes", name), True) is not None

    def _variant(self, project: object, reads: list[tuple]) -> str | None:
        """The name of the variant of a sheet (or section) whose ``reads`` have the values they
        have on ``project`` (None when one of them cannot be digested)."""
        from .read_trace import masks_masses

        mask = masks_masses(reads)
        digests = [self._digest_of(project, r, mask) for r in reads]
        if any(d is None for d in digests):
            return None
        import json
        return _digest("variant", json.dumps(reads), *[d for d in digests if d is not None])

    def find_variant(self, kind: str, identity: str, project: object) -> Path | None:
        """The entry of ``kind`` (``sheets``, ``sections``) named ``identity`` that was made from a
        project whose every read value (:mod:`reportgen.read_trace`) equals ``project``'s; None
        when there is none. Its use is noted (the newest entries are kept)."""
        import json

        base = self._variants_base(kind, identity)
        try:
            variants = [p for p in base.iterdir() if (p / ".complete").is_file()]
        except OSError:
            return None
        tried: set[str] = set()
        for entry in sorted(variants, key=lambda p: p.stat().st_mtime, reverse=True):
            try:
                reads = [tuple(r) for r in json.loads((entry / "reads.json").read_text(encoding="utf-8"))]
            except (OSError, ValueError):
                continue
            name = self._variant(project, reads)
            if name is None or name in tried:
                continue
            tried.add(name)
            found = base / name
            if (found / ".complete").is_file():
                _touch(found)
                _touch(base)
                return found
        return None

    def store_variant(self, kind: str, identity: str, project: object, reads: list[tuple],
                      fill: Callable[[Path], None], *, replace: bool = False) -> None:
        """Keep what ``fill(folder)`` writes as the entry of ``kind`` named ``identity`` under its
        ``reads``' values on ``project`` (``replace``: over an entry of the same values)."""
        import json

        name = self._variant(project, reads)
        if name is None:
            return
        base = self._variants_base(kind, identity)
        entry = base / name
        if (entry / ".complete").is_file() and not replace:
            return

        def fill_all(part: Path) -> None:
            fill(part)
            (part / "reads.json").write_text(json.dumps(reads), encoding="utf-8")

        if not _publish(entry, fill_all):
            return
        _prune(base, 4)                       # a few variants of each (an edit undone is a hit)
        _prune(base.parent, KEEP[kind])

    def restore_sheet(self, identity: str, project: object, files: dict[str, Path]) -> bool:
        """Copy the files of the sheet ``identity`` (the sheet module, its number and count, the
        language) drawn from a project whose every read value (:mod:`reportgen.read_trace`) equals
        ``project``'s; ``files``: the kept file's name → where it goes. False when there is none."""
        found = self.find_variant("sheets", identity, project)
        if found is None:
            return False
        try:
            for kept, target in files.items():
                _copy_atomic(found / kept, target)
        except OSError:
            return False
        return True

    def store_sheet(self, identity: str, project: object, reads: list[tuple], files: dict[str, Path]) -> None:
        """Keep the sheet's ``files`` (name → the file made) under its reads' values on ``project``."""
        def fill(part: Path) -> None:
            for kept, made in files.items():
                shutil.copyfile(made, part / kept)

        self.store_variant("sheets", identity, project, reads, fill)

    def restore_section(self, identity: str, project: object) -> dict | None:
        """What :meth:`store_section` kept of the note's section ``identity`` for a project whose
        every read value equals ``project``'s; None when nothing."""
        import json

        found = self.find_variant("sections", identity, project)
        if found is None:
            return None
        try:
            data = json.loads((found / "section.json").read_text(encoding="utf-8"))
        except (OSError, ValueError):
            return None
        return data if isinstance(data, dict) else None

    def store_section(self, identity: str, project: object, reads: list[tuple], data: dict) -> None:
        """Keep ``data`` (JSON: the section as rendered, :mod:`reportgen.commands.note_cache`)
        under its reads' values on ``project``, over what was kept for the same values."""
        import json

        def fill(part: Path) -> None:
            (part / "section.json").write_text(json.dumps(data, ensure_ascii=False), encoding="utf-8")

        self.store_variant("sections", identity, project, reads, fill, replace=True)

    # -- the note's figures --------------------------------------------------------------------
    def _figure_path(self, key: str) -> Path:
        return self.root / "figures" / (_digest("figure", self.code, key) + ".pdf")

    def restore_figure(self, key: str, target: Path) -> bool:
        """Copy the PDF of the figure with content key ``key`` to ``target``; False when none."""
        if not self.copy_figure(key, target):
            return False
        self.figures_reused += 1
        return True

    def copy_figure(self, key: str, target: Path) -> bool:
        """:meth:`restore_figure` without counting it (a first LaTeX pass's early copy)."""
        src = self._figure_path(key)
        part = target.with_name(f".{target.name}.part")
        try:
            shutil.copyfile(src, part)
            os.replace(part, target)
        except OSError:
            part.unlink(missing_ok=True)
            return False
        _touch(src.with_suffix(".json"))
        _touch(src)
        return True

    def figure_sizes(self, key: str) -> dict[str, float] | None:
        """The sizes kept with the figure of content key ``key`` (what the note reads of it), when
        its PDF is kept too; else None."""
        import json

        pdf = self._figure_path(key)
        try:
            sizes = json.loads(pdf.with_suffix(".json").read_text(encoding="utf-8"))
        except (OSError, ValueError):
            return None
        return sizes if pdf.is_file() and isinstance(sizes, dict) else None

    def store_figure(self, key: str, target: Path, sizes: dict[str, float] | None = None) -> None:
        """Keep the saved PDF ``target`` under ``key`` (and ``sizes``, JSON: floats read back exactly)."""
        import json

        dst = self._figure_path(key)
        try:
            dst.parent.mkdir(parents=True, exist_ok=True)
            if sizes is not None:
                fd, part = tempfile.mkstemp(dir=dst.parent, suffix=".part")
                with os.fdopen(fd, "w", encoding="utf-8") as f:
                    json.dump(sizes, f)
                os.replace(part, dst.with_suffix(".json"))
            _copy_atomic(target, dst)
        except OSError:
            return
        self.figures_saved += 1
        _prune(dst.parent, 2 * KEEP["figures"])

    # -- helpers -------------------------------------------------------------------------------
    def _store_dir(self, kind: str, key: str, src: Path, replace: bool = False) -> None:
        base = self.root / kind
        entry = base / key
        if entry.exists() and not replace:
            return
        if not _publish(entry, lambda part: _copy_tree(src, part)):
            return
        _prune(base, KEEP[kind])


def open_cache(task_path: str | os.PathLike[str], *, pdf: bool, sheets: bool,
               latexmk: str = "latexmk") -> BuildCache | None:
    """The cache for a build of ``task_path`` with these options; None when it cannot be used."""
    root = cache_root()
    if root is None:
        return None
    try:
        root.mkdir(parents=True, exist_ok=True)
        if not os.access(root, os.W_OK):
            return None
        path = Path(task_path).resolve()
        data = path.read_bytes()
    except OSError:
        return None
    epoch = os.environ.get("SOURCE_DATE_EPOCH", "")
    return BuildCache(root, data, path, f"pdf={pdf};sheets={sheets};latexmk={latexmk};epoch={epoch}")


def _publish(entry: Path, fill: Callable[[Path], None]) -> bool:
    """Write the cache entry ``entry`` (a folder) whole or not at all: ``fill`` a temporary folder
    beside it, mark it ``.complete`` and rename it into place (a reader never sees half an entry).
    False when the disk refused; nothing is left behind then."""
    part: Path | None = None
    try:
        entry.parent.mkdir(parents=True, exist_ok=True)
        part = Path(tempfile.mkdtemp(dir=entry.parent, prefix=".part-"))
        fill(part)
        (part / ".complete").write_bytes(b"")
        if entry.exists():
            shutil.rmtree(entry, ignore_errors=True)
        part.rename(entry)
    except OSError:
        if part is not None:
            shutil.rmtree(part, ignore_errors=True)
        return False
    return True


def _copy_tree(src: Path, dst: Path) -> None:
    dst.mkdir(parents=True, exist_ok=True)
    for item in src.iterdir():
        target = dst / item.name
        if item.is_dir():
            _copy_tree(item, target)
        else:
            shutil.copyfile(item, target)


def _write_atomic(dst: Path, text: str) -> None:
    """Write ``text`` to ``dst`` through a part file renamed into place."""
    fd, part = tempfile.mkstemp(dir=dst.parent, suffix=".part")
    with os.fdopen(fd, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(part, dst)


def _copy_atomic(src: Path, dst: Path) -> None:
    """Copy ``src`` to ``dst`` through a part file in ``dst``'s folder, renamed into place, so that
    a reader (or a build stopped half-way) never sees half a file."""
    fd, part = tempfile.mkstemp(dir=dst.parent, suffix=".part")
    os.close(fd)
    shutil.copyfile(src, part)
    os.replace(part, dst)


def _touch(path: Path) -> None:
    try:
        os.utime(path)
    except OSError:
        pass


def _prune(base: Path, keep: int) -> None:
    """Remove all but the ``keep`` most recently used entries of one kind."""
    try:
        entries = [p for p in base.iterdir() if not p.name.startswith(".")]
    except OSError:
        return
    if len(entries) <= keep:
        return
    entries.sort(key=lambda p: p.stat().st_mtime, reverse=True)
    for p in entries[keep:]:
        if p.is_dir():
            shutil.rmtree(p, ignore_errors=True)
        else:
            p.unlink(missing_ok=True)
