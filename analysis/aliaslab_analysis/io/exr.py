"""Reading an EXR image into numpy without a Python binding of OpenImageIO (Debian has none): Debian's
`oiiotool` (openimageio-tools) converts it to 32-bit float FITS, whose pixels are the file's last
width x height x channels x 4 bytes, big-endian, rows bottom-up (OpenImageIO's FITS writer); the array
returned is (height, width, channels), row 0 at the top, as the image is shown."""
import os
import shutil
import subprocess
import tempfile

import numpy as np

from . import errors


def oiiotool():
    tool = shutil.which("oiiotool")
    if tool is None:
        errors.fail("oiiotool not found: install Debian's openimageio-tools (experiments/setup_debian.sh)")
    return tool


def header(data):
    cards = {}
    for i in range(0, min(len(data), 2880 * 4), 80):
        card = data[i:i + 80].decode("ascii", "replace")
        if card[:8].strip() == "END":
            break
        if card[8:10] == "= ":
            cards[card[:8].strip()] = card[10:].split("/")[0].strip()
    return cards


def read_exr(path):
    """(height, width, channels) float64 array of an EXR (or any image oiiotool reads)."""
    return read_exrs([path])[0]


def read_exrs(paths, chunk=64):
    """read_exr of each path, converted by one oiiotool process per `chunk` images (each start costs ~0.4 s)."""
    for p in paths:
        if not os.path.isfile(p):
            errors.fail(f"{p}: no such image")
    out = []
    with tempfile.TemporaryDirectory(prefix="aliaslab-exr-") as tmp:
        for start in range(0, len(paths), chunk):
            part = paths[start:start + chunk]
            cmd, fits = [oiiotool()], []
            for i, p in enumerate(part):
                fits.append(os.path.join(tmp, f"{start + i}.fits"))
                cmd += [p, "-d", "float", "-o", fits[-1]]
            run = subprocess.run(cmd, capture_output=True, text=True)
            for p, f in zip(part, fits):
                if run.returncode != 0 or not os.path.isfile(f):
                    errors.fail(f"{p}: oiiotool cannot convert it: {run.stderr.strip()[:300]}")
                with open(f, "rb") as fh:
                    out.append(from_fits(fh.read(), p))
    return out


def from_fits(data, path):
    cards = header(data)
    try:
        c, w, h = (int(cards[k]) for k in ("NAXIS1", "NAXIS2", "NAXIS3"))
    except (KeyError, ValueError):
        c, w, h = 1, int(cards.get("NAXIS1", 0)), int(cards.get("NAXIS2", 0))
    n = c * w * h * 4
    if n == 0 or n > len(data):
        errors.fail(f"{path}: unexpected FITS layout from oiiotool ({cards})")
    pixels = np.frombuffer(data[len(data) - n:], dtype=">f4").reshape(h, w, c)[::-1]
    return pixels.astype(np.float64)
