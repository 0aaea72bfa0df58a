"""The permission bits of what reportgen writes: those of a file or folder made the ordinary way.

``tempfile.mkstemp`` and ``mkdtemp`` make their file 0600 and their folder 0700 whatever the umask,
so an output written through them and renamed into place would be readable by its owner only (a
teacher's account on a shared machine could not open the student's note). Every output that is
renamed into place gets, before the rename, the mode ``open``/``mkdir`` would have given it:
0666 or 0777 without the bits of the process's umask.
"""

from __future__ import annotations

import os
import threading

_LOCK = threading.Lock()


def current_umask() -> int:
    """The process's umask (read by setting and restoring it, under a lock)."""
    with _LOCK:
        mask = os.umask(0o022)
        os.umask(mask)
    return mask


def as_made_ordinarily(path: str | os.PathLike[str], *, directory: bool = False) -> None:
    """Give ``path`` the mode a plain ``open`` (0666) or ``mkdir`` (0777) would have, less the umask."""
    os.chmod(path, (0o777 if directory else 0o666) & ~current_umask())
