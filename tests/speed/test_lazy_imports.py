"""`reportgen solve` starts fast because it imports only what solving needs: not the other commands,
nor the presentation (matplotlib, ezdxf, Jinja, the note's and sheets' packages) nor scipy."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PRESS = ROOT / "examples" / "press" / "task.toml"
HEAVY = ("matplotlib", "scipy", "ezdxf", "jinja2", "shapely", "latex_templates", "drawings")

PROBE = """
import json, sys
from reportgen import cli
status = cli.main(["solve", sys.argv[1], "--json", sys.argv[2], "--quiet"])
print(json.dumps({"status": status, "modules": sorted(sys.modules)}))
"""


def test_solve_imports_no_presentation_and_no_other_command(tmp_path):
    out = subprocess.run([sys.executable, "-c", PROBE, str(PRESS), str(tmp_path / "r.json")],
                         capture_output=True, text=True, cwd=tmp_path, timeout=300)
    assert out.returncode == 0, out.stderr
    report = json.loads(out.stdout.strip().splitlines()[-1])
    assert report["status"] == 0 and (tmp_path / "r.json").is_file()
    modules = report["modules"]
    heavy = sorted(m for m in modules if m.split(".")[0] in HEAVY)
    assert heavy == []
    commands = sorted(m for m in modules if m.startswith("reportgen.commands.") and m.count(".") == 2)
    assert commands == ["reportgen.commands.solve"]


THREADS_PROBE = """
import json, os, sys
from reportgen import cli
status = cli.main(["solve", sys.argv[1], "--json", sys.argv[2], "--quiet"])
threads = len(os.listdir("/proc/self/task"))
print(json.dumps({"status": status, "threads": threads, "env": os.environ.get("OPENBLAS_NUM_THREADS")}))
"""


def _threads(tmp_path: Path, env: dict[str, str]) -> dict:
    import os

    clean = {k: v for k, v in os.environ.items() if k not in ("OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")}
    out = subprocess.run([sys.executable, "-c", THREADS_PROBE, str(PRESS), str(tmp_path / "r.json")],
                         capture_output=True, text=True, cwd=tmp_path, timeout=300, env={**clean, **env})
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout.strip().splitlines()[-1])


def test_the_command_line_runs_numpy_with_one_blas_thread_unless_the_user_set_a_number(tmp_path):
    """OpenBLAS starts a worker thread per processor when numpy is imported, and it spins on a free
    processor after each call (CPU above the wall time of `reportgen solve`): the command line asks
    for one thread before the command's modules import numpy; a number the user set is kept."""
    import os

    if not Path("/proc/self/task").is_dir():
        import pytest
        pytest.skip("needs Linux's /proc/self/task")
    ours = _threads(tmp_path, {})
    assert ours["status"] == 0 and ours["env"] == "1" and ours["threads"] == 1
    if (os.cpu_count() or 1) > 1:
        theirs = _threads(tmp_path, {"OPENBLAS_NUM_THREADS": "2"})
        assert theirs["env"] == "2" and theirs["threads"] >= 2
