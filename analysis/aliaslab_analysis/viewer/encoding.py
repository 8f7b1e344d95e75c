"""The viewer's image entries: an image's values quantised to 8 or 16 bits between its own minimum and maximum (or
a fixed scale) and stored as PNG data URIs (export.py's format), and their inverse (decode, for the tests)."""
import base64
import io

import numpy as np
from PIL import Image


def encode(q, mode):
    buf = io.BytesIO()
    Image.fromarray(q.astype(np.uint8), mode).save(buf, "PNG", optimize=True)
    return "data:image/png;base64," + base64.b64encode(buf.getvalue()).decode("ascii")


def png_entry(values, bits, scale=None):
    """An image entry {w, h, c, bits, lo, hi, src[, src2]} of an (h, w, c) array (c = 1 grey or 3 colour)
    quantised to `bits` between its own minimum and maximum (or the fixed (lo, hi) `scale`, values clipped to it):
    8 bits in a grey or RGB PNG; 16 bits grey in one RGB
    PNG (red the high byte, green the low byte), colour in two RGB PNGs (src the high bytes, src2 the low)."""
    v = np.nan_to_num(np.asarray(values, dtype=np.float64), nan=0.0, posinf=0.0, neginf=0.0)
    h, w, c = v.shape
    lo, hi = (float(v.min()), float(v.max())) if scale is None else (float(scale[0]), float(scale[1]))
    v = np.clip(v, lo, hi)
    top = (1 << bits) - 1
    q = np.zeros(v.shape, dtype=np.int64) if hi <= lo else np.rint((v - lo) / (hi - lo) * top).astype(np.int64)
    e = {"w": int(w), "h": int(h), "c": int(c), "bits": bits, "lo": lo, "hi": hi}
    if bits == 8:
        e["src"] = encode(q[..., 0], "L") if c == 1 else encode(q, "RGB")
    elif c == 1:
        e["src"] = encode(np.stack([q[..., 0] >> 8, q[..., 0] & 255, np.zeros_like(q[..., 0])], axis=-1), "RGB")
    else:
        e["src"], e["src2"] = encode(q >> 8, "RGB"), encode(q & 255, "RGB")
    return e


def decode(entry):
    """The (h, w, c) values an image entry stores (the inverse of png_entry; the tests use it)."""
    def pixels(src):
        return np.asarray(Image.open(io.BytesIO(base64.b64decode(src.split(",", 1)[1])))).astype(np.int64)
    a = pixels(entry["src"])
    if entry["bits"] == 8:
        q = a[..., None] if a.ndim == 2 else a[..., :3]
    elif entry["c"] == 1:
        q = ((a[..., 0] << 8) + a[..., 1])[..., None]
    else:
        q = (a[..., :3] << 8) + pixels(entry["src2"])[..., :3]
    top = (1 << entry["bits"]) - 1
    return entry["lo"] + q * (entry["hi"] - entry["lo"]) / top


def channels(img):
    """The image's channels as stored: one when R, G and B are equal (the grey scenes), else three."""
    if img.shape[2] >= 3 and not (np.array_equal(img[..., 0], img[..., 1]) and np.array_equal(img[..., 0], img[..., 2])):
        return img[..., :3]
    return img[..., :1]
