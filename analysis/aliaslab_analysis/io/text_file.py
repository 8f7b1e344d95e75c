"""Text files that may be gzipped: the committed studies are kept as study.csv.gz (lib/core/gzip.h), and every
reader takes a study CSV whether or not it is compressed, told by the gzip magic bytes, not by the name.

  read_text(path)   the file's text (UTF-8), decompressed when it is gzip data (several members joined)
  existing(path)    path, or path + ".gz" when only that exists (where a study kept gzipped is looked for)
"""
import gzip
import os
import zlib

from .errors import InputError

MAGIC = b"\x1f\x8b"


def read_text(path):
    """The text of `path`, decompressed when gzipped. Raises InputError naming the file when it cannot be
    read, is not UTF-8, or its gzip data is cut short (an interrupted sweep) or damaged."""
    try:
        with open(path, "rb") as f:
            data = f.read()
        if data[:2] == MAGIC:
            data = gzip.decompress(data)
        return data.decode("utf-8")
    except EOFError as e:
        raise InputError(f"{path}: a gzip member cut short (the sweep that wrote it was interrupted; rerun it "
                         "to finish the study)") from e
    except (gzip.BadGzipFile, zlib.error) as e:
        raise InputError(f"{path}: damaged gzip data: {e}") from e
    except UnicodeDecodeError as e:
        raise InputError(f"{path}: not a readable CSV: {e}") from e
    except OSError as e:
        raise InputError(f"{path}: cannot read: {e.strerror or e}") from e


def existing(path):
    """`path` when it is a file, else path + ".gz" when that is one (a study kept gzipped), else `path`."""
    if not os.path.isfile(path) and os.path.isfile(path + ".gz"):
        return path + ".gz"
    return path
