"""The search against brute force: the chosen set condition by condition, the same best set on
small ranges, impossible targets refused with reasons and the nearest ratios."""
import functools
import subprocess
import sys

import pytest
from hypothesis import given, settings, strategies as st

import brute
from reportgen.errors import PlanetarySynthesisError, TaskError
from reportgen.planetary import UndercutLimits, search, synthesize
from reportgen.planetary.schemes import SCHEMES

SMALL = UndercutLimits(external_min=8, internal_min=20, internal_difference_min=4)
SMALL_BOUND = 40


@functools.lru_cache(maxsize=None)
def small_sets(scheme):
    return tuple(brute.all_coaxial_sets(scheme, SMALL_BOUND, 8, 20, 4))


def brute_best(scheme, target, tol, k_given, driver="wheel"):
    """All valid sets by loops; K = given, or the largest of 6..2 that fits; ranked by the
    documented key (envelope, |deviation|, −K, z)."""
    out = []
    for z in small_sets(scheme):
        u1h = brute.willis(scheme, z)
        if u1h == 0:
            continue
        u = u1h if driver == "wheel" else 1 / u1h
        dev = (abs(float(u)) - abs(target)) / abs(target)
        if abs(dev) > tol * (1 + 1e-9) or (target < 0 and u > 0):
            continue
        if brute.envelope(scheme, z) > SMALL_BOUND:
            continue
        ks = [k_given] if k_given else [6, 5, 4, 3, 2]
        for k in ks:
            if brute.adjacency_geometric(scheme, z, k) and brute.assembly_by_phases(scheme, z, k):
                out.append((brute.envelope(scheme, z), abs(dev), -k, z))
                break
    out.sort()
    return out


# target ranges where small sets exist, per (scheme, driver)
RANGES = {("single-row", "wheel"): (2.2, 6.0), ("two-row-ext-int", "wheel"): (3.0, 12.0),
          ("two-row-ext-ext", "wheel"): (-6.0, 6.0), ("two-row-int-int", "wheel"): (-3.0, 3.0),
          ("single-row", "carrier"): (0.15, 0.45), ("two-row-ext-int", "carrier"): (0.08, 0.35),
          ("two-row-ext-ext", "carrier"): (-20.0, 20.0), ("two-row-int-int", "carrier"): (-30.0, 30.0)}


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(tuple(SCHEMES)), st.floats(0, 1), st.sampled_from(["auto", 2, 3, 4]),
       st.sampled_from([0.01, 0.03, 0.08]), st.sampled_from(["wheel", "carrier"]))
def test_same_best_as_brute_force_on_small_ranges(scheme, frac, k, tol, driver):
    lo, hi = RANGES[scheme, driver]
    target = lo + frac * (hi - lo)
    if abs(target) < 0.05:
        target = 0.05
    found = search(scheme, target, tol, k, driver=driver, limits=SMALL, count=3, max_teeth=SMALL_BOUND)
    expected = brute_best(scheme, target, tol, None if k == "auto" else k, driver)
    assert [c.z for c in found] == [e[3] for e in expected[:3]]
    assert [c.satellites for c in found] == [-e[2] for e in expected[:3]]


TARGETS = {"single-row": (3.0, 9.0), "two-row-ext-int": (6.0, 40.0),
           "two-row-ext-ext": (3.0, 40.0), "two-row-int-int": (2.0, 40.0)}


@settings(max_examples=30, deadline=None)
@given(st.sampled_from(tuple(SCHEMES)), st.floats(0, 1), st.sampled_from(["auto", 3]),
       st.sampled_from(["wheel", "carrier"]))
def test_chosen_set_passes_every_condition_independently(scheme, frac, k, driver):
    lo, hi = TARGETS[scheme]
    target = lo + frac * (hi - lo)
    try:
        d = synthesize(scheme, target, 0.05, k, driver=driver, alternatives=2)
    except PlanetarySynthesisError as exc:
        assert exc.reasons and exc.scheme == scheme
        return
    for z, kk in [(d.z, d.satellites)] + [(c.z, c.satellites) for c in d.alternatives]:
        assert brute.coaxial(scheme, z)
        assert brute.undercut_ok(scheme, z)
        assert brute.adjacency_geometric(scheme, z, kk)
        assert brute.assembly_by_phases(scheme, z, kk)
        u1h = brute.willis(scheme, z)
        u = float(u1h if driver == "wheel" else 1 / u1h)
        assert abs(abs(u) - target) <= 0.05 * target + 1e-12
    if k == "auto":   # K is the largest that fits
        z = d.z
        assert not any(brute.adjacency_geometric(scheme, z, kk) and brute.assembly_by_phases(scheme, z, kk)
                       for kk in range(d.satellites + 1, 7))
    sizes = [d.size] + [c.size for c in d.alternatives]
    assert sizes == sorted(sizes)


