"""Generated tables in Markdown, between markers: one helper for docs/tables.py
(`<!-- results:NAME -->`) and bench/tables.py (`<!-- bench:NAME -->`).

A document holds each block once, between `<!-- KIND:NAME -->` and
`<!-- /KIND:NAME -->`; everything between them is rewritten from the data.
Standard library only.
"""

import re
import sys


def marked(kind, name, lines):
    """The block as it stands in the document, markers included."""
    return f"<!-- {kind}:{name} -->\n" + "\n".join(lines) + f"\n<!-- /{kind}:{name} -->"


def replace_blocks(text, blocks, doc, kind):
    """`text` with each block of `blocks` (name -> lines) written between its markers;
    exits naming `doc` when a pair is missing or repeated."""
    for name, lines in blocks.items():
        pattern = re.compile(rf"(<!-- {kind}:{name} -->\n).*?(<!-- /{kind}:{name} -->)", re.S)
        if len(pattern.findall(text)) != 1:
            sys.exit(f"tables.py: {doc} needs exactly one <!-- {kind}:{name} --> ... "
                     f"<!-- /{kind}:{name} --> pair")
        text = pattern.sub(lambda m: m[1] + "\n".join(lines) + "\n" + m[2], text)
    return text


def write_or_check(path, doc, blocks, kind, check, what, source):
    """Rewrites the blocks of the document at `path` (shown as `doc`), or with `check`
    only compares them: 1 when they differ from `source`, else 0. `what` names the
    tables in the messages ("result tables")."""
    with open(path) as f:
        text = f.read()
    new = replace_blocks(text, blocks, doc, kind)
    if check:
        if new != text:
            print(f"\n{doc}: {what} differ from {source}")
            return 1
        print(f"\n{doc}: up to date")
        return 0
    if new != text:
        with open(path, "w") as f:
            f.write(new)
        print(f"\n{doc}: {what} written")
    else:
        print(f"\n{doc}: already up to date")
    return 0
