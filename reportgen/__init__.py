"""reportgen: the ТММ course project (structure, kinematics, kinetostatics, dynamics, gears)
from one task file to the explanatory note and the drawing sheets.

The solver modules in this package are pure computation: they never import the presentation
packages (``latex_templates``, ``drawings``) nor the command line.
"""

__version__ = "0.1.0"
