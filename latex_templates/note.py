"""The note as a whole: sections supplied by their authors, rendered into one ``report.tex``."""
from __future__ import annotations

import re
import shutil
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal, Mapping, Sequence

from reportgen.balance import check_balance
from reportgen.calc import CalcRecord, evaluate_displayed
from reportgen.errors import InternalError, OptionError, ParameterError
from reportgen.task import Document

from .build import BuildReport, build_pdf
from .tables import continued_heads, keep_rows_together
from .render import LANGUAGES, Strings, SymbolTracker, Tex, make_environment

FrameKind = Literal["none", "frame", "eskd"]
_KEY_RE = re.compile(r"^[a-z0-9][a-z0-9-]*$")


@dataclass(frozen=True)
class FigureRef:
    """Where a figure's file sits relative to ``report.tex`` and its LaTeX label."""
    path: str
    label: str


@dataclass
class Section:
    """One numbered section of the note.

    ``template`` is a template name (``sections/kinematics.tex.j2``, looked up in the package's
    templates, then in the builder's ``template_dirs``) rendered with ``context``; or ``body`` is
    ready LaTeX (trusted). ``figures`` maps a name to a matplotlib figure (saved as vector PDF) or
    a file path (copied); the template gets ``figures.<name>`` for ``m.figure(...)``.
    ``key`` (lower case, digits, ``-``) names the section's label ``sec:<key>`` and its files.
    """
    key: str
    title: str
    template: str | None = None
    body: str | None = None
    context: Mapping[str, Any] = field(default_factory=dict)
    figures: Mapping[str, Any] = field(default_factory=dict)

    def __post_init__(self) -> None:
        if not _KEY_RE.match(self.key):
            raise ParameterError("section key", self.key, "lower-case letters, digits and '-'")
        if (self.template is None) == (self.body is None):
            raise ParameterError(f"section {self.key!r}", "template and body", "exactly one of template= or body=")


@dataclass(frozen=True)
class _RenderedSection:
    key: str
    title: str
    body: Tex


