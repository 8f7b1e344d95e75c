"""`/usr/bin/python3 -m analysis COMMAND [options]` from the repository root (aliaslab_analysis/cli.py).

The analysis needs numpy, pandas and matplotlib, which Debian installs for its own /usr/bin/python3
(python3-numpy, python3-pandas, python3-matplotlib); another interpreter (a pyenv or venv python3 first on
PATH) usually lacks them, and is told how to run the analysis instead of showing a traceback."""
import importlib.util
import sys

NEEDED = ("numpy", "pandas", "matplotlib")


def missing_modules():
    """The modules the analysis needs that this interpreter cannot import."""
    return [name for name in NEEDED if importlib.util.find_spec(name) is None]


def how_to_run(missing):
    """The message for an interpreter without the analysis' modules."""
    return (f"error: this Python ({sys.executable}) lacks {', '.join(missing)}, which the analysis needs.\n"
            "Run it with Debian's interpreter, which sees python3-numpy, python3-pandas and python3-matplotlib:\n"
            f"    /usr/bin/python3 -m analysis {' '.join(sys.argv[1:]) or 'COMMAND'}\n"
            "(from the repository root; apt install python3-numpy python3-pandas python3-matplotlib if they "
            "are missing there too)\n")


if __name__ == "__main__":
    missing = missing_modules()
    if missing:
        sys.stderr.write(how_to_run(missing))
        sys.exit(2)
    from .aliaslab_analysis.cli import main

    sys.exit(main())
