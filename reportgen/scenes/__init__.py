"""Scenes: every construction the note and a sheet both show, computed once as pure geometry in mm
at one scale (:mod:`.scene`), built from the stage results (:mod:`.plans`, :mod:`.positions`), with
the one round-scale rule (:mod:`.scales`) and the room each drawing is given (:mod:`.boxes`).
Renderers: :mod:`latex_templates.figures.scene` (note) and :mod:`drawings.scenes.render` (sheets)."""
