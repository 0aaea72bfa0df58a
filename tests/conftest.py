"""Session-wide settings: builds made by tests do not use the user's build cache (a test that is
about the cache points REPORTGEN_CACHE at a folder of its own)."""
import os

os.environ["REPORTGEN_CACHE"] = "off"

# the sheets read their words with the note's catalogue loader, which the command layer gives them
# (drawings never imports latex_templates); tests that draw a sheet directly get the same one
from drawings.words import use_catalogue  # noqa: E402
from latex_templates.render import Strings  # noqa: E402

use_catalogue(Strings)
