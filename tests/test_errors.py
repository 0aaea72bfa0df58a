"""Issue 11: one error root. Every exception class of the project derives from
``reportgen.errors.ReportgenError``; no module raises a bare built-in error (outside the loader's own
validation, which raises TaskError through its value readers); the CLI turns each error into exit 2
(bad input) or 1 (a failed stage, keeping OUT.failed/), never a traceback.
"""
from __future__ import annotations

import importlib
import inspect
import pkgutil
import re
from pathlib import Path

import pytest

import drawings
import latex_templates
import reportgen
from reportgen import errors
from reportgen.cli import main

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = (reportgen, latex_templates, drawings)
BUILTIN = ("ValueError", "RuntimeError", "TypeError", "KeyError", "IndexError", "ArithmeticError",
           "ZeroDivisionError", "OverflowError", "AssertionError", "Exception", "LookupError", "OSError",
           "FileNotFoundError", "IOError")  # AttributeError stays: __getattr__'s protocol (hasattr, Jinja)
BARE_RAISE = re.compile(r"^\s*raise\s+(" + "|".join(BUILTIN) + r")\b", re.M)
# the loader's own validation: its abstract reader method (``raise NotImplementedError``) is allowed there
LOADER = {"reportgen/taskfile.py", "reportgen/taskfile_values.py"}


def _sources():
    for pkg in PACKAGES:
        base = Path(pkg.__file__).parent
        for path in sorted(base.rglob("*.py")):
            yield path.relative_to(ROOT).as_posix(), path.read_text(encoding="utf-8")


def test_no_bare_builtin_raises():
    found = [f"{rel}:{text[:m.start()].count(chr(10)) + 1}: {m.group(0).strip()}"
             for rel, text in _sources() if rel not in LOADER for m in BARE_RAISE.finditer(text)]
    assert not found, "raise a reportgen.errors class instead:\n" + "\n".join(found)


def _modules():
    for pkg in PACKAGES:
        yield pkg
        for info in pkgutil.walk_packages(pkg.__path__, pkg.__name__ + "."):
            if info.name.endswith("__main__"):
                continue
            yield importlib.import_module(info.name)


def test_every_exception_class_has_the_one_root():
    strays = []
    for mod in _modules():
        for name, cls in inspect.getmembers(mod, inspect.isclass):
            if cls.__module__ == mod.__name__ and issubclass(cls, BaseException) \
                    and not issubclass(cls, errors.ReportgenError):
                strays.append(f"{mod.__name__}.{name}")
    assert not strays


@pytest.mark.parametrize("exc, code", [
    (errors.ParameterError("n", 3, "at least 8"), 1),
    (errors.ComputationError("solve_ivp", "step size too small"), 1),
    (errors.NameLookupError("link", 9, (1, 2)), 1),
    (ZeroDivisionError("float division by zero"), 1),       # a bug: one line, no traceback
    (errors.TaskError("mechanism.name", "bad"), 2),
])
def test_cli_maps_every_error_to_an_exit_status(monkeypatch, capsys, exc, code):
    import reportgen.commands.gear as gear

    def boom(_args):
        raise exc
    monkeypatch.setattr(gear, "run", boom)
    rc = main(["gear", "--z1", "13", "--z2", "26", "--module", "9"])
    err = capsys.readouterr().err
    assert rc == code
    assert err.startswith("reportgen gear: ") and "Traceback" not in err and err.count("\n") == 1
    if not isinstance(exc, errors.ReportgenError):
        assert "internal error: ZeroDivisionError" in err


GEARS = "[gears]\nz1 = 13\nz2 = 26\nmodule = 9.0\nx1 = 0.63\nx2 = 0.67\n"


@pytest.mark.parametrize("exc", [errors.InternalError("sheet", "a view named 'x' is already on it"),
                                 KeyError("x")], ids=["reportgen-error", "bug"])
def test_a_failed_stage_keeps_out_failed(tmp_path, monkeypatch, capsys, exc):
    """Was: only BuildError kept OUT.failed/; any other error removed the work and printed a traceback."""
    import reportgen.commands.pipeline as pipeline

    def boom(*_a, **_k):
        raise exc
    monkeypatch.setattr(pipeline, "draw_sheets", boom)
    task = tmp_path / "task.toml"
    task.write_text(GEARS, encoding="utf-8")
    out = tmp_path / "out"
    rc = main(["build", str(task), "-o", str(out), "--quiet", "--no-pdf"])
    err = capsys.readouterr().err
    assert rc == 1 and "Traceback" not in err
    failed = tmp_path / "out.failed"
    assert str(failed) in err and (failed / "report.tex").is_file()
    assert "Traceback" in (failed / "error.log").read_text(encoding="utf-8")
    assert not out.exists()
