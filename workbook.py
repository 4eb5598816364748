#!/usr/bin/env python3
"""The workbook's front end, for systems without a POSIX shell (Windows) and for anyone:

    py workbook.py COMMAND [ARGS]       (Windows: the py launcher)
    python3 workbook.py COMMAND [ARGS]

the same commands as ./workbook (py workbook.py help lists them). The front end itself is the
package tools/cli."""
import sys

if sys.version_info < (3, 8):
    sys.exit("workbook: needs Python 3.8 or newer (this is Python %d.%d)" % sys.version_info[:2])

from tools.cli import main  # noqa: E402  (after the version check, which must run on any Python)

if __name__ == "__main__":
    sys.exit(main())
