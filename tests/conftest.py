"""Session-wide settings: builds made by tests do not use the user's build cache (a test that is
about the cache points REPORTGEN_CACHE at a folder of its own); ``built(example)`` builds an example
once per test session for every check that reads a whole build (tests/marks, tests/lang)."""
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

os.environ["REPORTGEN_CACHE"] = "off"

# the sheets read their words with the note's catalogue loader, which the command layer gives them
# (drawings never imports latex_templates); tests that draw a sheet directly get the same one
from drawings.words import use_catalogue  # noqa: E402
from latex_templates.render import Strings  # noqa: E402

use_catalogue(Strings)

ROOT = Path(__file__).resolve().parents[1]
_BUILT: dict[str, Path] = {}


@pytest.fixture(scope="session")
def build_dir(tmp_path_factory) -> Path:
    return tmp_path_factory.mktemp("examples")


@pytest.fixture
def built(build_dir):
    """``built(example)`` → the output folder of ``reportgen build examples/<example>/task.toml``
    (note, sheets, results.json), built on first use and shared by the whole session."""
    if shutil.which("latexmk") is None:
        pytest.fail("latexmk is not installed: run `make test` (it installs TeX Live)")

    def get(example: str) -> Path:
        if example not in _BUILT:
            out = build_dir / example
            r = subprocess.run([sys.executable, "-m", "reportgen", "build",
                                str(ROOT / "examples" / example / "task.toml"), "-o", str(out)],
                               capture_output=True, text=True, cwd=ROOT, timeout=900)
            assert r.returncode == 0, r.stdout + r.stderr
            _BUILT[example] = out
        return _BUILT[example]
    return get
