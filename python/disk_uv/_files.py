# Copyright (c) 2026 The Disk_segmentation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Whole files or none: what the package writes appears only once complete.

A file is first written to ``.disk_uv-HOST-PID-XXXXXXXX.part`` beside it:
the host and process in the name tell a later process whether the writer
is gone (killed mid-write), so that its temporary can be removed.
"""

import os
import re
import socket
import tempfile

# The host name as it goes into temporary names: short, no '-' (the separator).
_HOST = re.sub(r"[^A-Za-z0-9.]", "_", socket.gethostname())[:32] or "host"
# This tool's temporaries: HOST-PID- since the pid was added, nothing before.
_TEMPORARY = re.compile(r"\.disk_uv-(?:(?P<host>[A-Za-z0-9_.]+)-(?P<pid>\d{1,10})-)?[a-z0-9_]{8}\.part\Z")


def _temporary_prefix(pid):
    return ".disk_uv-%s-%d-" % (_HOST, pid)


def write_atomically(path, data, overwrite=True):
    """Writes bytes to a temporary file beside `path`, then renames it over `path`.

    An interrupted write leaves `path` as it was. Raises FileExistsError if
    `path` exists and not `overwrite`, IsADirectoryError if it is a folder.
    """
    path = os.fsdecode(path)  # str, bytes or path-like; other bytes than UTF-8 as surrogates
    if os.path.isdir(path):
        raise IsADirectoryError(path)
    if not overwrite and os.path.exists(path):
        raise FileExistsError(path)
    folder = os.path.dirname(os.path.abspath(path))
    descriptor, temporary = tempfile.mkstemp(dir=folder, prefix=_temporary_prefix(os.getpid()), suffix=".part")
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


def _alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (OSError, OverflowError):  # not ours to signal (EPERM), or no pid at all: keep its file
        return True
    return True


def _remove(path):
    try:
        os.unlink(path)
    except FileNotFoundError:  # removed meanwhile
        pass


def remove_temporaries(folder, pid):
    """Removes the temporaries that process `pid` of this host left in `folder` (not below)."""
    for entry in os.scandir(folder):
        match = _TEMPORARY.match(entry.name)
        if match and match["host"] == _HOST and int(match["pid"]) == pid and entry.is_file(follow_symlinks=False):
            _remove(entry.path)


def remove_stale_temporaries(folder):
    """Removes, anywhere under `folder`, the temporaries of writers that are gone.

    Those of this host's processes that no longer run, and those of earlier
    versions (``.disk_uv-XXXXXXXX.part``, no writer named); never a file of
    another host, of a running process or that is not such a temporary.
    """
    for root, _, files in os.walk(folder):
        for file in files:
            match = _TEMPORARY.match(file)
            if match and (match["pid"] is None or (match["host"] == _HOST and not _alive(int(match["pid"])))):
                path = os.path.join(root, file)
                if not os.path.islink(path):
                    _remove(path)
