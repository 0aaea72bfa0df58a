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


# ------------------------------------------------------------------------------------ make check
# Tests that take seconds of CPU each without building a document (whole sections rendered for
# every example, brute-force cross-checks, the bench, subprocess runs under other hash seeds) are
# `slow` as well, so that `make check` (-m "not slow") stays within a minute on two cores; `make
# test` and CI run them all (docs/testing.md). Listed here rather than in each file so that the list
# is one place to read and to trim; tests/test_slow_list.py fails on an entry that names no test.
SLOW_TESTS = (
    "tests/dynamics_presentation/test_dyn_note.py::test_section_renders_and_every_record_reevaluates",
    "tests/scenes/test_needs.py::test_parts_read_only_what_they_declare",
    "tests/hard_cases/test_hard_bench.py::test_bench_quick_writes_tables_and_plot",
    "tests/planetary/test_search.py::test_same_best_as_brute_force_on_a_grid_of_targets",
    "tests/planetary/test_search.py::test_same_best_as_brute_force_on_small_ranges",
    "tests/gears/test_shifts_checks.py::test_auto_satisfies_every_check",
    "tests/kinetostatics_presentation/test_kst_note.py::test_kst_section_renders_and_records_reevaluate",
    "tests/kinetostatics_presentation/test_kst_note.py::test_kst_warning_near_dead_centre",
    "tests/kinetostatics_presentation/test_kst_note.py::test_the_levers_arms_are_printed_as_a_drawing_is_read",
    "tests/kinetostatics_presentation/test_balance_signs.py::test_every_printed_balance_holds_with_its_printed_result",
    "tests/scenes/test_note_sheet_same.py::test_plan_segments_equal_in_note_and_sheet",
    "tests/scenes/test_numbering.py::test_same_angle_same_number",
    "tests/speed/test_pipeline.py::test_the_sheets_run_in_parallel_with_the_note",
    "tests/speed/test_pipeline.py::test_the_sheets_process_lists_and_imports_the_sheets_itself",
    "tests/speed/test_latex_passes.py::test_the_early_first_pass_writes_the_pdf_latexmk_writes",
    "tests/speed/test_dxf_hash_seed.py::test_sheet_dxf_is_the_same_under_different_hash_seeds",
    "tests/gears_presentation/test_gears_presentation.py::test_section_renders_and_every_record_reevaluates",
    "tests/gears_presentation/test_gears_presentation.py::test_sheet_audit_and_no_overlaps",
    "tests/gears_presentation/test_gears_presentation.py::test_gear_only_task_builds_section_and_sheet_without_the_linkage",
    "tests/dynamics/test_examples.py::test_motion_cross_checked_by_solve_ivp",
    "tests/kinematics_presentation/test_kin_part.py::test_crank_vectors_on_the_plans",
    "tests/test_errors.py::test_a_failed_stage_keeps_out_failed",
    "tests/hard_cases/test_hard_stages.py::test_small_pinion_auto_shifts_refused_with_the_inequalities",
    "tests/taskfile/test_taskfile_fuzz.py::test_mutated_valid_tasks",
    "tests/sheet1/test_sheet1_kinematics.py::test_scale_captions_come_from_the_results",
    "tests/sheet1/test_sheet1_kinematics.py::test_registered_and_drawn",
    # sheet 1 drawn with 1, 2 and 3 plan positions for every linkage example (15 sheets)
    "tests/sheet1/test_plan_pairs_layout.py::test_drawn_at_the_notes_scale_with_the_small_plans",
    "tests/sheet1/test_plan_pairs_layout.py::test_each_acceleration_plan_beside_its_velocity_plan",
    "tests/sheet1/test_plan_pairs_layout.py::test_nothing_overlaps_or_leaves_the_field",
    # sheet 1's small plans: drawn for every linkage example and test task, the core's layout with 1–3
    # plan positions and any plan positions, their μv in ru, uk and en (issue 12)
    "tests/sheet1/test_small_plans_required.py::test_every_task_draws_all_its_small_plans_in_the_field",
    "tests/sheet1/test_small_plans_required.py::test_the_core_reserves_the_small_plans_for_every_number_of_plan_positions",
    "tests/sheet1/test_small_plans_required.py::test_any_plan_positions_keep_the_small_plans",
    "tests/sheet1/test_small_plans_required.py::test_the_small_plans_scale_is_the_same_in_every_language",
    "tests/sheet1/test_small_plans_required.py::test_the_sheets_print_one_small_plans_scale_in_every_language",
    "tests/kinetostatics_presentation/test_kst_sheet.py::test_kst_sheet_audit_and_overlaps",
    "tests/dynamics_presentation/test_dyn_note.py::test_analysed_position_is_the_solvers",
    "tests/dynamics_presentation/test_dyn_note.py::test_numbers_are_the_results",
    "tests/gears_presentation/test_gears_presentation.py::test_failed_check_is_stated_as_a_finding",
    "tests/gears_presentation/test_gears_presentation.py::test_records_are_the_solver_numbers",
    "tests/gears_presentation/test_gears_presentation.py::test_sheet_halves_follow_the_task",
    "tests/cli/test_solve.py::test_at_angles",
    "tests/control/test_build.py::test_new_build_without_latex",
    "tests/crane/test_note_and_sheets.py::test_build_writes_note_sheets_and_results",
    "tests/bad_input/test_bad_input.py::test_latex_special_characters_print_literally",
    "tests/kinetostatics/test_position_and_cli.py::test_cli_shaper_force_at_45",
    "tests/scenes/test_polygons_legible.py::test_detail_letters_are_not_repeated_on_sheet_2",
    "tests/sheet1/test_plan_positions_sheet.py::test_default_two_plan_positions_one_per_stroke",
    "tests/sheet1/test_plan_positions_sheet.py::test_note_has_both_velocity_and_acceleration_plans",
    "tests/sheet1/test_plan_positions_sheet.py::test_sheet_draws_both_plans_of_every_plan_position",
    "tests/sheet1/test_plan_positions_sheet.py::test_scale_table_one_row_per_scale_with_the_notes_values",
    "tests/sheet1/test_plan_positions_sheet.py::test_note_prints_each_plan_scale",
    "tests/sheet1/test_plan_positions_sheet.py::test_small_plans_letters_legible_apart_and_at_their_points",
    "tests/sheet1/test_sheet1_kinematics.py::test_same_input_same_bytes",
    "tests/scenes/test_meshing_note_sheet_same.py::test_meshing_geometry_same_in_note_and_sheet",
    "tests/scenes/test_meshing_note_sheet_same.py::test_meshing_caption_and_ab_from_the_scene",
    "tests/scenes/test_meshing_note_sheet_same.py::test_meshing_note_designations_legible_and_clear",
    # sheet 2's arrangement tried with the lever one round step larger, for every example; the A3 control sheet
    "tests/scenes/test_lever_scale.py::test_the_lever_fills_the_room_sheet_2_gives_it",
    "tests/scenes/test_lever_scale.py::test_the_a3_control_sheet_draws_the_notes_lever",
    # every control-work table's variant 1 drawn on A3 and read back (~25 s)
    "tests/control/test_control_sheet_fill.py::test_the_mechanism_is_drawn_at_the_largest_scale_the_sheet_holds",
    "tests/control/test_control_sheet_fill.py::test_the_schemes_texts_keep_apart_and_off_the_links",
    # scaled examples (hypothesis): solved through the CLI and in process (~30 s), sheet 3 of each
    # (~9 s), every sheet drawn, built without the PDF
    "tests/robustness/test_scaled_solve.py::test_scaled_example_is_solved_or_refused",
    "tests/robustness/test_scaled_sheets.py::test_scaled_dynamics_sheet",
    "tests/robustness/test_scaled_sheets.py::test_scaled_example_every_sheet",
    "tests/robustness/test_scaled_sheets.py::test_scaled_example_builds_without_pdf",
    # section 3 of the press × 100 rendered in three languages
    "tests/hard_cases/test_wittenbauer_fits.py::test_the_note_says_the_energy_graph_is_reduced",
    # sheet 4 drawn at the corners of the examples' blocking contours and for every gear example;
    # sheet 3 at each example's grid and at 24 positions; note ↔ sheet 4 places (issue 12)
    "tests/scenes/test_meshing_marks.py::test_sheet4_texts_apart_at_contour_corners",
    "tests/scenes/test_meshing_marks.py::test_sheet4_texts_apart",
    "tests/scenes/test_meshing_note_sheet_same.py::test_designations_at_the_same_places_in_note_and_sheet",
    "tests/dynamics_presentation/test_sheet3_numbers.py::test_sheet3_numbers_apart_and_beside_their_nodes",
)


def _slow_entry(nodeid: str) -> str | None:
    for entry in SLOW_TESTS:
        if nodeid == entry or nodeid.startswith(entry + "["):
            return entry
    return None


def stale_slow_entries(root: Path) -> list[str]:
    """Entries whose file is gone or no longer defines the test (renamed or moved): tests/test_slow_list.py."""
    stale = []
    for entry in SLOW_TESTS:
        path, name = entry.split("::")
        file = root / path
        if not file.is_file() or f"def {name}(" not in file.read_text(encoding="utf-8"):
            stale.append(entry)
    return stale


@pytest.hookimpl(tryfirst=True)
def pytest_collection_modifyitems(items):
    for item in items:
        if _slow_entry(item.nodeid) is not None:
            item.add_marker(pytest.mark.slow)


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
