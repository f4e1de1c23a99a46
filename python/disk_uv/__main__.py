# Copyright (c) 2026 The Disk_segmentation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""python3 -m disk_uv batch INPUT OUTPUT_DIR [options]: see disk_uv.batch."""

import sys


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if not argv or argv[0] in ("-h", "--help"):
        print("usage: python3 -m disk_uv batch INPUT OUTPUT_DIR [options]   (batch --help for the options)")
        return 0 if argv else 2
    if argv[0] != "batch":
        print("python3 -m disk_uv: unknown command '%s' (expected: batch)" % argv[0], file=sys.stderr)
        return 2
    from .batch import main as batch_main
    return batch_main(argv[1:])


if __name__ == "__main__":
    sys.exit(main())
