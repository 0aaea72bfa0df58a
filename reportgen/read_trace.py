"""What a sheet read of its project, recorded while it is drawn, so that the build cache can tell
next time, before drawing it, whether anything it read has changed (:mod:`reportgen.cache`).

A sheet sees the project through :class:`reportgen.project.Needs`; :class:`TracedNeeds` is that
view with a notebook: every attribute the sheet reads of the project (a stage, the task's
sections, the boxes, a helper), of ``project.task`` (a section) and of ``project.scenes`` (a
scene, or a scene at another scale with its arguments) is written down as a *read*, a small
JSON-able tuple. :func:`read_digest` evaluates a read again on another project and digests the
value (:func:`reportgen.cache.content_digest`); a sheet whose reads all digest as before is the
same drawing. A read that cannot be replayed or digested (a method of the project called with
computed arguments, an object without a canonical form) makes the trace *opaque*: such a sheet
is always drawn.

The bodies' masses and moments of inertia are left out of the digest of the linkage (and of the
structure and model built from it) when the sheet read no stage computed from them
(:data:`MASS_STAGES`): the kinematic and gear sheets are then the same drawing whatever the
masses. No sheet reads ``Body.mass`` or ``Body.inertia`` itself (tests/speed/test_sheet_cache.py
greps the drawings for it).
"""
from __future__ import annotations

from typing import Any

from .project import STAGES, Needs

#: Stages whose values follow from the bodies' masses and moments of inertia.
MASS_STAGES = frozenset({"kinetostatics", "balancing_cycle", "balancing_cycle_dense", "resistance", "dynamics"})
#: Fields left out of the linkage's digest for a sheet that reads no stage of MASS_STAGES.
MASS_FIELDS = frozenset({("Body", "mass"), ("Body", "inertia")})
#: Methods of ``project.scenes`` a sheet may call; replayed with the same (JSON) arguments.
SCENE_CALLS = frozenset({"positions_at", "free_bodies_at"})
#: A read that cannot be replayed.
OPAQUE = ("opaque",)


class Trace:
    """The reads of one sheet, in the order first made, each once."""

    def __init__(self) -> None:
        self.reads: list[tuple] = []
        self._seen: set[tuple] = set()

    def add(self, read: tuple) -> None:
        if read not in self._seen:
            self._seen.add(read)
            self.reads.append(read)

    @property
    def opaque(self) -> bool:
        return OPAQUE in self._seen


class TracedNeeds(Needs):
    """A :class:`Needs` view that writes each read into ``trace``."""

    def __init__(self, project: Any, needs: tuple[str, ...], owner: str, trace: Trace) -> None:
        super().__init__(project, needs, owner)
        self._trace = trace

    def __getattr__(self, name: str) -> Any:
        value = super().__getattr__(name)        # an undeclared stage raises here
        if name == "scenes":
            return _TracedScenes(value, self._trace)
        if name == "task":
            return _TracedTask(value, self._trace)
        if name in STAGES or not callable(value):
            self._trace.add(("attr", name))
        else:                                    # a method (kinematics_at, loads_at …): not replayed
            self._trace.add(OPAQUE)
        return value


class _TracedTask:
    """``project.task`` for a traced sheet or note section: each section read is recorded;
    ``task.has(section)`` as the section's presence only."""

    def __init__(self, task: Any, trace: Trace) -> None:
        self._task, self._trace = task, trace

    def __getattr__(self, name: str) -> Any:
        value = getattr(self._task, name)
        if name == "has":                      # a section's presence, not its values
            def has(section: str) -> bool:
                self._trace.add(("task-has", section))
                return bool(value(section))
            return has
        self._trace.add(("task", name) if not callable(value) else OPAQUE)
        return value


class _TracedScenes:
    """``project.scenes`` for a traced sheet: each scene read is recorded, each call of
    :data:`SCENE_CALLS` with its arguments (anything else is opaque)."""

    def __init__(self, scenes: Any, trace: Trace) -> None:
        self._scenes, self._trace = scenes, trace

    def __getattr__(self, name: str) -> Any:
        value = getattr(self._scenes, name)
        if name in SCENE_CALLS:
            def call(*args: Any) -> Any:
                plain = all(isinstance(a, (str, int, float, bool)) for a in args)
                self._trace.add(("scenes-call", name, *args) if plain else OPAQUE)
                return value(*args)
            return call
        self._trace.add(("scenes", name) if not callable(value) and name != "project" else OPAQUE)
        return value


def read_value(project: Any, read: tuple) -> Any:
    """The value ``read`` names, on ``project`` (a :class:`reportgen.project.Project`)."""
    kind = read[0]
    if kind == "attr":
        return getattr(project, read[1])
    if kind == "task":
        return getattr(project.task, read[1])
    if kind == "task-has":
        return project.task.has(read[1])
    if kind == "scenes":
        return getattr(project.scenes, read[1])
    if kind == "scenes-call":
        return getattr(project.scenes, read[1])(*read[2:])
    from .errors import InternalError
    raise InternalError("read_trace", f"no such read: {read!r}")


def masks_masses(reads: list[tuple]) -> bool:
    """Whether the masses may be left out of the linkage's digest for a sheet with these reads."""
    return not any(r[0] == "attr" and r[1] in MASS_STAGES for r in reads) \
        and ("task", "mechanism") not in reads


def read_digest(project: Any, read: tuple, *, mask_masses: bool) -> str:
    """The content digest of the value ``read`` names on ``project``; the model (a solver, no data)
    as the linkage and structure it is built from. Raises InternalError (no canonical form) or
    the stage's own error."""
    from .cache import content_digest

    skip = MASS_FIELDS if mask_masses else frozenset()
    if read == ("attr", "model"):
        return content_digest(("KinematicModel", project.linkage, project.structure), skip=skip)
    return content_digest(read_value(project, read), skip=skip)


def scene_inputs(project: Any, name: str) -> list[tuple] | None:
    """What the scene ``project.scenes.<name>`` reads of the project (stages, task sections, other
    scenes), found by making it again on a recording view of the project; None when a read cannot
    be replayed or the scene cannot be made so. The scene is a function of these values (and of
    the code): the build cache keeps its digest under theirs, so that a rebuild learns that a scene
    is the same without making it (:meth:`reportgen.cache.BuildCache.scene_digest`)."""
    from .scenes.stage import Scenes

    trace = Trace()
    try:
        getattr(Scenes(TracedNeeds(project, tuple(sorted(STAGES)), f"scene {name}", trace)), name)
    except Exception:  # noqa: BLE001 - a scene that needs the real project: not kept by its inputs
        return None
    return None if trace.opaque else trace.reads
