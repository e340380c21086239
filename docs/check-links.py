#!/usr/bin/env python3
"""Checks that every relative link in the repository's Markdown pages (*.md at the top
level and under docs/) points at a file or folder that exists in the clone.

    python3 docs/check-links.py      exit 1 and a list when a link is broken
"""
import pathlib
import re
import sys

root = pathlib.Path(__file__).resolve().parent.parent
link = re.compile(r"\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
fence = re.compile(r"^\s*(```|~~~)")
broken = []
checked = 0
pages = sorted(root.glob("*.md")) + sorted((root / "docs").glob("**/*.md"))
for page in pages:
    inside = False
    for number, line in enumerate(page.read_text(encoding="utf-8").splitlines(), 1):
        if fence.match(line):
            inside = not inside
            continue
        if inside:
            continue
        for target in link.findall(line):
            if re.match(r"^[a-z][a-z0-9+.-]*:", target) or target.startswith("#"):
                continue  # a URL, or an anchor in the same page
            checked += 1
            path = target.split("#", 1)[0]
            resolved = (page.parent / path).resolve()
            if root not in resolved.parents and resolved != root:
                broken.append(f"{page.relative_to(root)}:{number}: {target} leaves the repository")
            elif not resolved.exists():
                broken.append(f"{page.relative_to(root)}:{number}: {target} does not exist")
        if "../shared/" in line:
            broken.append(f"{page.relative_to(root)}:{number}: names ../shared/, outside a clone")
print(f"{checked} relative links in {len(pages)} pages checked")
for b in broken:
    print(b)
sys.exit(1 if broken else 0)
