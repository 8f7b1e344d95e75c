"""A small Markdown reader for the results/*.md records (headings, tables, paragraphs; **bold** and
`code` inline) into HTML, and the writer of a DataFrame as a Markdown table (for --tables)."""
import html
import re


def markdown_tables(text):
    """HTML of every Markdown table in text (each a run of '|' lines: header, separator, rows), or ''.
    **bold** inside cells is kept as bold."""
    return "\n".join(b for kind, b in markdown_blocks(text) if kind == "table")


def inline(text):
    text = html.escape(text)
    text = re.sub(r"\*\*(.+?)\*\*", r"<b>\1</b>", text)
    return re.sub(r"`([^`]+)`", r"<code>\1</code>", text)


def markdown_blocks(text):
    """A small Markdown reader for the results/*.md records: [(kind, html)] with kind in heading,
    table, paragraph. Tables need a separator row under the header."""
    out, para, block = [], [], []

    def flush_para():
        if para:
            out.append(("paragraph", "<p>" + inline(" ".join(para)) + "</p>"))
            para.clear()

    def flush_table():
        if not block:
            return
        lines = list(block)
        block.clear()
        if len(lines) < 2 or not set(lines[1].replace("|", "").strip()) <= set("-: "):
            para.extend(lines)  # not a table: no separator row under the header
            return
        cells = [[inline(c.strip()) for c in l.strip().strip("|").split("|")] for l in lines]
        head = "".join(f"<th>{c}</th>" for c in cells[0])
        body = "".join("<tr>" + "".join(f"<td>{c}</td>" for c in row) + "</tr>" for row in cells[2:])
        out.append(("table", f"<table><tr>{head}</tr>{body}</table>"))

    for line in text.splitlines() + [""]:
        s = line.strip()
        if s.startswith("|"):
            flush_para()
            block.append(line)
            continue
        flush_table()
        flush_para() if not s or s.startswith("#") else None
        if s.startswith("#"):
            level = min(len(s) - len(s.lstrip("#")) + 2, 5)
            out.append(("heading", f"<h{level}>{inline(s.lstrip('#').strip())}</h{level}>"))
        elif s:
            para.append(s)
    flush_table()
    flush_para()
    return out


def markdown(df, float_format="{:.4g}"):
    cols = list(df.columns)
    rows = ["| " + " | ".join(cols) + " |", "|" + "---|" * len(cols)]
    for _, r in df.iterrows():
        rows.append("| " + " | ".join(float_format.format(v) if isinstance(v, float) else str(v)
                                      for v in r) + " |")
    return "\n".join(rows)
