"""The external involute gear pair: geometry (ГОСТ 16532-70), checks, automatic shifts by a computed
blocking contour, specific sliding, tooth profiles and the meshing picture as pure geometry.

Public entry points: :func:`reportgen.gears.pair.solve_gear_pair` and
:func:`reportgen.gears.pair.from_task`; see docs/gears.md.
"""
