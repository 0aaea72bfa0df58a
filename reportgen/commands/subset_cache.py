"""Font subsets of the note's figures kept by the build cache (``subsets/``), so that a rebuild's
figures do not run fontTools again for the glyph sets an earlier build subset.

Matplotlib's PDF backend embeds, for each font a figure uses, a subset of it made by fontTools
(``_backend_pdf_ps.get_glyphs_subset``: the font file parsed, pruned to the glyphs, written —
≈ 10–40 ms each, and most of a rebuild's figure saving: a fresh process has no subset made yet).
A subset is a pure function of the font file, its face and the glyph set, as
:func:`latex_templates.figures.saving.remember_font_subsets` (the same within one process) relies
on; this layer under it keeps the bytes and the glyph numbers on disk, keyed by the code's
fingerprint (fontTools' and matplotlib's versions, the fonts installed) and those three. The bytes
written into the PDF are the ones the layer under it wrote — the subset cut from the font read once
(latex_templates/figures/font_subset.py), or fontTools' for a font it does not cut
(tests/speed/test_subset_cache.py).
"""
from __future__ import annotations

import hashlib
import json
import os
import tempfile
from contextlib import nullcontext
from pathlib import Path
from typing import Any

#: Subsets kept (the least recently used removed first).
KEEP = 600
_FOLDER: Path | None = None      # this build's cache folder of subsets; None: no cache
_CODE = ""
_PRUNED: set[Path] = set()
_INSTALLED = False


class _KeptFont:
    """A kept subset as the backend uses it: only written out (``save``)."""

    def __init__(self, data: bytes) -> None:
        self.data = data

    def save(self, file: Any, **_options: Any) -> None:
        file.write(self.data)


class _KeptSubset:
    """What ``get_glyphs_subset`` yields: the font and the old → new glyph numbers."""

    def __init__(self, data: bytes, glyph_index_map: dict[int, int]) -> None:
        self.font = _KeptFont(data)
        self.glyph_index_map = glyph_index_map


def use(cache: Any) -> None:
    """Read and write subsets in ``cache``'s folder (a :class:`reportgen.cache.BuildCache`; None:
    neither) from now on in this process and the processes it forks."""
    global _FOLDER, _CODE
    if cache is None:
        _FOLDER = None
        return
    _FOLDER, _CODE = cache.root / "subsets", cache.code
    _install()
    if _FOLDER not in _PRUNED:
        _PRUNED.add(_FOLDER)
        from ..cache import _prune
        _prune(_FOLDER, KEEP)


def _install() -> None:
    """Put the disk layer in place of fontTools' subsetting, once per process and before the
    memory of subsets (``remember_font_subsets``, installed when the first figure is saved) wraps
    it; a process that saved a figure before is left as it is (no disk layer: the same bytes)."""
    global _INSTALLED
    from matplotlib.backends import _backend_pdf_ps as pdf_ps

    if _INSTALLED or getattr(pdf_ps.get_glyphs_subset, "reportgen_memo", False):
        return
    _INSTALLED = True
    from latex_templates.figures.font_subset import cut_below
    original = cut_below(pdf_ps.get_glyphs_subset)   # subsets cut from the font read once (cpu helper)

    def get_glyphs_subset(fontfile: Any, glyphs: Any) -> Any:
        folder = _FOLDER
        if folder is None:
            return original(fontfile, glyphs)
        gids = sorted({int(g) for g in glyphs})
        key = hashlib.sha256(json.dumps([_CODE, str(fontfile), int(getattr(fontfile, "face_index", 0)),
                                         gids]).encode()).hexdigest()
        path = folder / key
        found = _read(path)
        if found is None:
            with original(fontfile, glyphs) as subset:
                found = (pdf_ps.font_as_file(subset.font).getvalue(),
                         {int(k): int(v) for k, v in subset.glyph_index_map.items()})
            _write(path, *found)
        else:
            try:
                os.utime(path)
            except OSError:
                pass
        return nullcontext(_KeptSubset(*found))

    get_glyphs_subset.reportgen_original = original  # type: ignore[attr-defined]
    pdf_ps.get_glyphs_subset = get_glyphs_subset


def _read(path: Path) -> tuple[bytes, dict[int, int]] | None:
    try:
        data = path.read_bytes()
        n = int.from_bytes(data[:4], "little")
        gmap = {int(k): int(v) for k, v in json.loads(data[4:4 + n].decode())}
        return data[4 + n:], gmap
    except (OSError, ValueError, UnicodeDecodeError):
        return None


def _write(path: Path, font: bytes, gmap: dict[int, int]) -> None:
    head = json.dumps(sorted(gmap.items())).encode()
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, part = tempfile.mkstemp(dir=path.parent, suffix=".part")
        with os.fdopen(fd, "wb") as f:
            f.write(len(head).to_bytes(4, "little") + head + font)
        os.replace(part, path)
    except OSError:
        return
