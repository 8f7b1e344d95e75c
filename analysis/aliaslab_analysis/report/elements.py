"""The HTML building blocks of the report's pages: the style sheet, figures (images linked by relative path and
loaded lazily, or embedded as data URIs with charts palette-reduced), each with an anchor, and the writing of
a whole page (with the table of contents and the click-to-enlarge script of navigation.py)."""
import base64
import html
import io
import os

from ..io import errors
from ..charts import palette
from . import navigation

CSS = """body{font-family:sans-serif;margin:0 auto;max-width:1250px;padding:1em 1.5em;background:#fafafa;
color:#222;line-height:1.45}h1{font-size:1.55em;margin-bottom:.2em}h2{border-bottom:1px solid #ccc;margin-top:2em}
h3{margin-top:1.6em}.facts{color:#555;font-size:.9em}.answer{background:#fff;border-left:4px solid #2a6;
padding:.6em 1em;margin:1em 0}.note{background:#fff8e0;border-left:4px solid #e0a800;padding:.4em 1em;
font-size:.9em}figure{margin:.8em 0;background:#fff;border:1px solid #ddd;padding:6px;display:inline-block;
max-width:100%;box-sizing:border-box;vertical-align:top}figure img{max-width:100%;height:auto}
figcaption{font-size:.85em;color:#444;max-width:60em}table{border-collapse:collapse;font-size:.82em;margin:.5em 0}
td,th{border:1px solid #ccc;padding:2px 6px;text-align:right}th{background:#eee}td:first-child{text-align:left}
.pix img{width:192px;image-rendering:pixelated}.sheet img{max-height:860px;width:auto}.pix figure{margin-right:8px}
.pair{display:flex;flex-wrap:wrap;gap:8px;align-items:flex-start}.pair figure{margin:0}
.pair img{width:256px;image-rendering:pixelated}.pair figure.spec img{width:600px;image-rendering:auto}.pair figcaption{max-width:256px}.pair figure.spec figcaption{max-width:600px}nav a{margin-right:.8em}
details{margin:.6em 0}summary{cursor:pointer;color:#236}code{background:#eee;padding:0 3px}
figure img{cursor:zoom-in}figcaption a.anchor{color:#999;text-decoration:none;margin-left:.3em}
.answer-table td{text-align:left;vertical-align:top;min-width:13em}.answer-table th{vertical-align:top;text-align:left}
.answer-table .cfg{font-weight:600;color:#245;margin-top:.2em}.answer-table .ctl{color:#555}
.sizes td,.sizes th{text-align:left;vertical-align:top}ul.sizes li{margin:.3em 0}.docs li{margin:.15em 0}.docs td,.docs th{text-align:left}.docs pre{background:#eee;padding:.5em;overflow:auto}"""


def chart_png_bytes(path):
    """A chart's PNG with a 256-colour palette (no dithering): about a third of the bytes, and a chart has
    far fewer colours than that. Renders are never passed here (their pixels are data). Falls back to the
    file's bytes where Pillow (a dependency of Debian's matplotlib) is missing."""
    try:
        from PIL import Image
    except ImportError:
        with open(path, "rb") as f:
            return f.read()
    out = io.BytesIO()
    with Image.open(path) as im:
        if im.mode == "P":  # already palette-coded (figures.save_figure does it)
            with open(path, "rb") as f:
                return f.read()
        im.convert("RGB").quantize(colors=256, dither=Image.Dither.NONE).save(out, "PNG", optimize=True)
    return out.getvalue()


def image_src(page_dir, path, embed):
    if embed:
        if os.path.basename(os.path.dirname(path)) == "charts":
            data = chart_png_bytes(path)
        else:
            with open(path, "rb") as f:
                data = f.read()
        return "data:image/png;base64," + base64.b64encode(data).decode("ascii")
    return html.escape(os.path.relpath(path, page_dir).replace(os.sep, "/"))


def png_size(path):
    """(width, height) of a PNG from its IHDR chunk, or None when the file is not a PNG: the page's <img> tags
    carry them, so that the page keeps its layout while the images load."""
    try:
        with open(path, "rb") as f:
            head = f.read(24)
    except OSError:
        return None
    if len(head) < 24 or not head.startswith(b"\x89PNG\r\n\x1a\n") or head[12:16] != b"IHDR":
        return None
    return int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")


def size_attributes(path):
    """" width='W' height='H'" of a PNG, or ''."""
    size = png_size(path)
    return f" width='{size[0]}' height='{size[1]}'" if size else ""


def plain(caption):
    """A caption's text without its tags, for alt text."""
    import re
    return html.unescape(re.sub(r"<[^>]+>", "", caption))


def figure(page_dir, path, caption, embed, cls="", anchor=None, toc=None):
    """<figure> of an existing PNG (or '' when the file is missing), decoded lazily; with an anchor id (and a
    link to itself in the caption) when given; toc: its entry in the table of contents (navigation.py)."""
    if not os.path.isfile(path):
        return ""
    ident = f" id='{html.escape(anchor)}'" if anchor else ""
    entry = f" data-toc='{html.escape(toc)}'" if toc and anchor else ""
    link = f"<a class='anchor' href='#{html.escape(anchor)}' title='link to this chart'>#</a>" if anchor else ""
    return (f"<figure class='{cls}'{ident}{entry}><img src='{image_src(page_dir, path, embed)}'{size_attributes(path)} "
            "loading='lazy' "
            f"decoding='async' alt='{html.escape(plain(caption))}'><figcaption>{caption}{link}</figcaption></figure>")


def write_page(path, title, body, toc=False):
    """Writes the page atomically; toc: a sticky table of contents beside the body, built from its headings
    and anchored figures (navigation.py). Every page gets the click-to-enlarge script."""
    if toc:
        body = navigation.with_toc(body)
    page = ("<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'>"
            f"<meta name='viewport' content='width=device-width'><title>{html.escape(title)}</title>"
            f"<style>{CSS}{navigation.CSS}{palette.css_variables()}</style></head><body>{body}"
            f"{navigation.lightbox()}</body></html>\n")
    tmp = path + ".partial"
    try:
        with open(tmp, "w", encoding="utf-8") as f:
            f.write(page)
        os.replace(tmp, path)
    except OSError as e:
        if os.path.exists(tmp):
            os.remove(tmp)
        errors.fail(f"{os.path.dirname(path) or '.'}: cannot write {os.path.basename(path)}: {e.strerror or e}")
    return path
