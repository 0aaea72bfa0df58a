"""Errors of the dynamics stage: bad input names its task key (``dynamics.delta``…)."""
from __future__ import annotations

from ..errors import TaskError


class DynamicsInputError(TaskError):
    """A [dynamics] value (or a missing section) that the flywheel calculation cannot use.

    ``path`` is the task key (``dynamics.flywheel.density``), ``problem`` what is wrong,
    ``expected`` what would be valid.
    """
