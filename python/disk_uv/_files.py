# Copyright (c) 2026 The Disk_segmentation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Whole files or none: what the package writes appears only once complete."""

import os
import tempfile


def write_atomically(path, data, overwrite=True):
    """Writes bytes to a temporary file beside `path`, then renames it over `path`.

    An interrupted write leaves `path` as it was. Raises FileExistsError if
    `path` exists and not `overwrite`, IsADirectoryError if it is a folder.
    """
    path = os.fspath(path)
    if os.path.isdir(path):
        raise IsADirectoryError(path)
    if not overwrite and os.path.exists(path):
        raise FileExistsError(path)
    folder = os.path.dirname(os.path.abspath(path))
    descriptor, temporary = tempfile.mkstemp(dir=folder, prefix=".disk_uv-", suffix=".part")
    try:
        with os.fdopen(descriptor, "wb") as out:
            out.write(data)
            out.flush()
            os.fsync(out.fileno())
        os.chmod(temporary, 0o644)
        os.replace(temporary, path)
    except BaseException:
        if os.path.exists(temporary):
            os.unlink(temporary)
        raise
