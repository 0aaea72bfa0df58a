"""The memory of reduced quantities (reportgen.dynamics.memo) and the solves without accelerations
change no bit of the dynamics (issue 16 item 3: results.json stays byte-identical)."""
from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from reportgen.dynamics import ProjectCycle, solve_dynamics
from reportgen.dynamics.memo import ReducedMemo

from .conftest import project_of


def _same(a, b, path="") -> None:
    """Equal to the bit (signs of zero and NaN included), through dataclasses, tuples and dicts."""
    if dataclasses.is_dataclass(a) and not isinstance(a, type):
        assert type(a) is type(b), path
        for f in dataclasses.fields(a):
            _same(getattr(a, f.name), getattr(b, f.name), f"{path}.{f.name}")
    elif isinstance(a, (tuple, list)):
        assert len(a) == len(b), path
        for i, (x, y) in enumerate(zip(a, b)):
            _same(x, y, f"{path}[{i}]")
    elif isinstance(a, dict):
        assert a.keys() == b.keys(), path
        for k in a:
            _same(a[k], b[k], f"{path}[{k!r}]")
    elif isinstance(a, (np.ndarray, float, np.floating)):
        x, y = np.asarray(a), np.asarray(b)
        assert x.shape == y.shape and np.array_equal(x, y, equal_nan=True), path
        assert np.array_equal(np.signbit(x), np.signbit(y)), path
    else:
        assert a == b, path


def _plain(monkeypatch) -> None:
    """The dynamics as before: every request computed afresh, with the accelerations."""
    monkeypatch.setattr(ReducedMemo, "__call__", lambda self, theta, with_dJ: self._fresh(theta, True))


@pytest.mark.parametrize("name", ["press", "shaper", "class3"])
def test_the_memory_and_the_lean_solves_change_no_bit(name, monkeypatch):
    fast = solve_dynamics(project_of(name))
    with monkeypatch.context() as m:
        _plain(m)
        plain = solve_dynamics(project_of(name))
    _same(fast, plain)


def test_the_memory_serves_repeated_and_contained_angles():
    cycle = ProjectCycle(project_of("press"))
    memo = cycle._memo
    assert memo.elementwise
    theta = np.linspace(0.0, 6.0, 50)
    r1 = cycle.reduced(theta)
    n = memo.computed
    r2 = cycle.reduced(theta[::-3])                       # all seen: nothing computed
    assert memo.computed == n
    _same(r2.M, r1.M[::-3])
    _same(r2.dJ, r1.dJ[::-3])
    mixed = np.concatenate((theta[:5], [0.123, 4.567]))  # two new angles: only they are computed
    r3 = cycle.reduced(mixed, with_dJ=False)
    assert memo.computed == n + 2
    fresh = ProjectCycle(project_of("press")).reduced(mixed)
    _same(r3.M, fresh.M)
    _same(r3.J, fresh.J)
    assert np.isnan(r3.dJ[-2:]).all()
    # asked with dJ after being computed without: computed again, with the accelerations
    r4 = cycle.reduced(np.array([0.123]))
    _same(r4.dJ, fresh.dJ[-2:-1])


def test_class_iii_keeps_whole_calls_only():
    cycle = ProjectCycle(project_of("class3"))
    memo = cycle._memo
    assert not memo.elementwise
    theta = np.linspace(0.0, 6.0, 20)
    cycle.reduced(theta)
    n = memo.computed
    cycle.reduced(theta.copy())                           # the same angles: kept
    assert memo.computed == n
    cycle.reduced(theta[:10])                             # a part: computed with its own Newton run
    assert memo.computed == n + 10


def test_the_memory_matches_angles_by_their_bits_and_computes_each_once():
    calls = []

    def compute(theta, with_dJ):
        calls.append(theta.copy())
        return np.cos(theta), np.sin(theta), np.copysign(1.0, theta)
    memo = ReducedMemo(compute, elementwise=True)
    M, J, dJ = memo(np.array([0.5, 0.0, 0.5, 0.25]), True)
    assert [list(c) for c in calls] == [[0.0, 0.25, 0.5]]          # each angle once
    _same(M, np.cos(np.array([0.5, 0.0, 0.5, 0.25])))
    M2, J2, dJ2 = memo(np.array([-0.0, 0.25]), True)               # −0.0 is not 0.0
    assert memo.computed == 4 and list(calls[-1]) == [-0.0]
    _same(dJ2, np.array([-1.0, 1.0]))
