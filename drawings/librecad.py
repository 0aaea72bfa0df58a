"""The headless check with a real CAD reader: LibreCAD prints the DXF to PDF, pdftoppm rasterises.

``QT_QPA_PLATFORM=offscreen librecad dxf2pdf -a -t OUTDIR sheet.dxf`` (``dxf2pdf`` first; ``-o`` and
``-p`` are broken in 2.2.0; without ``-a`` the page is blank). LibreCAD strokes its text, so the
PDF is judged by its pixels.
"""
from __future__ import annotations

import os
import shutil
import subprocess
from dataclasses import dataclass
from pathlib import Path

from reportgen.errors import BuildError
from reportgen.tolerances import BLANK_INK

from .preview import ink_fraction



def missing_tools() -> list[str]:
    """Which of librecad and pdftoppm are not installed (empty when the check can run)."""
    return [tool for tool in ("librecad", "pdftoppm") if shutil.which(tool) is None]


def _require_tools() -> None:
    missing = missing_tools()
    if missing:
        raise BuildError("LibreCAD check",
                         f"{' and '.join(missing)} not found on PATH; install with "
                         f"`apt-get install librecad poppler-utils`")


def dxf_to_pdf(dxf_path: str | os.PathLike[str], out_dir: str | os.PathLike[str],
               timeout: float = 120.0) -> Path:
    """Print ``dxf_path`` with LibreCAD (fit to page) into ``out_dir``; returns the PDF path."""
    _require_tools()
    dxf = Path(dxf_path).resolve()
    out = Path(out_dir).resolve()
    out.mkdir(parents=True, exist_ok=True)
    pdf = out / (dxf.stem + ".pdf")
    if pdf.exists():
        pdf.unlink()
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen")
    env.setdefault("XDG_RUNTIME_DIR", str(out))
    proc = subprocess.run(["librecad", "dxf2pdf", "-a", "-t", str(out), str(dxf)], env=env,
                          capture_output=True, text=True, timeout=timeout, check=False)
    if proc.returncode != 0 or not pdf.exists():
        raise BuildError("LibreCAD check",
                         f"librecad dxf2pdf exited with {proc.returncode} and wrote no {pdf.name}: "
                         f"{(proc.stderr or proc.stdout).strip()[-500:]}")
    return pdf


def pdf_to_png(pdf_path: str | os.PathLike[str], dpi: int = 50) -> Path:
    """The first page of a PDF as a PNG next to it (pdftoppm)."""
    _require_tools()
    pdf = Path(pdf_path)
    prefix = pdf.with_suffix("")
    proc = subprocess.run(["pdftoppm", "-png", "-r", str(dpi), "-f", "1", "-l", "1",
                           "-singlefile", str(pdf), str(prefix)],
                          capture_output=True, text=True, check=False)
    png = prefix.with_suffix(".png")
    if proc.returncode != 0 or not png.exists():
        raise BuildError("LibreCAD check", f"pdftoppm failed on {pdf.name}: {proc.stderr.strip()}")
    return png


@dataclass(frozen=True)
class LibreCADResult:
    """Result of :func:`check_sheet`: the PDF and PNG written and the share of inked pixels."""
    pdf: Path
    png: Path
    ink: float

    @property
    def drawn(self) -> bool:
        """True when LibreCAD put something on the page."""
        return self.ink > BLANK_INK


def check_sheet(dxf_path: str | os.PathLike[str], out_dir: str | os.PathLike[str],
                dpi: int = 50) -> LibreCADResult:
    """Print a DXF with LibreCAD, rasterise the page and measure its ink."""
    pdf = dxf_to_pdf(dxf_path, out_dir)
    png = pdf_to_png(pdf, dpi)
    return LibreCADResult(pdf, png, ink_fraction(png))
