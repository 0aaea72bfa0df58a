"""Issue 11: `reportgen planetary` and `reportgen build` use the same input speed for the same reducer
(planetary.drive.input_speed: the drive's when the ratio is "auto", else the motor's, else 100 rad/s).
Was: the command assumed ω1 = 1 rad/s (v_A = 0.0544 m/s) while the build used 100 rad/s."""
from __future__ import annotations

import json
import math

import pytest

from reportgen.cli import main
from reportgen.planetary.drive import DEFAULT_INPUT_OMEGA, input_speed
from reportgen.project import Project
from reportgen.results import build_results
from reportgen.taskfile import loads_task


def _cli_block(capsys, argv):
    assert main(["planetary", *argv, "--json"]) == 0
    return json.loads(capsys.readouterr().out)


def _build_block(toml: str):
    return json.loads(json.dumps(build_results(Project(loads_task(toml)))["planetary"]))


@pytest.mark.parametrize("motor", [None, 1500])
def test_command_and_build_agree(capsys, motor):
    task = ('[planetary]\nscheme = "two-row-ext-int"\nratio = 12.272\ntolerance = 0.05\nsatellites = 3\n'
            'module = 6.4\n' + (f"motor_rpm = {motor}\n" if motor else ""))
    argv = ["--scheme", "two-row-ext-int", "--ratio", "12.272", "--satellites", "3", "--module", "6.4"]
    if motor:
        argv += ["--motor-rpm", str(motor)]
    cli, built = _cli_block(capsys, argv), _build_block(task)
    assert cli["velocity"] == built["velocity"]
    w = math.pi * motor / 30 if motor else DEFAULT_INPUT_OMEGA
    assert cli["velocity"]["omega1"] == pytest.approx(w, rel=1e-12)


def test_input_speed_rule():
    assert input_speed(None, None) == (DEFAULT_INPUT_OMEGA, "default")
    assert input_speed(None, 1500) == (pytest.approx(50 * math.pi), "motor")
