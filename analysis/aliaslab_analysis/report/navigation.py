"""Finding one's way on the page: a sticky table of contents built from the page's own anchors (every
<h2>/<h3> with an id, and every figure with an id and a data-toc label, nested under the heading before it),
the scene gallery (a card per scene linking to its section); a scene's charts show in the contents
while the reader is in that scene, and click-to-enlarge (a lightbox in plain
CSS/JS: no network, works from file://). The palette is handed to the page's scripts as
window.ALIASLAB_PALETTE (palette.as_json) and as CSS variables (--sampler-NAME)."""
import html
import re

from ..charts import palette

CSS = """body{max-width:1560px}.layout{display:grid;grid-template-columns:230px minmax(0,1fr);gap:1.6em}
.layout>main{min-width:0}nav.toc{position:sticky;top:0;align-self:start;max-height:100vh;overflow-y:auto;
font-size:.8em;padding:.6em .2em 1em 0;border-right:1px solid #ddd}nav.toc ul{list-style:none;margin:0;
padding-left:.9em}nav.toc>ul{padding-left:0}nav.toc li{margin:.1em 0}nav.toc a{color:#236;text-decoration:none}
nav.toc a:hover{text-decoration:underline}nav.toc a.here{font-weight:bold;color:#000}nav.toc .fig a{color:#567}
nav.toc b{display:block;margin-bottom:.3em}nav.toc ul ul ul{display:none}nav.toc li:has(a.here)>ul{display:block}.gallery{display:flex;flex-wrap:wrap;gap:10px;margin:.8em 0}
.gallery a{display:block;width:170px;background:#fff;border:1px solid #ddd;padding:5px;color:#222;
text-decoration:none;font-size:.8em}.gallery a:hover{border-color:#236}.gallery img{width:160px;height:160px;
object-fit:contain;background:#eee;display:block}
.gallery img.px{image-rendering:pixelated}.gallery .none{width:160px;height:160px;
background:#eee;display:flex;align-items:center;justify-content:center;color:#777;text-align:center}
#lightbox{display:none;position:fixed;inset:0;background:rgba(0,0,0,.82);z-index:50;overflow:auto;cursor:zoom-out}
#lightbox.open{display:block}#lightbox img{display:block;margin:2em auto;background:#fff;max-width:none}
#lightbox p{color:#eee;text-align:center;margin:.5em 2em;font-size:.9em}
@media (max-width:900px){.layout{display:block}nav.toc{position:static;max-height:none;border:0}}"""

ENTRY = re.compile(r"<(h2|h3)\s+id='([^']+)'[^>]*>(.*?)</\1>|<\w+[^>]*?\sid='([^']+)'\s+data-toc='([^']+)'", re.S)


def entries(body):
    """[(level, id, label)] in page order: level 2 and 3 for headings, 4 for anchored figures."""
    out = []
    for m in ENTRY.finditer(body):
        if m.group(1):
            label = html.unescape(re.sub(r"<[^>]+>", "", m.group(3))).strip()
            out.append((int(m.group(1)[1]), m.group(2), label))
        else:
            out.append((4, m.group(4), html.unescape(m.group(5))))
    return out


def toc_html(items):
    """Nested <ul> of the entries (a figure nests under the heading before it)."""
    parts, depth = [], 0
    for level, ident, label in items:
        want = {2: 1, 3: 2, 4: 3}[level]
        if depth == 0:
            parts.append("<ul>")
            depth = 1
        while depth < want:
            parts.append("<ul>")
            depth += 1
        while depth > want:
            parts.append("</ul>")
            depth -= 1
        cls = " class='fig'" if level == 4 else ""
        parts.append(f"<li{cls}><a href='#{html.escape(ident)}'>{html.escape(label)}</a></li>")
    parts.append("</ul>" * depth)
    return "".join(parts)


def with_toc(body):
    """The body inside a two-column layout: the sticky table of contents, then the page."""
    return (f"<div class='layout'><nav class='toc' aria-label='contents'><b>Contents</b>{toc_html(entries(body))}"
            f"</nav><main>{body}</main></div>")


def gallery(cards):
    """The scene gallery: cards [(anchor, title, image src or None, line of text, magnified)], each linking to its
    scene; a magnified image (smaller than its card) is drawn with its pixels square, not smoothed."""
    out = []
    for anchor, title, src, text, magnified in cards:
        px = " class='px'" if magnified else ""
        pic = (f"<img{px} src='{html.escape(src)}' width='160' height='160' loading='lazy' "
               f"alt='{html.escape(title)}'>" if src
               else "<span class='none'>no image in this study</span>")
        out.append(f"<a href='#{html.escape(anchor)}'>{pic}<b>{html.escape(title)}</b><br>{text}</a>")
    return "<div class='gallery'>" + "".join(out) + "</div>"


SCRIPT = """
window.ALIASLAB_PALETTE = %s;
(function () {
  var box = document.getElementById('lightbox'), big = box.querySelector('img'), cap = box.querySelector('p');
  document.addEventListener('click', function (e) {
    var t = e.target;
    if (t.tagName === 'IMG' && t.closest('figure') && !t.closest('#lightbox')) {
      big.src = t.currentSrc || t.src; big.alt = t.alt; cap.textContent = t.alt; box.classList.add('open');
      e.preventDefault();
    } else if (box.classList.contains('open') && t.closest('#lightbox')) {
      box.classList.remove('open');
    }
  });
  document.addEventListener('keydown', function (e) {
    if (e.key === 'Escape') box.classList.remove('open');
  });
  // the contents mark where the reader is: the last anchor whose top has passed the upper third of the window
  var links = Array.from(document.querySelectorAll('nav.toc a')), queued = false, current = null;
  var targets = links.map(function (a) { return document.getElementById(a.getAttribute('href').slice(1)); });
  function mark() {
    queued = false;
    var line = window.innerHeight / 3, pick = null;
    targets.forEach(function (el, i) { if (el && el.getBoundingClientRect().top <= line) pick = links[i]; });
    if (pick === current) return;
    if (current) current.classList.remove('here');
    if (pick) pick.classList.add('here');
    current = pick;
  }
  window.addEventListener('scroll', function () { if (!queued) { queued = true; requestAnimationFrame(mark); } });
  mark();
})();
"""


def lightbox():
    """The overlay and the script (click a figure's image to see it at its own size; click or Esc closes)."""
    return ("<div id='lightbox' role='dialog' aria-label='enlarged image'><p></p><img alt=''></div>"
            f"<script>{SCRIPT % palette.as_json()}</script>")
