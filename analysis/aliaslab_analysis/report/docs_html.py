"""Markdown to HTML for the pages: the repository's definitions (docs/*.md) rendered into one folder of HTML pages
at report time (docs_folder: the repository's results/docs for every page inside results/, so a sub-study's page
links to that one copy by a relative path; RESULTS/docs for a page elsewhere), so that the page's "Definitions"
link opens a readable page, and the records of engineering.html. Uses Debian's python3-markdown (tables, lists, code blocks, inline HTML entities);
without it, the report's own small reader (markdown.py: headings, tables, paragraphs) and a note."""
import html
import os
import re

from .markdown import markdown_blocks

try:
    import markdown as _markdown
except ImportError:  # python3-markdown missing: experiments/setup_debian.sh installs it
    _markdown = None

LINK = re.compile(r"""href=(["'])(?!https?:|#|mailto:)([^"'#]+)\.md(#[^"']*)?\1""")


def to_html(text):
    """HTML of a Markdown text: python3-markdown with tables, fenced code, sane lists and heading ids (toc: the
    same slugs as the docs' own #links) when present."""
    if _markdown is None:
        return ("<p class='note'>python3-markdown is not installed: a plain rendering.</p>"
                + "\n".join(b for _, b in markdown_blocks(text)))
    return _markdown.markdown(text, extensions=["tables", "fenced_code", "sane_lists", "toc"], output_format="html")


def md_links_to_html(fragment):
    """Links to sibling .md files rewritten to their .html rendering (anchors kept)."""
    return LINK.sub(lambda m: f"href={m.group(1)}{m.group(2)}.html{m.group(3) or ''}{m.group(1)}", fragment)


def docs_folder(results, repo):
    """The folder of the rendered definitions a page in `results` links to: REPO/results/docs when `results` is
    the repository's results folder or inside it (one copy for every committed page), else RESULTS/docs."""
    shared = os.path.realpath(os.path.join(repo, "results"))
    here = os.path.realpath(results)
    return os.path.join(shared, "docs") if here == shared or here.startswith(shared + os.sep) else \
        os.path.join(results, "docs")


def render_docs(docs_dir, out_dir, write_page, back_href):
    """Renders every docs_dir/*.md into out_dir/NAME.html; returns {name.md: path of its page}. Links between
    the docs follow; links leaving docs/ (to ../README.md, source files) are kept as text, since the pages
    live elsewhere."""
    if not os.path.isdir(docs_dir):
        return {}
    os.makedirs(out_dir, exist_ok=True)
    written = {}
    names = sorted(f for f in os.listdir(docs_dir) if f.endswith(".md"))
    for name in names:
        with open(os.path.join(docs_dir, name), encoding="utf-8", errors="replace") as f:
            body = md_links_to_html(to_html(f.read()))
        body = re.sub(r"<a href=(['\"])(\.\./|/)[^'\"]*\1>(.*?)</a>", r"\3", body)  # outside docs/: text only
        index = " ".join(f"<a href='{html.escape(n[:-3])}.html'>{html.escape(n)}</a>" for n in names)
        page = (f"<p><a href='{html.escape(back_href)}'>Back to the report</a> &middot; docs: {index}</p>"
                f"<div class='docs'>{body}</div>")
        written[name] = write_page(os.path.join(out_dir, name[:-3] + ".html"), f"aliaslab docs/{name}", page)
    return written
