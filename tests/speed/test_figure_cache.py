"""Issue 16 item 2: the content keys under which the build cache keeps the note's scene figures
(reportgen.cache.content_digest, latex_templates.figures.scene.figure_key)."""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path
from types import MappingProxyType

import numpy as np
import pytest

from reportgen.cache import BuildCache, content_digest
from reportgen.scenes.scene import Arrow, Label, Scale, Scene, Segment

ROOT = Path(__file__).resolve().parents[2]


def scene(x: float = 40.0, text: str = "a") -> Scene:
    return Scene("plan", (Scale("μv", 0.01, "м/с/мм"),),
                 (Segment("ab", (0.0, 0.0), (x, 0.0)), Arrow("pa", (0.0, 0.0), (0.0, 30.0))),
                 (Label(text, "pa", (0.0, 30.0)),), MappingProxyType({"a": (0.0, 30.0)}),
                 MappingProxyType({"pa": 30.0}))


def test_the_digest_tells_every_field_apart():
    base = content_digest(scene())
    assert content_digest(scene()) == base
    assert content_digest(scene(x=40.0 + 1e-12)) != base          # float bits, not a rounded repr
    assert content_digest(scene(text="b")) != base
    assert content_digest((1, 2)) != content_digest((1.0, 2.0))    # an int is not its float
    assert content_digest(("ab", "c")) != content_digest(("a", "bc"))
    assert content_digest(np.arange(2000.0)) != content_digest(np.arange(2000.0) + np.eye(1, 2000, 1500)[0])


def test_the_digest_refuses_what_has_no_canonical_form():
    from reportgen.errors import InternalError

    with pytest.raises(InternalError, match="object"):
        content_digest((1, object()))


def test_the_digest_is_the_same_whatever_the_hash_seed():
    code = ("from tests.speed.test_figure_cache import scene; from reportgen.cache import content_digest;"
            "print(content_digest((scene(), {'x': 1, 'y': 2})))")
    seen = {subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, check=True,
                           env=dict(os.environ, PYTHONHASHSEED=seed)).stdout for seed in ("1", "4")}
    assert len(seen) == 1


def test_a_figure_keyed_by_its_scene_loses_its_key_when_drawn_on_afterwards():
    from latex_templates.figures.saving import content_key
    from latex_templates.figures.scene import scene_figure

    one, same, other = scene_figure(scene()), scene_figure(scene()), scene_figure(scene(x=41.0))
    assert content_key(one) == content_key(same) != content_key(other) is not None
    assert content_key(scene_figure(scene(), colours=False)) != content_key(one)
    one.axes[0].plot([0, 1], [0, 1])
    assert content_key(one) is None


def test_the_cache_copies_a_kept_figure_and_counts_it(tmp_path):
    cache = BuildCache(tmp_path / "cache", b"task", tmp_path / "task.toml", "options")
    made = tmp_path / "made.pdf"
    made.write_bytes(b"%PDF-1.4 a figure")
    cache.store_figure("k", made)
    target = tmp_path / "out.pdf"
    assert not cache.restore_figure("other", target) and not target.exists()
    assert cache.restore_figure("k", target)
    assert target.read_bytes() == made.read_bytes()
    assert (cache.figures_saved, cache.figures_reused) == (1, 1)


def test_a_kept_figure_is_not_made_and_is_made_when_its_pdf_is_gone(tmp_path):
    from latex_templates.figures.saving import KeptFigure, queued
    from latex_templates.figures.scene import scene_figure

    cache = BuildCache(tmp_path / "cache", b"task", tmp_path / "task.toml", "options")
    with queued(cache) as q:
        made = scene_figure(scene())
    assert not isinstance(made, KeptFigure)            # nothing kept yet: the figure is made
    first = tmp_path / "first.pdf"
    q.add(made, first)
    q.save(cache=cache)
    width, reduction = made.width_cm, made.reportgen_reduction
    with queued(cache) as q:
        kept = scene_figure(scene())
    assert isinstance(kept, KeptFigure)
    assert (kept.width_cm, kept.reportgen_reduction) == (width, reduction)   # exactly, as the note prints them
    second = tmp_path / "second.pdf"
    q.add(kept, second)
    q.save(cache=cache)
    assert second.read_bytes() == first.read_bytes() and cache.figures_reused == 1
    # the kept PDF removed between the look-up and the save: the figure is made and saved after all
    with queued(cache) as q:
        kept = scene_figure(scene())
    for pdf in (tmp_path / "cache" / "figures").glob("*.pdf"):
        pdf.unlink()
    third = tmp_path / "third.pdf"
    q.add(kept, third)
    q.save(cache=cache)
    assert third.read_bytes() == first.read_bytes() and cache.figures_reused == 1


def test_a_split_save_copies_kept_figures_counts_them_and_keeps_the_new_ones(tmp_path):
    """FigureQueue.start_split (the build's measuring in two processes) with the cache: a kept
    figure is copied and counted as save() counts it, a new one saved (by either process) and kept,
    the same bytes as saving them one by one."""
    from latex_templates.figures.saving import KeptFigure, queued
    from latex_templates.figures.scene import scene_figure
    from reportgen.commands import pipeline

    cache = BuildCache(tmp_path / "cache", b"task", tmp_path / "task.toml", "options")
    with queued(cache) as q:
        first = scene_figure(scene())
    q.add(first, tmp_path / "a0.pdf")
    q.save(cache=cache)
    with queued(cache) as q:
        kept = scene_figure(scene())
        new = [scene_figure(scene(20.0 + 5 * i, f"n{i}")) for i in range(3)]
    assert isinstance(kept, KeptFigure) and not any(isinstance(f, KeptFigure) for f in new)
    q.add(kept, tmp_path / "b0.pdf")
    for i, fig in enumerate(new):
        q.add(fig, tmp_path / f"b{i + 1}.pdf")
    q.start_split(pipeline._fork_figures_ready, cache).finish()
    assert (tmp_path / "b0.pdf").read_bytes() == (tmp_path / "a0.pdf").read_bytes()
    assert (cache.figures_reused, cache.figures_saved) == (1, 1 + 3)
    with queued(cache) as q:                        # the new ones are kept now: the same bytes again
        again = [scene_figure(scene(20.0 + 5 * i, f"n{i}")) for i in range(3)]
    assert all(isinstance(f, KeptFigure) for f in again)
    for i, fig in enumerate(again):
        q.add(fig, tmp_path / f"c{i + 1}.pdf")
    q.start_split(pipeline._fork_figures_ready, cache).finish()
    for i in range(3):
        assert (tmp_path / f"c{i + 1}.pdf").read_bytes() == (tmp_path / f"b{i + 1}.pdf").read_bytes()
    assert cache.figures_reused == 1 + 3
