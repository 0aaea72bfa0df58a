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
