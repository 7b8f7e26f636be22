#!/usr/bin/python3
"""Renders a Markdown page as MkDocs does (Python-Markdown with MkDocs' default extensions) and prints what a
hostile name made live: a tag that is not one of the page's own kinds, an on* attribute, a javascript:/data: link,
and each expected text that is not shown as text. Exit 1 when anything is printed.

Usage: markdown_scan.py PAGE.md [TEXTS.json]   (a JSON list of names that must be visible, control characters as
spaces; in a file, so that no shell ever reads them)
"""
import html.parser
import json
import re
import sys

import markdown

# The tags vssw's own pages render to (io/document_markdown.cpp): headings, paragraphs, lists, tables, links to the
# page's anchors, plots, bold cells.
OWN_TAGS = {"h1", "h2", "h3", "h4", "p", "ul", "li", "table", "thead", "tbody", "tr", "th", "td", "a", "img", "strong"}


class Scan(html.parser.HTMLParser):
    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.problems = []
        self.text = []

    def handle_starttag(self, tag, attrs):
        self.text.append(" ")  # a text's pieces are joined as they are, but text across elements is apart
        if tag not in OWN_TAGS:
            self.problems.append(f"a live <{tag}> tag")
        for name, value in attrs:
            if name.lower().startswith("on"):
                self.problems.append(f"a live {name} attribute on <{tag}>")
            if name in ("href", "src") and re.match(r"\s*(javascript|data):", value or "", re.I):
                self.problems.append(f"a live {value!r} link on <{tag}>")
        if tag == "a" and not dict(attrs).get("href", "").startswith("#"):
            self.problems.append(f"a link to {dict(attrs).get('href')!r}")
        if tag == "img" and not dict(attrs).get("src", "").startswith("plots/"):
            self.problems.append(f"an image from {dict(attrs).get('src')!r}")
        if tag == "img":
            self.text.append(dict(attrs).get("alt", ""))

    def handle_endtag(self, tag):
        self.text.append(" ")

    def handle_data(self, data):
        self.text.append(data)


def squeezed(text):
    return " ".join(re.sub(r"[\x00-\x1f\x7f]", " ", text).split())


def main():
    page = open(sys.argv[1], encoding="utf-8").read()
    scan = Scan()
    scan.feed(markdown.markdown(page, extensions=["toc", "tables", "fenced_code"]))
    shown = squeezed("".join(scan.text))
    texts = json.load(open(sys.argv[2], encoding="utf-8")) if len(sys.argv) > 2 else []
    problems = scan.problems + [f"not shown as text: {t!r}" for t in texts if squeezed(t) not in shown]
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
