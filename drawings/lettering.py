"""One home for turning a note's symbol into sheet lettering: a name with its indices as the note
prints it (``R^{\\tau}_{24}``, ``F'_{\\text{и}4}``, ``F^{B}_{M\\text{и}2}``, ``r_{b1}``, ``\\alpha_{w}``)
becomes a :class:`Rich` — a base, a raised superscript and a lowered subscript — which the sheets
letter as separate TEXT entities, the indices one ГОСТ 2.304 size smaller
(:func:`drawings.scenes.kinematics_labels.draw_rich`; its box by ``size``/``text_extent``, what
the label placer measures).

Why TEXT entities and not one MTEXT with inline codes (``\\S…^…;`` stacking, ``\\H0.7x;``): the
sheets' previews are drawn by :mod:`drawings.raster`, which letters TEXT and plain one-line MTEXT
only (a formatted MTEXT sends the whole sheet to ezdxf's slower renderer), LibreCAD 2.2 draws
MTEXT's stacking codes as a fraction rather than as indices, and a reader of the DXF, the label
checks (tests/labels) and the placer measure one TEXT per piece alike. A Russian subscript word
(``\\text{и}``, ``ур``) is lettered in the sheet's language (:func:`drawings.words.symbol`)."""
from __future__ import annotations

import re
from dataclasses import dataclass

#: LaTeX commands of the notes' symbols, as the sheets' font letters them.
GREEK = {r"\tau": "τ", r"\omega": "ω", r"\varepsilon": "ε", r"\epsilon": "ε", r"\varphi": "φ", r"\phi": "φ",
         r"\pi": "π", r"\psi": "ψ", r"\mu": "μ", r"\alpha": "α", r"\beta": "β", r"\gamma": "γ",
         r"\delta": "δ", r"\Delta": "Δ", r"\lambda": "λ", r"\rho": "ρ", r"\eta": "η", r"\sigma": "σ",
         r"\Sigma": "Σ", r"\theta": "θ", r"\xi": "ξ", r"\nu": "ν"}
_CYRILLIC = re.compile(r"[А-Яа-яЁёІіЇїЄєҐґ]")


@dataclass(frozen=True)
class Rich:
    """A base text with an optional superscript and subscript (stacked after the base)."""
    base: str
    sup: str = ""
    sub: str = ""

    @property
    def plain(self) -> str:
        """The letters in one line (``Rτ24``): what a search of the sheet's text finds."""
        return self.base + self.sup + self.sub


def _localised(text: str) -> str:
    """A Russian subscript word in the sheet's language (Latin and Greek letters stay)."""
    if not _CYRILLIC.search(text):
        return text
    from .words import symbol
    return symbol(text)


def flatten(tex: str) -> str:
    """``A_{3}A`` → ``A3A``; ``\\text{и}`` → ``и``; Greek commands to letters; a prime to ``'``;
    braces, spacing and marks dropped."""
    tex = re.sub(r"\\(?:text|mathrm|mathit|operatorname)\s*\{([^{}]*)\}", r"\1", tex)
    for cmd, ch in sorted(GREEK.items(), key=lambda kv: -len(kv[0])):
        tex = re.sub(re.escape(cmd) + r"(?![A-Za-z])", ch, tex)
    tex = tex.replace(r"\prime", "'").replace("′", "'")
    tex = re.sub(r"\\[,;:! ]", "", tex)
    return re.sub(r"[{}_^\\ ]", "", tex)


def _group(tex: str, start: int) -> tuple[str, int]:
    """The argument of ^ or _ at ``start``: a braced group, a command (``\\tau``) or one character."""
    if start < len(tex) and tex[start] == "{":
        depth, i = 0, start
        while i < len(tex):
            depth += {"{": 1, "}": -1}.get(tex[i], 0)
            if depth == 0:
                return tex[start + 1:i], i + 1
            i += 1
        return tex[start + 1:], len(tex)
    m = re.match(r"\\[A-Za-z]+", tex[start:])
    if m:
        return m.group(0), start + m.end()
    return tex[start:start + 1], start + 1


def _split_base(tex: str) -> tuple[str, int]:
    """The base of a symbol: everything before its first ``_`` or ``^`` outside braces."""
    depth = 0
    for i, ch in enumerate(tex):
        depth += {"{": 1, "}": -1}.get(ch, 0)
        if depth == 0 and ch in "_^" and (i == 0 or tex[i - 1] != "\\"):
            return tex[:i], i
    return tex, len(tex)


def from_tex(tex: str) -> Rich:
    """A note's symbol (``a^{\\tau}_{BA}``, ``R^{\\tau}_{24}``, ``F'_{\\text{и}4}``, ``\\alpha_{w}``)
    as a :class:`Rich` in the sheet's language; a prime of the base (``F'``) is raised as the note
    prints it, above the subscript. Several superscripts or subscripts are joined."""
    base, i = _split_base(tex)
    sup = sub = ""
    while i < len(tex):
        mark = tex[i]
        arg, i = _group(tex, i + 1)
        if mark == "^":
            sup += flatten(arg)
        elif mark == "_":
            sub += flatten(arg)
        else:
            break
    base = flatten(base)
    primes = len(base) - len(base.rstrip("'"))
    if primes and len(base) > primes:
        base, sup = base[:-primes], "'" * primes + sup
    return Rich(_localised(base), _localised(sup), _localised(sub))


def from_name(name: str) -> Rich:
    """A plain name with trailing digits as its index (``s2`` → s₂, ``O1`` → O₁, ``H1`` → H₁):
    the sheets' names that have no note symbol."""
    m = re.match(r"^(\D+?)(\d+)$", name)
    return Rich(m.group(1), "", m.group(2)) if m else Rich(name)
