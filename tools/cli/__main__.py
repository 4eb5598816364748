"""python3 -m tools.cli COMMAND [ARGS]: the same as ./workbook COMMAND [ARGS]."""
import sys

from tools.cli import main

sys.exit(main())
