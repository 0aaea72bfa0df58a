"""Bad input: what is impossible is refused (exit 2, the key named); a catalogue row that is too
weak is a failed check with the next catalogue step."""
from __future__ import annotations

import dataclasses as dc

import pytest

from reportgen.cli import main
from reportgen.crane import crane_calc
from reportgen.errors import TaskError
from reportgen.taskfile import loads_task

from .helpers import example_crane, example_text, with_hoist, with_trolley


def test_the_example_passes_every_check():
    calc = crane_calc(example_crane())
    failed = [(name, c.key) for name, m in calc.mechanisms for c in m.checks if not c.passed]
    assert failed == []


def test_a_rope_weaker_than_required_is_a_failed_check_with_the_required_force():
    crane = example_crane()
    rope = dc.replace(crane.hoist.rope, breaking_force_kn=600.0)
    calc = crane_calc(with_hoist(crane, rope=rope))
    c = calc.hoist.check("rope")
    assert not c.passed
    assert c.value == 600_000.0 and c.limit == pytest.approx(calc.hoist.value("F_req"))
    assert c.advice == "rope_force" and c.advice_value == pytest.approx(c.limit / 1000)
    assert c.advice_unit == "кН"


def test_a_motor_too_small_fails_heating_and_overload_and_asks_for_more_power():
    crane = example_crane()
    motor = dc.replace(crane.hoist.motor, power_kw=22.0)
    calc = crane_calc(with_hoist(crane, motor=motor))
    failed = {c.key: c for c in calc.hoist.checks if not c.passed}
    assert "overload" in failed
    assert "start_torque" in failed or "heating" in failed
    for c in failed.values():
        if c.advice in ("motor_power", "motor_torque"):
            assert c.advice_value > 22.0


def test_a_motor_that_cannot_start_is_said_so():
    crane = example_crane()
    motor = dc.replace(crane.hoist.motor, power_kw=40.0)
    calc = crane_calc(with_hoist(crane, motor=motor))
    c = calc.hoist.check("start_torque")
    assert not c.passed and "t_p" not in calc.hoist.records


def test_a_weak_brake_and_wheel_are_failed_checks():
    crane = example_crane()
    crane = with_hoist(crane, brake=dc.replace(crane.hoist.brake, rated_torque=1000.0))
    crane = with_trolley(crane, wheel=dc.replace(crane.trolley.wheel, allowable_load_kn=320.0))
    calc = crane_calc(crane)
    assert not calc.hoist.check("brake").passed
    c = calc.trolley.check("wheel_load")
    assert not c.passed and c.advice_value == pytest.approx(calc.trolley.value("P_max") / 1000)


def test_the_seeds_motor_slips_the_empty_trolleys_wheels():
    """Seed 002 chooses a 20,5 kW motor at 895 rpm for the trolley; with 4 of 8 wheels driven and
    the mean starting torque 1,6·M_ном the empty trolley's driven wheels slip (k_сц < 1,2)."""
    crane = example_crane()
    motor = dc.replace(crane.trolley.motor, power_kw=20.5, speed_rpm=895, start_torque_ratio=1.6)
    calc = crane_calc(with_trolley(crane, motor=motor, mass_t=42.0))
    c = calc.trolley.check("adhesion_start")
    assert not c.passed and c.value < 1.2


def _replace(text: str, old: str, new: str) -> str:
    assert old in text, old
    return text.replace(old, new, 1)


@pytest.mark.parametrize("old, new, path", [
    ('group = "3М"            # ГОСТ 25835-83; the seed: «лёгкий режим — группа 3М»\n', "", "crane.group"),
    ("lifting_speed_m_min = 2.22", "lifting_speed_m_min = -2.22", "crane.hoist.lifting_speed_m_min"),
    ("speed_m_min = 23", "speed_m_min = 0", "crane.trolley.speed_m_min"),
    ('group = "3М"', 'group = "3M"', "crane.group"),            # a Latin M
    ("driven_wheels = 4", "driven_wheels = 9", "crane.trolley.driven_wheels"),
    ("efficiency = 0.94", "efficiency = 1.4", "crane.hoist.reducer.efficiency"),
    ('rules = "1969"', 'rules = "1970"', "crane.rules"),
    ("wall_mm = 40", "wall_mm = 500", "crane.hoist.drum.wall_mm"),
    ("z2 = 52", "z2 = 12", "crane.hoist.open_gear.z2"),
    ("ratio = 8\n", "ratio = 8\nratoi = 2\n", "crane.hoist.polyspast.ratoi"),
])
def test_impossible_input_is_refused_naming_the_key(old, new, path):
    text = _replace(example_text(), old, new)
    with pytest.raises(TaskError) as err:
        loads_task(text)
    assert err.value.path == path


def test_cli_exit_status_2_and_the_key_on_stderr(tmp_path, capsys):
    bad = tmp_path / "task.toml"
    bad.write_text(_replace(example_text(), "lifting_speed_m_min = 2.22", "lifting_speed_m_min = -1"),
                   encoding="utf-8")
    assert main(["crane", str(bad)]) == 2
    assert "crane.hoist.lifting_speed_m_min" in capsys.readouterr().err
    out = tmp_path / "out"
    assert main(["build", str(bad), "-o", str(out), "--quiet"]) == 2
    assert not out.exists() and list(tmp_path.iterdir()) == [bad]


def test_kind_crane_without_a_crane_section_is_refused():
    with pytest.raises(TaskError) as err:
        loads_task('[document]\nkind = "crane"\n')
    assert err.value.path == "crane"


def test_kind_is_inferred_from_the_sections():
    assert loads_task(example_text().replace('kind = "crane"', "")).kind == "crane"
    assert loads_task("[gears]\nz1 = 13\nz2 = 26\nmodule = 9\n").kind == "course-project"


def test_crane_command_prints_the_checks_and_json(tmp_path, capsys):
    from .helpers import EXAMPLE
    assert main(["crane", str(EXAMPLE)]) == 0
    out = capsys.readouterr().out
    assert "[pass] rope: 782 500 Н ≥ 667 243 Н" in out
    assert "133 449" in out and "FAIL" not in out.replace("some checks FAIL", "")
    assert main(["crane", str(EXAMPLE), "--json"]) == 0
    import json
    block = json.loads(capsys.readouterr().out)
    assert block["passed"] is True
    assert block["hoist"]["values"]["S_max"]["value"] == pytest.approx(133_448.6, abs=0.1)


def test_crane_command_prints_a_failed_check_with_the_next_step(tmp_path, capsys):
    bad = tmp_path / "task.toml"
    bad.write_text(_replace(example_text(), "breaking_force_kn = 782.5", "breaking_force_kn = 600"),
                   encoding="utf-8")
    assert main(["crane", str(bad)]) == 0
    out = capsys.readouterr().out
    assert "[FAIL] rope: 600 000 Н ≥ 667 243 Н  → next step: rope_force (667,2 кН)" in out


def test_crane_command_on_a_task_without_crane_is_refused(tmp_path, capsys):
    t = tmp_path / "task.toml"
    t.write_text("[gears]\nz1 = 13\nz2 = 26\nmodule = 9\n", encoding="utf-8")
    assert main(["crane", str(t)]) == 2
    assert "crane" in capsys.readouterr().err
