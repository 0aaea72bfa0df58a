"""Session-wide settings: builds made by tests do not use the user's build cache (a test that is
about the cache points REPORTGEN_CACHE at a folder of its own)."""
import os

os.environ["REPORTGEN_CACHE"] = "off"