def test_ratio_up_to_40_ext_int():
    d = synthesize("two-row-ext-int", 40.0, 0.05)
    assert d.valid and abs(d.ratio - 40) <= 2


def test_impossible_target_is_refused_with_nearest():
    # single-row: u1H = 2 + 2·z2/z1 > 2, so 1.5 cannot be reached
    with pytest.raises(PlanetarySynthesisError) as ei:
        synthesize("single-row", 1.5, 0.05)
    exc = ei.value
    assert exc.scheme == "single-row" and exc.target == 1.5
    assert exc.nearest and all(abs(u) > 1.5 * 1.05 for u, _, _ in exc.nearest)
    assert "planetary.ratio" in str(exc) and "nearest ratios" in str(exc)


def test_impossible_satellites_are_refused_with_reason():
    # single-row with six planets: adjacency needs (z1 + z2)/2 > z2 + 2, i.e. z1 > z2 + 4,
    # so u1H = 2 + 2·z2/z1 < 4: a target of 8 cannot fit six planets
    with pytest.raises(PlanetarySynthesisError) as ei:
        synthesize("single-row", 8.0, 0.02, satellites=6)
    assert any("adjacency" in r for r in ei.value.reasons)


@pytest.mark.parametrize("kwargs, path", [
    (dict(scheme="triple-row", ratio=5.0), "planetary.scheme"),
    (dict(scheme="single-row", ratio=0.0), "planetary.ratio"),
    (dict(scheme="single-row", ratio=5.0, tolerance=0.0), "planetary.tolerance"),
    (dict(scheme="single-row", ratio=5.0, satellites=0), "planetary.satellites"),
    (dict(scheme="single-row", ratio=5.0, satellites="3"), "planetary.satellites"),
    (dict(scheme="single-row", ratio=5.0, module=-1), "planetary.module"),
    (dict(scheme="single-row", ratio=5.0, driver="sun"), "planetary.driver"),
])
def test_bad_input_names_the_key(kwargs, path):
    with pytest.raises(TaskError) as ei:
        synthesize(**kwargs)
    assert ei.value.path == path and ei.value.expected


def test_cli_done_when():
    cmd = [sys.executable, "-m", "reportgen", "planetary", "--scheme", "two-row-ext-int",
           "--ratio", "12.272", "--satellites", "3"]
    out = subprocess.run(cmd, capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    for word in ("coaxial", "undercut", "adjacency", "assembly", "ratio", "valid"):
        assert word in out.stdout
    js = subprocess.run(cmd + ["--json"], capture_output=True, text=True)
    import json
    block = json.loads(js.stdout)
    assert set(block) >= {"scheme", "z", "satellites", "ratio", "ratio_target", "ratio_graphical", "checks"}
    assert block["checks"]["coaxial"] and block["checks"]["adjacent"] and block["checks"]["assembly"]
    assert block["satellites"] == 3 and block["ratio_target"] == 12.272
    bad = subprocess.run(cmd[:-1] + ["seven"], capture_output=True, text=True)
    assert bad.returncode == 2 and "--satellites" in bad.stderr
    imp = subprocess.run([sys.executable, "-m", "reportgen", "planetary", "--scheme", "single-row",
                          "--ratio", "1.5"], capture_output=True, text=True)
    assert imp.returncode == 2 and "nearest" in imp.stderr


def test_same_best_as_brute_force_on_a_grid_of_targets():
    """Deterministic sweep (the hypothesis test above samples the same space): 7 targets per
    (scheme, driver), K auto and 3, two tolerances; most cases must have solutions."""
    nonempty = 0
    for (scheme, driver), (lo, hi) in RANGES.items():
        for i in range(7):
            target = lo + (hi - lo) * i / 6
            target = target if abs(target) >= 0.05 else 0.05
            for k in ("auto", 3):
                for tol in (0.01, 0.08):
                    expected = brute_best(scheme, target, tol, None if k == "auto" else k, driver)
                    found = search(scheme, target, tol, k, driver=driver, limits=SMALL, count=3,
                                   max_teeth=SMALL_BOUND)
                    assert [(c.z, c.satellites) for c in found] == [(e[3], -e[2]) for e in expected[:3]], \
                        (scheme, driver, target, k, tol)
                    assert len({c.z for c in found}) == len(found)
                    nonempty += bool(expected)
    assert nonempty >= 80
