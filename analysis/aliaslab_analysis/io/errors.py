"""Bad input: the exception the readers raise and the exit with status 2 the commands take on it.

Every command reports bad input as `error: MESSAGE` on stderr and exits 2 (1 is kept for regressions,
compare's verdict); a message names the file (and line or column) or the option.
"""
import os
import sys


class InputError(Exception):
    """Bad input: the message names the file (and line or column)."""


def fail(message):
    """Prints an input error and exits with status 2 (1 is kept for regressions)."""
    print(f"error: {message}", file=sys.stderr)
    sys.exit(2)


def prepare_out(path, option="--out"):
    """Creates the output folder `path` (or fails, exit 2, naming the option) before anything is written."""
    try:
        os.makedirs(path, exist_ok=True)
    except OSError as e:
        fail(f"{option}: cannot create folder '{path}': {e.strerror or e}")
    if not os.access(path, os.W_OK):
        fail(f"{option}: folder '{path}' is not writable")