class NoteBuilder:
    """Collects the sections of a note and renders/builds it.

    >>> from reportgen.calc import CalcRecord, evaluate_displayed
from reportgen.task import Document
    >>> note = NoteBuilder(Document(title="Пресс"))
    >>> note.add_section(Section(key="demo", title="Демо", body="Текст."))
    """

    def __init__(self, document: Document, language: str | None = None, *,
                 frame: FrameKind = "eskd", designation: str = "",
                 template_dirs: Sequence[Path | str] = (),
                 introduction: Sequence[str] = (), conclusions: Sequence[str] = (),
                 references: Sequence[str] = (), assignment: Section | None = None,
                 extra_preamble: str = "", strings: Strings | None = None,
                 default_title: str | None = None) -> None:
        self.document = document
        self.language = language or document.language or "ru"
        if self.language not in LANGUAGES:
            raise OptionError("language", f"{self.language!r} has no strings catalogue", "one of " + ", ".join(LANGUAGES))
        if frame not in ("none", "frame", "eskd"):
            raise ParameterError("frame", frame, "none, frame or eskd")
        self.frame = frame
        self.designation = designation
        self.template_dirs = tuple(template_dirs)
        self.introduction = list(introduction)
        self.conclusions = list(conclusions)
        self.references = list(references)
        self.assignment = assignment
        self.extra_preamble = extra_preamble
        self.sections: list[Section] = []
        self.strings = strings if strings is not None else Strings(
            self.language, overlay="control.overrides" if getattr(document, "kind", "") == "control-work" else None)
        self.symbols = SymbolTracker()
        self.last_build: BuildReport | None = None
        # the title the task left out, in the note's language (catalogue key; issue 12)
        self.default_title = default_title or ("control.sheet.title" if getattr(document, "kind", "") == "control-work"
                                               else "document_defaults.title")

    @property
    def records(self) -> list[CalcRecord]:
        """Every calculation record printed by the last :meth:`render`, in order."""
        return list(self.symbols.records)

    def add_section(self, section: Section) -> None:
        """Append a numbered section (in the order of the note)."""
        if any(s.key == section.key for s in self.sections):
            raise ParameterError("section key", section.key, "a key not used twice in the note")
        self.sections.append(section)

    # ------------------------------------------------------------------ rendering
    def render(self, out_dir: Path | str) -> Path:
        """Write ``out_dir/report.tex`` and ``out_dir/figures/*``; return the .tex path."""
        out = Path(out_dir)
        out.mkdir(parents=True, exist_ok=True)
        env = make_environment(self.template_dirs)
        self.symbols = SymbolTracker()
        base = {"s": self.strings, "sym": self.symbols, "doc": self.strings.titled(self.document, self.default_title),
                "language": self.language}
        macros = env.get_template("macros.tex.j2").make_module(dict(base))
        base["m"] = macros
        assignment = None
        if self.assignment is not None:
            assignment = self._render_section(env, self.assignment, base, out).body
        rendered = [self._render_section(env, sec, base, out) for sec in self.sections]
        babel = LANGUAGES[self.language]
        babel_languages = babel if babel == "english" else f"english,{babel}"
        text = env.get_template("note.tex.j2").render(
            **base, sections=rendered, assignment=assignment,
            introduction=self.introduction, conclusions=self.conclusions,
            references=self.references, frame=self.frame, designation=self.designation,
            bottom_margin_mm=27 if self.frame == "eskd" else 20,
            babel_languages=babel_languages, extra_preamble=Tex(self.extra_preamble))
        bad = [r for r in self.symbols.records if not evaluate_displayed(r).ok]
        if bad:
            raise InternalError("note", "printed formulas do not reproduce their printed results: "
                             + "; ".join(f"{r.symbol} = {r.expr}" for r in bad))
        unbalanced = [b for b in self.symbols.balances if not check_balance(b).ok]
        if unbalanced:
            raise InternalError("note", "printed balance equations do not hold with their printed results: "
                                + "; ".join(f"{b.equation_latex()} with {b.result.symbol} = "
                                            f"{b.result.result_number_latex()}" for b in unbalanced))
        text = keep_rows_together(continued_heads(self.strings.localize_latex(text),
                                                  str(self.strings.get("captions.table_continued"))))
        tex_path = out / "report.tex"
        tex_path.write_text(text, encoding="utf-8")
        return tex_path

    def build(self, out_dir: Path | str, *, latexmk: str = "latexmk",
              strict_references: bool = True) -> BuildReport:
        """Render and compile to ``out_dir/report.pdf``; the report has the pdf, log and timing."""
        tex_path = self.render(out_dir)
        self.last_build = build_pdf(tex_path, latexmk=latexmk,
                                    strict_references=strict_references)
        return self.last_build

    def _render_section(self, env: Any, sec: Section, base: dict[str, Any],
                        out: Path) -> _RenderedSection:
        figures = {name: _place_figure(obj, out / "figures", f"{sec.key}-{name}", sec.key, name)
                   for name, obj in sec.figures.items()}
        if sec.body is not None:
            body = Tex(sec.body)
        else:
            context = {**base, "figures": _Namespace(figures), "section": sec, **sec.context}
            body = Tex(env.get_template(sec.template).render(context))
        return _RenderedSection(sec.key, sec.title, body)


class _Namespace:
    """``figures.plan`` in a template; an unknown name is an error that lists the known ones."""

    def __init__(self, items: Mapping[str, FigureRef]) -> None:
        self._items = dict(items)

    def __getattr__(self, name: str) -> FigureRef:
        if name.startswith("_"):
            raise AttributeError(name)
        try:
            return self._items[name]
        except KeyError:
            raise AttributeError(f"no figure {name!r}; known: {', '.join(self._items) or 'none'}") from None

    def __getitem__(self, name: str) -> FigureRef:
        return self.__getattr__(name)


def _place_figure(obj: Any, fig_dir: Path, stem: str, section_key: str, name: str) -> FigureRef:
    """Save a matplotlib figure as PDF (no timestamp), or copy a file; return its reference."""
    fig_dir.mkdir(parents=True, exist_ok=True)
    safe = re.sub(r"[^A-Za-z0-9-]", "-", stem)
    if hasattr(obj, "savefig"):
        from .figures.saving import place

        target = fig_dir / f"{safe}.pdf"
        place(obj, target)      # saved now, or queued by the build (latex_templates/figures/saving.py)
    else:
        src = Path(obj)
        if not src.is_file():
            raise InternalError(f"figure {name!r} of section {section_key!r}", f"no file {src}")
        target = fig_dir / f"{safe}{src.suffix.lower()}"
        shutil.copyfile(src, target)
    return FigureRef(path=f"figures/{target.name}", label=f"fig:{section_key}:{name}")
