"""The working stroke's window takes round-off either side of its ends (found by tests/robustness: a
scaled class3 evaluated at the example's position 0, 4e-16 rad before its own start, had its
resistance off there and its reactions 39 % off the similar example's)."""
from __future__ import annotations

import math

import numpy as np

from reportgen.loads import StrokeWindow


def test_round_off_before_the_start_is_the_start():
    for sign in (1.0, -1.0):
        w = StrokeWindow(3.788408623367909, 0.1889905521311775, sign)
        s = w.phi_start
        on = w.on_working(np.array([s, s - sign * 4e-16, s + sign * 4e-16, s - sign * 1e-6]))
        assert on.tolist() == [True, True, True, False]


def test_the_ends_and_the_middle():
    w = StrokeWindow(0.5, 2.0, 1.0)
    phi = np.array([0.5, 1.0, 2.0, 2.0 + 1e-6, 0.5 - 1e-6, 0.5 + 2 * math.pi])
    assert w.on_working(phi).tolist() == [True, True, True, False, False, True]
