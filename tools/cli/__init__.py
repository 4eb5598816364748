"""./workbook, the one entry point of the workbook, as a Python package (standard library only).

    ./workbook COMMAND [ARGS]        (Linux, macOS: a few lines of sh that start this package)
    py workbook.py COMMAND [ARGS]    (Windows, or anywhere without a POSIX shell)
    python3 -m tools.cli COMMAND     (from the workbook's folder)

Where each idea lives:
  commands.py   every command: its options, its help and what it does (one definition each;
                `./workbook help` and each `--help` are generated from it)
  edition.py    what this copy of the workbook holds (solutions? grader?), its chapters and seed
  prerequisites.py  finding the tools the workbook needs and installing what is missing
  building.py   configuring and building the CMake presets
  host.py       what differs between Linux, macOS and Windows (path lists, .exe, consoles)
  console.py    how the front end speaks: progress lines, refusals, failures"""


def main(argv=None):
    from tools.cli.commands import main as run
    return run(argv)
