"""The findings as HTML paragraphs (the page) or as a Markdown section (results/README.md)."""
from .markdown import inline


def html_paragraphs(findings):
    return [f"<p id='finding-{inline(f.key).replace(':', '-')}'>{inline(f.text)}</p>" for f in findings]


def markdown_section(findings, source):
    out = ["## Findings", "", f"_Generated from `{source}` by `python3 -m analysis report --findings-md`; "
           "every number below is recomputed from the CSV by analysis/tests/test_findings.py._", ""]
    for f in findings:
        out += [f"**{f.title}.** {f.text}", ""]
    return "\n".join(out)
