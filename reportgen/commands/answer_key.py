"""The one-page answer key of a table (PDF, matplotlib): one row per variant, the values a teacher
checks (φ, ω1, ω and ε of links 2–4, v and a of the output point, P_у, M_у)."""
from __future__ import annotations

from pathlib import Path

#: (answers.csv column, format) of the key's columns; headings: strings control.key.columns.<column>.
KEY_COLUMNS: tuple[tuple[str, str], ...] = (
    ("phi_deg", "{:.0f}"), ("omega1", "{:.0f}"),
    ("omega2", "{:+.3f}"), ("omega3", "{:+.3f}"), ("omega4", "{:+.3f}"),
    ("eps2", "{:+.1f}"), ("eps3", "{:+.1f}"), ("eps4", "{:+.1f}"),
    ("v_out", "{:.3f}"), ("a_out", "{:.2f}"), ("Py", "{:+.1f}"), ("My", "{:+.2f}"),
)


def cell(value: float, fmt: str, mark: str) -> str:
    """A key's number as the note prints it: the language's decimal ``mark`` and a true minus."""
    return fmt.format(value).replace("-", "\u2212").replace(".", mark)


def _page(path: Path, title: str, rows: list[tuple[str, dict | None, str | None]], strings) -> None:
    import matplotlib
    matplotlib.use("Agg")
    from matplotlib.backends.backend_pdf import PdfPages
    from matplotlib.figure import Figure

    fig = Figure(figsize=(11.69, 8.27))
    ax = fig.add_axes((0.03, 0.08, 0.94, 0.80))
    ax.axis("off")
    fig.text(0.5, 0.94, title, ha="center", fontsize=14)
    head = [str(strings.get("control.key.variant"))] + [str(strings.get(f"control.key.columns.{k}")) for k, _ in KEY_COLUMNS]
    cells = []
    for name, row, _err in rows:
        if row is None:
            cells.append([name, str(strings.get("control.key.failed"))] + [""] * (len(KEY_COLUMNS) - 1))
        else:
            mark = strings.decimal_mark()
            cells.append([name] + [cell(row[k], fmt, mark) if k in row else "" for k, fmt in KEY_COLUMNS])
    tab = ax.table(cellText=cells, colLabels=head, loc="upper center", cellLoc="center")
    tab.auto_set_font_size(False)
    tab.set_fontsize(9)
    tab.scale(1.0, 1.6)
    fig.text(0.5, 0.04, str(strings.get("control.key.footnote")), ha="center", fontsize=8)
    with PdfPages(path, metadata={"CreationDate": None, "ModDate": None}) as pdf:
        pdf.savefig(fig)


def write_keys(outcomes, jobs, out: Path, language: str = "ru") -> list[str]:
    """One page per table (``answer-key-table-T.pdf``), or ``answer-key.pdf`` for jobs without a
    table; returns the file names written."""
    from latex_templates.render import Strings
    strings = Strings(language)
    groups: dict[int | None, list] = {}
    for j, o in zip(jobs, outcomes):
        label = str(j.variant) if j.variant is not None else j.name
        groups.setdefault(j.table, []).append((label, o.row, o.error))
    written = []
    for t, rows in groups.items():
        name = f"answer-key-table-{t}.pdf" if t is not None else "answer-key.pdf"
        title = str(strings.get("control.key.title")).replace("{table}", str(t)) if t is not None else \
            str(strings.get("control.key.title_tasks"))
        tmp = out / f".{name}.tmp"
        _page(tmp, title, rows, strings)
        tmp.replace(out / name)
        written.append(name)
    return written
