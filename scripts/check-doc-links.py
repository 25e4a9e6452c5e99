#!/usr/bin/env python3
"""Checks the internal links of README.md and docs/ (./run.sh docs, ctest docs.links).

Every relative link of a Markdown page, outside code blocks, must name a file that exists; a
link to a heading (page.md#anchor, #anchor) must name a heading of that page, as GitHub and
mkdocs make anchors from headings; links into docs/api/ (the Doxygen reference, generated) are
checked in the built site. Pages under docs/new/ (not yet placed) are left out. With
--site DIR, every relative href and src of the built site's pages (the Doxygen reference
included) must name a file of the site. Prints each broken link (file:line: link) and exits 1
when there is any."""
import argparse
import html
import re
import sys
from pathlib import Path

LINK = re.compile(r"!?\[(?:[^\]\[]|\[[^\]]*\])*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
FENCE = re.compile(r"^\s*(```|~~~)")


def slug(heading):
    text = re.sub(r"`([^`]*)`", r"\1", heading)
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text).strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def outside_code(text):
    """(line number, line) of the lines outside fenced code, inline code blanked."""
    inside = False
    for number, line in enumerate(text.split("\n"), 1):
        if FENCE.match(line):
            inside = not inside
            continue
        if not inside:
            yield number, re.sub(r"`[^`]*`", lambda m: " " * len(m.group(0)), line)


def anchors(page, cache={}):
    if page not in cache:
        found = set()
        for _, line in outside_code(page.read_text()):
            heading = re.match(r"^#{1,6}\s+(.*?)\s*#*\s*$", line)
            if heading:
                found.add(slug(heading.group(1)))
        # Headings with code: slug from the raw text too.
        for line in page.read_text().split("\n"):
            heading = re.match(r"^#{1,6}\s+(.*?)\s*$", line)
            if heading:
                found.add(slug(heading.group(1)))
        found |= set(re.findall(r"<a\s+(?:name|id)=\"([^\"]+)\"", page.read_text()))
        cache[page] = found
    return cache[page]


def check_markdown(page, broken, generated):
    for number, line in outside_code(page.read_text()):
        for match in LINK.finditer(line):
            target = match.group(1)
            if re.match(r"^[a-z][a-z0-9+.-]*:", target):  # https:, mailto:, ...
                continue
            path, _, anchor = target.partition("#")
            file = (page.parent / path).resolve() if path else page
            if generated in file.parents:  # the Doxygen reference: checked in the site
                continue
            if not file.exists():
                broken.append(f"{page}:{number}: {target}: no such file")
            elif anchor and file.suffix == ".md" and anchor not in anchors(file):
                broken.append(f"{page}:{number}: {target}: no heading '{anchor}' in {file.name}")


def check_site(site, broken):
    for page in site.rglob("*.html"):
        if page.name == "404.html":  # served at any depth: its links are from the site's root
            continue
        for number, line in enumerate(page.read_text(errors="replace").split("\n"), 1):
            for target in re.findall(r"(?:href|src)=\"([^\"]+)\"", line):
                target = html.unescape(target)
                if re.match(r"^([a-z][a-z0-9+.-]*:|//|#)", target):
                    continue
                path = target.split("#")[0].split("?")[0]
                base = site if path.startswith("/") else page.parent
                if path and not (base / path.lstrip("/")).exists():
                    broken.append(f"{page}:{number}: {target}: no such file in the site")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("root", type=Path, help="the repository's root")
    parser.add_argument("--site", type=Path, help="a built site to check as well")
    args = parser.parse_args()
    pages = [args.root / "README.md"] + sorted(
        p for p in (args.root / "docs").rglob("*.md") if "new" not in p.relative_to(
            args.root / "docs").parts[:1])
    broken = []
    for page in pages:
        check_markdown(page, broken, (args.root / "docs" / "api").resolve())
    if args.site:
        if not (args.site / "api" / "index.html").is_file():
            broken.append(f"{args.site}/api/index.html: the C++ API reference is missing")
        check_site(args.site, broken)
    for line in broken:
        print(line)
    print(f"check-doc-links: {len(pages)} pages, {len(broken)} broken links"
          + (f", site {args.site} checked" if args.site else ""))
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
