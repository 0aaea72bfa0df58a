"""The list of slow tests in tests/conftest.py (what `make check` leaves to `make test`) names tests
that exist: a renamed or moved test would otherwise quietly come back into the fast loop."""
from __future__ import annotations

import importlib.util
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _conftest():
    """tests/conftest.py by its path (several folders have a conftest.py of their own)."""
    spec = importlib.util.spec_from_file_location("tests_root_conftest", ROOT / "tests" / "conftest.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_every_slow_entry_names_a_test():
    assert _conftest().stale_slow_entries(ROOT) == []


def test_the_check_sees_a_stale_entry(tmp_path, monkeypatch):
    conftest = _conftest()
    path, name = conftest.SLOW_TESTS[0].split("::")
    (tmp_path / path).parent.mkdir(parents=True)
    (tmp_path / path).write_text(f"def {name}_renamed():\n    pass\n", encoding="utf-8")
    assert conftest.SLOW_TESTS[0] in conftest.stale_slow_entries(tmp_path)
    monkeypatch.setattr(conftest, "SLOW_TESTS", ())
    assert conftest.stale_slow_entries(tmp_path) == []
